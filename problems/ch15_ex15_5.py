"""Wells, Example 15.5 — the network of Fig. 15-3 (Ex. 15.1) written in the "vibration" form (10.7):
inductance x acceleration + resistance x current + elastance x charge = EMF, coordinates (Q1, Q2), Q3 = Q1 - Q2."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, MassMatrix, Problem, Quantity, Simulation

Q1, Q2 = coordinates("Q1 Q2")
M11, M22, M33, M12, M13, M23 = parameters("M_11 M_22 M_33 M_12 M_13 M_23")
C1, C2, C3, E1, E2, E3, R1, R2, R3 = parameters("C_1 C_2 C_3 E_1 E_2 E_3 R_1 R_2 R_3")
half = sp.Rational(1, 2)
d1, d2 = Q1.diff(t), Q2.diff(t)
Q3 = Q1 - Q2
d3 = Q3.diff(t)

system = System(
    [Q1, Q2],
    T=half * (M11 * d1**2 + M22 * d2**2 + M33 * d3**2 + 2 * M12 * d1 * d2 + 2 * M13 * d1 * d3 + 2 * M23 * d2 * d3),
    V=half * (Q1**2 / C1 + Q2**2 / C2 + Q3**2 / C3) - E1 * Q1 + E2 * Q2 + E3 * Q3,
    P=-half * (R1 * d1**2 + R2 * d2**2 + R3 * d3**2),
    name="two-mesh network, Fig. 15-3 (vibration form)",
)

m12 = M12 + M23 - M33 - M13


def _stiffness(s):
    """Elastance matrix K = Hessian of V in the charges."""
    qs = [sp.Symbol(f"_q{i}") for i in range(2)]
    v = s.V.subs(dict(zip(s.coordinates, qs)))
    return sp.hessian(v, qs)


def _resistance(s):
    """Resistance matrix B = -Hessian of P in the currents."""
    vs = [sp.Symbol(f"_v{i}") for i in range(2)]
    p = s.P.subs({q.diff(t): v for q, v in zip(s.coordinates, vs)})
    return -sp.hessian(p, vs)


PROBLEM = Problem(
    id="ex15.5",
    title="Fig. 15-3 network in the vibration form M Q'' + B Q' + K Q = E",
    chapter=15,
    source="Wells, Example 15.5",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq((M11 + M33 + 2 * M13) * Q1.diff(t, 2) + (R1 + R3) * d1 + (1 / C1 + 1 / C3) * Q1
                      + m12 * Q2.diff(t, 2) - R3 * d2 - Q2 / C3, E1 - E3),
                sp.Eq(m12 * Q1.diff(t, 2) - R3 * d1 - Q1 / C3 + (M22 - 2 * M23 + M33) * Q2.diff(t, 2)
                      + (R2 + R3) * d2 + (1 / C2 + 1 / C3) * Q2, E3 - E2),
            ],
            per_equation=True,
        ),
        MassMatrix(sp.Matrix([[M11 + M33 + 2 * M13, m12], [m12, M22 - 2 * M23 + M33]])),
        Quantity("elastance matrix K", _stiffness,
                 sp.Matrix([[1 / C1 + 1 / C3, -1 / C3], [-1 / C3, 1 / C2 + 1 / C3]]), description="K = d2V/dQ2"),
        Quantity("resistance matrix B", _resistance,
                 sp.Matrix([[R1 + R3, -R3], [-R3, R2 + R3]]), description="B = -d2P/dQ'2"),
    ],
    simulation=Simulation(
        params={M11: 1.0, M22: 1.2, M33: 0.8, M12: 0.2, M13: 0.1, M23: 0.15, C1: 1.0, C2: 0.5, C3: 2.0,
                E1: 1.0, E2: 0.5, E3: 0.2, R1: 0.1, R2: 0.2, R3: 0.05},
        initial={Q1: 0.1, Q2: -0.1, d1: 0.0, d2: 0.0},
        t_end=20,
    ),
)
