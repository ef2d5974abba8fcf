"""Wells, Example 15.1 — two-mesh network of Fig. 15-3: three coils with mutual inductance between all,
three capacitors, three EMFs, three resistors; charges as coordinates.

Branch charges Q1, Q2, Q3 with the junction (Kirchhoff) law Q1 = Q2 + Q3; Wells keeps q = (Q1, Q2) and writes
Q3 = Q1 - Q2. Inductances play the part of masses in T (15.1), elastances 1/C of springs in V (15.2), the EMFs
enter V as -E1 Q1 + E2 Q2 + E3 Q3 (E2, E3 opposed to the assumed currents), and the resistors enter through
Wells' power function P = -1/2 sum R Q'^2 (15.4a), F_Q = +dP/dQ'.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
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
C1, C2, C3, E1, E2, E3, R1, R2, R3 = parameters("C_1 C_2 C_3 E_1 E_2 E_3 R_1 R_2 R_3")
half = sp.Rational(1, 2)
d1, d2 = Q1.diff(t), Q2.diff(t)
Q3 = Q1 - Q2  # junction law Q1 = Q2 + Q3
d3 = Q3.diff(t)

T = half * (M11 * d1**2 + M22 * d2**2 + M33 * d3**2 + 2 * M12 * d1 * d2 + 2 * M13 * d1 * d3 + 2 * M23 * d2 * d3)
V = half * (Q1**2 / C1 + Q2**2 / C2 + Q3**2 / C3) - E1 * Q1 + E2 * Q2 + E3 * Q3
P = -half * (R1 * d1**2 + R2 * d2**2 + R3 * d3**2)

system = System([Q1, Q2], T=T, V=V, P=P, name="two-mesh network, Fig. 15-3")

F1 = R3 * d2 - (R1 + R3) * d1
F2 = R3 * d1 - (R2 + R3) * d2

PROBLEM = Problem(
    id="ex15.1",
    title="Two-mesh network with three mutually coupled coils, capacitors, EMFs and resistors",
    chapter=15,
    source="Wells, Example 15.1, eqs. (3), (4) and the equations of motion",
    system=system,
    answers=[
        KineticEnergy(
            half * (M11 * d1**2 + M22 * d2**2 + M33 * (d1 - d2) ** 2 + 2 * M12 * d1 * d2
                    + 2 * M13 * d1 * (d1 - d2) + 2 * M23 * d2 * (d1 - d2))
        ),
        PotentialEnergy(half * (Q1**2 / C1 + Q2**2 / C2 + (Q1 - Q2) ** 2 / C3) - E1 * Q1 + E2 * Q2 + E3 * (Q1 - Q2)),
        PowerFunction(-half * (R1 * d1**2 + R2 * d2**2 + R3 * (d1 - d2) ** 2)),
        GeneralizedForces({Q1: F1, Q2: F2}),
        EquationsOfMotion(
            [
                sp.Eq((M11 + M33 + 2 * M13) * Q1.diff(t, 2) + (M12 - M13 - M33 + M23) * Q2.diff(t, 2)
                      + (1 / C1 + 1 / C3) * Q1 - Q2 / C3 - E1 + E3, F1),
                sp.Eq((M22 + M33 - 2 * M23) * Q2.diff(t, 2) + (M12 - M33 - M13 + M23) * Q1.diff(t, 2)
                      + (1 / C2 + 1 / C3) * Q2 - Q1 / C3 + E2 - E3, F2),
            ],
            per_equation=True,
        ),
    ],
    # inductance matrix (branch form) positive definite: self 1.0, mutual 0.2
    simulation=Simulation(
        params={M11: 1.0, M22: 1.2, M33: 0.8, M12: 0.2, M13: 0.1, M23: 0.15, C1: 1.0, C2: 0.5, C3: 2.0,
                E1: 1.0, E2: 0.5, E3: 0.2, R1: 0.1, R2: 0.2, R3: 0.05},
        initial={Q1: 0.0, Q2: 0.0, d1: 0.0, d2: 0.0},
        t_end=20,
    ),
)
