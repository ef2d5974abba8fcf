"""Wells, Example 6.2 — dumbbell sliding on a rough horizontal plane (dry friction on each mass), q = (x, y, theta)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, mu, g = parameters("m1 m2 l1 l2 mu g")

p1 = (x + l1 * sp.cos(theta), y + l1 * sp.sin(theta))
p2 = (x - l2 * sp.cos(theta), y - l2 * sp.sin(theta))
v1 = sp.sqrt(sum(c.diff(t) ** 2 for c in p1))
v2 = sp.sqrt(sum(c.diff(t) ** 2 for c in p2))
f1, f2 = mu * m1 * g, mu * m2 * g
# Coulomb friction f_i opposite each mass's velocity: Wells' P = -sum f_i v_i (6.15).
system = System([x, y, theta], bodies=[Particle(m1, p1), Particle(m2, p2)], P=-f1 * v1 - f2 * v2,
                name="dumbbell on a rough plane")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
V1 = sp.sqrt((xd - l1 * thd * sp.sin(theta)) ** 2 + (yd + l1 * thd * sp.cos(theta)) ** 2)
V2 = sp.sqrt((xd + l2 * thd * sp.sin(theta)) ** 2 + (yd - l2 * thd * sp.cos(theta)) ** 2)
PROBLEM = Problem(
    id="ex6.2",
    title="Dumbbell on a rough plane: generalized friction forces F_x, F_theta",
    chapter=6,
    source="Wells, Example 6.2",
    system=system,
    answers=[
        GeneralizedForces({
            x: -f2 * (xd + l2 * thd * sp.sin(theta)) / V2 - f1 * (xd - l1 * thd * sp.sin(theta)) / V1,
            theta: -(f2 * (l2 * (xd * sp.sin(theta) - yd * sp.cos(theta)) + l2**2 * thd) / V2
                     + f1 * (l1 * (yd * sp.cos(theta) - xd * sp.sin(theta)) + l1**2 * thd) / V1),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l1: 0.5, l2: 0.3, mu: 0.2, g: 9.81},
                          initial={x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}, t_end=0.2),
    correction="F_y is not printed separately (read from eq. (3)); F_theta is the book's coefficient of delta theta "
    "with its overall minus sign.",
)
