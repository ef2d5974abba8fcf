"""Wells, Problem 15.6 — two wall galvanometers (radial fields, coil angles theta1, theta2 on suspensions k1, k2)
whose circuits (charges Q1, Q2, inductances M11, M22 coupled by M12, resistances R1, R2) share a capacitor C and
a battery E1 (Fig. 15-12).

In a radial field the flux linkage of a coil grows linearly with its angle, so the magnet terms of L are
N1 Phi1 Q1' theta1 + N2 Phi2 Q2' theta2 (part of T here, linear in the currents): they give the back EMF
N Phi theta' in the circuit and the torque N Phi Q' on the coil.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, PowerFunction, Problem, Simulation

Q1, Q2, th1, th2 = coordinates("Q1 Q2 theta1 theta2")
M11, M12, M22, I1, I2, N1, N2, Phi1, Phi2 = parameters("M_11 M_12 M_22 I_1 I_2 N_1 N_2 Phi_1 Phi_2")
E1, C, k1, k2, R1, R2 = parameters("E_1 C k_1 k_2 R_1 R_2")
half = sp.Rational(1, 2)
d1, d2, w1, w2 = Q1.diff(t), Q2.diff(t), th1.diff(t), th2.diff(t)

T = (half * (M11 * d1**2 + 2 * M12 * d1 * d2 + M22 * d2**2) + half * I1 * w1**2 + half * I2 * w2**2
     + N1 * Phi1 * d1 * th1 + N2 * Phi2 * d2 * th2)
V = -(Q1 + Q2) * E1 + half * (Q1 + Q2) ** 2 / C + half * k1 * th1**2 + half * k2 * th2**2
system = System([Q1, Q2, th1, th2], T=T, V=V, P=-half * (R1 * d1**2 + R2 * d2**2),
                name="two wall galvanometers sharing a capacitor, Fig. 15-12")

PROBLEM = Problem(
    id="p15.6",
    title="Two wall galvanometers in radial fields sharing a capacitor and a battery",
    chapter=15,
    source="Wells, Problem 15.6",
    system=system,
    answers=[
        KineticEnergy(half * (M11 * d1**2 + 2 * M12 * d1 * d2 + M22 * d2**2) + half * I1 * w1**2
                      + half * I2 * w2**2 + N1 * Phi1 * d1 * th1 + N2 * Phi2 * d2 * th2),
        PotentialEnergy(-(Q1 + Q2) * E1 + half * (Q1 + Q2) ** 2 / C + half * k1 * th1**2 + half * k2 * th2**2),
        PowerFunction(-half * (R1 * d1**2 + R2 * d2**2)),
        EquationsOfMotion(
            [
                sp.Eq(M11 * Q1.diff(t, 2) + M12 * Q2.diff(t, 2) + N1 * Phi1 * w1 - E1 + (Q1 + Q2) / C, -R1 * d1),
                sp.Eq(M22 * Q2.diff(t, 2) + M12 * Q1.diff(t, 2) + N2 * Phi2 * w2 - E1 + (Q1 + Q2) / C, -R2 * d2),
                sp.Eq(I1 * th1.diff(t, 2) - N1 * Phi1 * d1 + k1 * th1, 0),
                sp.Eq(I2 * th2.diff(t, 2) - N2 * Phi2 * d2 + k2 * th2, 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={M11: 1.0, M12: 0.3, M22: 1.0, I1: 1.0, I2: 1.5, N1: 1.0, N2: 1.0, Phi1: 0.5, Phi2: 0.4,
                E1: 1.0, C: 1.0, k1: 2.0, k2: 1.0, R1: 0.3, R2: 0.2},
        initial={Q1: 0.0, Q2: 0.0, th1: 0.0, th2: 0.0, d1: 0.0, d2: 0.0, w1: 0.0, w2: 0.0},
        t_end=20,
    ),
    correction="Wells gives L only. The equations of motion (with the resistances R1, R2 through P) were derived in "
               "the catalog for Q1 and theta1 ('the other two are similar'); the Q2, theta2 equations are their "
               "images under 1 <-> 2. Checked here against Wells' L.",
)
