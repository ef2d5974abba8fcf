"""Wells, Example 6.11 — dumbbell sliding on an incline (angle alpha) with power-law drag: the power function P."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, a1, a2, n1, n2, g, alpha = parameters("m1 m2 l1 l2 a1 a2 n1 n2 g alpha")

# y up the slope. Drag (6.14) plus the power of the gravity components along the slope (6.18).
p1 = (x + l1 * sp.cos(theta), y + l1 * sp.sin(theta))
p2 = (x - l2 * sp.cos(theta), y - l2 * sp.sin(theta))
v1 = sp.sqrt(sum(c.diff(t) ** 2 for c in p1))
v2 = sp.sqrt(sum(c.diff(t) ** 2 for c in p2))
P = (-a1 * v1 ** (n1 + 1) / (n1 + 1) - a2 * v2 ** (n2 + 1) / (n2 + 1)
     - m1 * g * sp.sin(alpha) * p1[1].diff(t) - m2 * g * sp.sin(alpha) * p2[1].diff(t))
system = System([x, y, theta], bodies=[Particle(m1, p1), Particle(m2, p2)], P=P, name="dumbbell on an incline")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="ex6.11",
    title="Dumbbell on an incline with power-law drag: P including gravity (6.19)",
    chapter=6,
    source="Wells, Example 6.11, eq. (6.19)",
    system=system,
    answers=[
        PowerFunction(
            -(a1 / (n1 + 1)) * ((xd - l1 * thd * sp.sin(theta)) ** 2 + (yd + l1 * thd * sp.cos(theta)) ** 2) ** ((n1 + 1) / 2)
            - (a2 / (n2 + 1)) * ((xd + l2 * thd * sp.sin(theta)) ** 2 + (yd - l2 * thd * sp.cos(theta)) ** 2) ** ((n2 + 1) / 2)
            - m1 * g * sp.sin(alpha) * (yd + l1 * thd * sp.cos(theta))
            - m2 * g * sp.sin(alpha) * (yd - l2 * thd * sp.cos(theta))
        ),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l1: 0.5, l2: 0.3, a1: 0.5, a2: 0.3, n1: 2, n2: 1.5, g: 9.81,
                                  alpha: 0.3},
                          initial={x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}, t_end=3),
    ranges={"alpha": (0.1, 1.2)},
)
