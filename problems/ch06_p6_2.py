"""Wells, Problem 6.2 — viscous dumbbell in coordinates (x1, y1, theta) of mass m1, l = l1 + l2."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x1, y1, theta = coordinates("x1 y1 theta")
m1, m2, l, a1, a2 = parameters("m1 m2 l a1 a2")

p1 = (x1, y1)
p2 = (x1 - l * sp.cos(theta), y1 - l * sp.sin(theta))
P = -sum(a * sum(c.diff(t) ** 2 for c in p) / 2 for a, p in ((a1, p1), (a2, p2)))
system = System([x1, y1, theta], bodies=[Particle(m1, p1), Particle(m2, p2)], P=P, name="viscous dumbbell (x1, y1)")

x1d, y1d, thd = x1.diff(t), y1.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="p6.2",
    title="Viscous dumbbell in (x1, y1, theta)",
    chapter=6,
    source="Wells, Problem 6.2",
    system=system,
    answers=[
        GeneralizedForces({
            x1: -(a1 + a2) * x1d - a2 * l * thd * sp.sin(theta),
            y1: -(a1 + a2) * y1d + a2 * l * thd * sp.cos(theta),
            theta: -a2 * l**2 * thd - a2 * l * (x1d * sp.sin(theta) - y1d * sp.cos(theta)),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l: 0.8, a1: 0.5, a2: 0.3},
                          initial={x1: 0, y1: 0, theta: 0, x1.diff(t): 1, y1.diff(t): 0.5, theta.diff(t): 2}, t_end=5),
    correction="m2 is placed at (x1 - l cos theta, y1 - l sin theta), the placement the printed signs imply.",
)
