"""Wells, eq. (2.41) — double pendulum in rectangular coordinates with an inextensible upper string."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

x1, x2, y2 = coordinates("x1 x2 y2")
m1, m2, r1 = parameters("m1 m2 r1")

# x1² + y1² = r1² eliminates y1 (m1 below the support: y1 = −(r1² − x1²)^(1/2)); m2 free in the plane.
system = System(
    [x1, x2, y2],
    bodies=[Particle(m1, (x1, -sp.sqrt(r1**2 - x1**2)), name="m1"), Particle(m2, (x2, y2), name="m2")],
    name="double pendulum, rectangular coordinates",
)

PROBLEM = Problem(
    id="eq2.41",
    title="Double pendulum in rectangular coordinates, y1 eliminated by x1^2 + y1^2 = r1^2",
    chapter=2,
    source="Wells, Sec. 2.9, eq. (2.41)",
    system=system,
    answers=[
        KineticEnergy(
            sp.Rational(1, 2) * m1 * x1.diff(t) ** 2 * r1**2 / (r1**2 - x1**2)
            + sp.Rational(1, 2) * m2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)
        ),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 1, r1: 1.0},
        initial={x1: 0.2, x2: 0.5, y2: -1.5, x1.diff(t): 0.3, x2.diff(t): 0.0, y2.diff(t): 0.0},
        t_end=1.0,
    ),
    correction="Only T is given (the string r2 is not imposed in (2.41)); the simulation is the force-free "
    "motion of this T, kept short so |x1| < r1.",
)
