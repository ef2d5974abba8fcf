"""Wells, Example 15.4 — a small coil (2) on a shaft with a torsion spring k, inside a long coil (1): the mutual
inductance depends on the shaft angle, M12 = A sin(theta) (Fig. 15-6). Coil 1 carries a battery E1, coil 2 an
applied E0 sin(wt); resistances R1, R2; I = moment of inertia of the shaft and coil 2.

The mutual-inductance term A Q1' Q2' sin(theta) of T gives both the induced EMFs (A theta' Q2' cos theta, ...)
and the electrical torque A Q1' Q2' cos theta on the coil.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, PowerFunction, Problem, Simulation

Q1, Q2, th = coordinates("Q1 Q2 theta")
M11, M22, I, A, k, E1, E0, w, R1, R2 = parameters("M_11 M_22 I A k E_1 E_0 omega R_1 R_2")
half = sp.Rational(1, 2)
d1, d2, thd = Q1.diff(t), Q2.diff(t), th.diff(t)

T = half * M11 * d1**2 + half * M22 * d2**2 + half * I * thd**2 + A * d1 * d2 * sp.sin(th)
system = System(
    [Q1, Q2, th],
    T=T,
    V=-E1 * Q1 - Q2 * E0 * sp.sin(w * t) + half * k * th**2,
    P=-half * (R1 * d1**2 + R2 * d2**2),
    name="rotating coil inside a long coil, Fig. 15-6",
)

PROBLEM = Problem(
    id="ex15.4",
    title="Coil on a torsion shaft inside a long coil, M12 = A sin(theta)",
    chapter=15,
    source="Wells, Example 15.4",
    system=system,
    answers=[
        KineticEnergy(half * M11 * d1**2 + half * M22 * d2**2 + half * I * thd**2 + A * d1 * d2 * sp.sin(th)),
        # from L: ... + E1 Q1 + Q2 E0 sin wt - 1/2 k theta^2
        PotentialEnergy(-E1 * Q1 - Q2 * E0 * sp.sin(w * t) + half * k * th**2),
        PowerFunction(-half * (R1 * d1**2 + R2 * d2**2)),
        EquationsOfMotion(
            [
                sp.Eq(M11 * Q1.diff(t, 2) + A * Q2.diff(t, 2) * sp.sin(th) + A * thd * d2 * sp.cos(th) - E1, -R1 * d1),
                sp.Eq(M22 * Q2.diff(t, 2) + A * Q1.diff(t, 2) * sp.sin(th) + A * thd * d1 * sp.cos(th)
                      - E0 * sp.sin(w * t), -R2 * d2),
                sp.Eq(I * th.diff(t, 2) - A * d1 * d2 * sp.cos(th) + k * th, 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        # A^2 < M11 M22 keeps the inductance matrix positive definite for every theta
        params={M11: 1.0, M22: 1.0, I: 1.0, A: 0.5, k: 2.0, E1: 1.0, E0: 0.5, w: 3.0, R1: 0.5, R2: 0.5},
        initial={Q1: 0.0, Q2: 0.0, th: 0.3, d1: 0.0, d2: 0.0, thd: 0.0},
        t_end=20,
    ),
)
