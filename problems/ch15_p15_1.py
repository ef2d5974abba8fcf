"""Wells, Problem 15.1 — the two-mesh circuit of Fig. 15-10: coils M11 and M22 coupled by M12, a third coil M33
(no mutual inductance with the others) in series with M22, a capacitor C, resistances R1, R2 and an applied
E0 sin(wt) in mesh 1."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, MassMatrix, PotentialEnergy, Problem, Simulation

Q1, Q2 = coordinates("Q1 Q2")
M11, M22, M33, M12, C, E0, w, R1, R2 = parameters("M_11 M_22 M_33 M_12 C E_0 omega R_1 R_2")
half = sp.Rational(1, 2)
d1, d2 = Q1.diff(t), Q2.diff(t)

system = System(
    [Q1, Q2],
    T=half * (M11 * d1**2 + 2 * M12 * d1 * d2 + (M22 + M33) * d2**2),
    V=-Q1 * E0 * sp.sin(w * t) + half * Q2**2 / C,
    P=-half * (R1 * d1**2 + R2 * d2**2),
    name="two-mesh circuit, Fig. 15-10",
)

PROBLEM = Problem(
    id="p15.1",
    title="Two-mesh circuit with coupled coils, capacitor and applied E0 sin wt (Fig. 15-10)",
    chapter=15,
    source="Wells, Problem 15.1",
    system=system,
    answers=[
        KineticEnergy(half * (M11 * d1**2 + 2 * M12 * d1 * d2 + (M22 + M33) * d2**2)),
        PotentialEnergy(-Q1 * E0 * sp.sin(w * t) + half * Q2**2 / C),
        MassMatrix(sp.Matrix([[M11, M12], [M12, M22 + M33]])),
        EquationsOfMotion(
            [
                sp.Eq(M11 * Q1.diff(t, 2) + M12 * Q2.diff(t, 2) - E0 * sp.sin(w * t), -R1 * d1),
                sp.Eq((M22 + M33) * Q2.diff(t, 2) + M12 * Q1.diff(t, 2) + Q2 / C, -R2 * d2),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={M11: 1.0, M22: 1.0, M33: 0.5, M12: 0.4, C: 0.5, E0: 1.0, w: 2.0, R1: 0.2, R2: 0.1},
        initial={Q1: 0.0, Q2: 0.0, d1: 0.0, d2: 0.0},
        t_end=20,
    ),
    correction="L is printed with the cross term 1/2 M12 Q1' Q2'; the stated equations (M12 Q2'' in the Q1 equation, "
               "M12 Q1'' in the Q2 equation) need 1/2 (2 M12 Q1' Q2') as in (15.1), T = 1/2 sum M_ir Q_i' Q_r' "
               "(catalog, re-derived).",
)
