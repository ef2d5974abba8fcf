"""Wells, Example 6.9 — dumbbell with power-law drag f_i = a_i v_i^(n_i) on each mass."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, a1, a2, n1, n2 = parameters("m1 m2 l1 l2 a1 a2 n1 n2")

p1 = (x + l1 * sp.cos(theta), y + l1 * sp.sin(theta))
p2 = (x - l2 * sp.cos(theta), y - l2 * sp.sin(theta))
v1 = sp.sqrt(sum(c.diff(t) ** 2 for c in p1))
v2 = sp.sqrt(sum(c.diff(t) ** 2 for c in p2))
# Drag a v^n opposite v: Wells' P = -sum a_i v_i^(n_i+1)/(n_i+1) (6.14).
system = System([x, y, theta], bodies=[Particle(m1, p1), Particle(m2, p2)],
                P=-a1 * v1 ** (n1 + 1) / (n1 + 1) - a2 * v2 ** (n2 + 1) / (n2 + 1), name="dumbbell, power-law drag")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
V1 = sp.sqrt((xd - l1 * thd * sp.sin(theta)) ** 2 + (yd + l1 * thd * sp.cos(theta)) ** 2)
V2 = sp.sqrt((xd + l2 * thd * sp.sin(theta)) ** 2 + (yd - l2 * thd * sp.cos(theta)) ** 2)
PROBLEM = Problem(
    id="ex6.9",
    title="Dumbbell with power-law drag a_i v_i^(n_i): F_theta",
    chapter=6,
    source="Wells, Example 6.9",
    system=system,
    answers=[
        GeneralizedForces({
            theta: -a1 * V1 ** (n1 - 1) * l1 * (yd * sp.cos(theta) - xd * sp.sin(theta) + l1 * thd)
                   - a2 * V2 ** (n2 - 1) * l2 * (xd * sp.sin(theta) - yd * sp.cos(theta) + l2 * thd),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l1: 0.5, l2: 0.3, a1: 0.5, a2: 0.3, n1: 2, n2: 1.5},
                          initial={x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}, t_end=3),
)
