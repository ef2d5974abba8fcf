"""Wells, Problem 6.22 — the spring pendulum on a rough incline (Prob. 6.9) with every force in P (6.18)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

r, theta = coordinates("r theta")
m, g, k, r0, alpha, a = parameters("m g k r0 alpha a")

pos = (r * sp.sin(theta), r * sp.cos(theta))  # in the incline; second component down the slope
speed = sp.sqrt(sum(c.diff(t) ** 2 for c in pos))
# P = friction (-a v) + power of the spring force along r + power of m g sin(alpha) down the slope.
P = -a * speed - k * (r - r0) * r.diff(t) + m * g * sp.sin(alpha) * pos[1].diff(t)
system = System([r, theta], bodies=[Particle(m, pos)], P=P, name="spring pendulum on a rough incline (all in P)")

rd, thd = r.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="p6.22",
    title="P = -a(rd^2 + r^2 thd^2)^(1/2) - k(r - r0) rd + m g sin(alpha)(rd cos theta - r thd sin theta)",
    chapter=6,
    source="Wells, Problem 6.22",
    system=system,
    answers=[PowerFunction(-a * sp.sqrt(rd**2 + r**2 * thd**2) - k * (r - r0) * rd
                           + m * g * sp.sin(alpha) * (rd * sp.cos(theta) - r * thd * sp.sin(theta)))],
    simulation=Simulation(params={m: 1, g: 9.81, k: 30, r0: 1, alpha: 0.4, a: 0.5},
                          initial={r: 1.2, theta: 0.5, r.diff(t): 0.3, theta.diff(t): 1}, t_end=0.5),
    ranges={"alpha": (0.1, 1.2)},
    correction="Spring and gravity are in P only (not in V), so nothing is counted twice.",
)
