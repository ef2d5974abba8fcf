"""Wells, Problem 6.5 — double torsional pendulum with eddy-current damping (a1) and a brake between disks (a2)."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, PowerFunction, Problem, Simulation

th1, th2 = coordinates("theta1 theta2")
I1, I2, C1, C2, C3, a1, a2, r1, r2 = parameters("I1 I2 C1 C2 C3 a1 a2 r1 r2")

# Two damping elements on each: viscous a1 at radius r1 on disk 1 (fixed magnets), a2 at radius r2 between disks.
P = 2 * (-a1 * (r1 * th1.diff(t)) ** 2 / 2) + 2 * (-a2 * (r2 * (th1.diff(t) - th2.diff(t))) ** 2 / 2)
system = System([th1, th2], T=I1 * th1.diff(t) ** 2 / 2 + I2 * th2.diff(t) ** 2 / 2,
                V=C3 * th1**2 / 2 + C2 * (th1 - th2) ** 2 / 2 + C1 * th2**2 / 2, P=P,
                name="double torsional pendulum with damping")

d1, d2 = th1.diff(t), th2.diff(t)
PROBLEM = Problem(
    id="p6.5",
    title="Double torsional pendulum with eddy-current and brake damping",
    chapter=6,
    source="Wells, Problem 6.5",
    system=system,
    answers=[
        EquationsOfMotion([
            sp.Eq(I1 * th1.diff(t, 2) + C3 * th1 + C2 * (th1 - th2) + 2 * a1 * r1**2 * d1 + 2 * a2 * r2**2 * (d1 - d2), 0),
            sp.Eq(I2 * th2.diff(t, 2) - C2 * (th1 - th2) + C1 * th2 - 2 * a2 * r2**2 * (d1 - d2), 0),
        ], per_equation=True),
        PowerFunction(-a1 * r1**2 * d1**2 - a2 * r2**2 * (d1 - d2) ** 2),
    ],
    simulation=Simulation(params={I1: 1, I2: 0.5, C1: 2, C2: 1, C3: 3, a1: 0.1, a2: 0.05, r1: 0.5, r2: 0.4},
                          initial={th1: 0.5, th2: 0, th1.diff(t): 0, th2.diff(t): 0}, t_end=10),
    correction="V and P are implied by the printed equations (catalog); the damping is modelled as a pair of "
    "viscous elements (coefficient a_i at radius r_i) per stage.",
)
