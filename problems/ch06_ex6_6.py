"""Wells, Example 6.6 — dumbbell with viscous drag a1, a2 on the two masses, q = (x, y, theta)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, a1, a2 = parameters("m1 m2 l1 l2 a1 a2")

p1 = (x + l1 * sp.cos(theta), y + l1 * sp.sin(theta))
p2 = (x - l2 * sp.cos(theta), y - l2 * sp.sin(theta))
# Viscous drag: Wells' P = -(1/2) sum a_i v_i^2 (6.16).
P = -sum(a * sum(c.diff(t) ** 2 for c in p) / 2 for a, p in ((a1, p1), (a2, p2)))
system = System([x, y, theta], bodies=[Particle(m1, p1), Particle(m2, p2)], P=P, name="viscous dumbbell")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="ex6.6",
    title="Viscous dumbbell: F_x, F_y, F_theta",
    chapter=6,
    source="Wells, Example 6.6",
    system=system,
    answers=[
        GeneralizedForces({
            x: -((a1 + a2) * xd + (a2 * l2 - a1 * l1) * thd * sp.sin(theta)),
            y: -((a1 + a2) * yd - (a2 * l2 - a1 * l1) * thd * sp.cos(theta)),
            theta: -((a2 * l2**2 + a1 * l1**2) * thd + (a2 * l2 - a1 * l1) * (xd * sp.sin(theta) - yd * sp.cos(theta))),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l1: 0.5, l2: 0.3, a1: 0.5, a2: 0.3},
                          initial={x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}, t_end=5),
)
