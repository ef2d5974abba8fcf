"""Wells, Example 15.2 — circuit of Fig. 15-4 with two identical two-element tubes in the common branch
(nonlinear voltage drop E3 = A |Q3'|^(b-1) Q3'), a battery E1, an applied E2 = E0 sin(wt), one capacitor C.

Mesh charges Q1, Q2 with the junction law Q3 = Q2 - Q1. Wells gives L and the virtual work of the resistors
and tubes, delta W = -[R1 Q1' dQ1 + R2 Q2' dQ2 + R3 u (dQ2 - dQ1) + A |u|^(b-1) u (dQ2 - dQ1)], u = Q2' - Q1';
that delta W is given to the engine literally (the tube law is a signed power law, not differentiable at u = 0
for b < 1). The variant "-P" uses the equivalent power function (15.4b),
P = -1/2 (R1 Q1'^2 + R2 Q2'^2 + R3 u^2) - A |u|^(b+1)/(b+1).
"""

import sympy as sp

from lagrange import System, coordinates, delta, parameters, t
from lagrange.corpus import (
    EquationsOfMotion,
    GeneralizedForces,
    KineticEnergy,
    PotentialEnergy,
    PowerFunction,
    Problem,
    Simulation,
)

Q1, Q2 = coordinates("Q1 Q2")
M11, M22, M33, M12, M13, M23 = parameters("M_11 M_22 M_33 M_12 M_13 M_23")
C, E1, E0, w, R1, R2, R3, A, b = parameters("C E_1 E_0 omega R_1 R_2 R_3 A b")
half = sp.Rational(1, 2)
d1, d2 = Q1.diff(t), Q2.diff(t)
u = d2 - d1  # current Q3' of the common branch (Q3 = Q2 - Q1)
tube = A * sp.Abs(u) ** (b - 1) * u

T = half * (M11 * d1**2 + M22 * d2**2 + M33 * u**2 + 2 * M12 * d1 * d2 + 2 * M13 * d1 * u + 2 * M23 * d2 * u)
V = half * Q1**2 / C - E1 * Q1 - Q2 * E0 * sp.sin(w * t)  # L = T - V as printed; E2 = E0 sin wt kept in L
dW = -(R1 * d1 * delta(Q1) + R2 * d2 * delta(Q2) + R3 * u * delta(Q2 - Q1) + tube * delta(Q2 - Q1))

system = System([Q1, Q2], T=T, V=V, forces=dW, name="two-tube circuit, Fig. 15-4")
system_P = System(
    [Q1, Q2], T=T, V=V,
    P=-half * (R1 * d1**2 + R2 * d2**2 + R3 * u**2) - A * sp.Abs(u) ** (b + 1) / (b + 1),
    name="two-tube circuit, Fig. 15-4 (power function)",
)

F1 = -R1 * d1 + R3 * u + tube
F2 = -R2 * d2 - R3 * u - tube
m12 = M12 - M33 + M13 - M23
EOM = EquationsOfMotion(
    [
        sp.Eq((M11 + M33 - 2 * M13) * Q1.diff(t, 2) + m12 * Q2.diff(t, 2) + Q1 / C - E1, F1),
        sp.Eq((M22 + M33 + 2 * M23) * Q2.diff(t, 2) + m12 * Q1.diff(t, 2) - E0 * sp.sin(w * t), F2),
    ],
    per_equation=True,
)
BOOK_T = KineticEnergy(
    half * (M11 * d1**2 + M22 * d2**2 + M33 * (d2 - d1) ** 2 + 2 * M12 * d1 * d2 + 2 * M13 * d1 * (d2 - d1)
            + 2 * M23 * d2 * (d2 - d1))
)
BOOK_V = PotentialEnergy(half * Q1**2 / C - E1 * Q1 - Q2 * E0 * sp.sin(w * t))
SIM = Simulation(
    params={M11: 1.0, M22: 1.2, M33: 0.8, M12: 0.2, M13: 0.1, M23: 0.15, C: 1.0, E1: 1.0, E0: 0.5, w: 2.0,
            R1: 0.1, R2: 0.2, R3: 0.05, A: 0.3, b: 1.5},
    initial={Q1: 0.0, Q2: 0.0, d1: 0.3, d2: 0.1},
    t_end=10,
)
NOTE = ("Wells gives L and delta W only; the equations of motion are not printed — they were derived in the "
        "catalog (with u = Q2' - Q1') and are checked here against Wells' L and delta W.")

PROBLEMS = [
    Problem(
        id="ex15.2",
        title="Circuit with two identical tubes (signed power-law drop) and an applied E0 sin wt, by virtual work",
        chapter=15,
        source="Wells, Example 15.2",
        system=system,
        answers=[BOOK_T, BOOK_V, GeneralizedForces({Q1: F1, Q2: F2}), EOM],
        simulation=SIM,
        correction=NOTE,
        ranges={"b": (1.2, 2.5)},
    ),
    Problem(
        id="ex15.2-P",
        title="Circuit with two identical tubes: the same resistive forces from Wells' power function (15.4b)",
        chapter=15,
        source="Wells, Example 15.2 and eq. (15.4b)",
        system=system_P,
        answers=[
            PowerFunction(-half * (R1 * d1**2 + R2 * d2**2 + R3 * (d2 - d1) ** 2)
                          - A * sp.Abs(d2 - d1) ** (b + 1) / (b + 1)),
            GeneralizedForces({Q1: F1, Q2: F2}),
            # per_equation's symbolic ratio test cannot identify dP/du = -A |u|^b sign(u) with the book's
            # -A |u|^(b-1) u; the accelerations are compared numerically (and per equation in "ex15.2").
            EquationsOfMotion(EOM.equations),
        ],
        simulation=SIM,
        correction=NOTE,
        ranges={"b": (1.2, 2.5)},
    ),
]
