"""Wells, Problem 6.9 — spring pendulum sliding on a rough incline (angle alpha), friction f = mu m g cos(alpha)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

r, theta = coordinates("r theta")
m, g, k, r0, alpha, f = parameters("m g k r0 alpha f")

# Polar coordinates in the incline, theta from the down-slope line; down-slope distance r cos(theta).
pos = (r * sp.sin(theta), r * sp.cos(theta))
speed = sp.sqrt(sum(c.diff(t) ** 2 for c in pos))
system = System([r, theta], bodies=[Particle(m, pos)],
                V=k * (r - r0) ** 2 / 2 - m * g * sp.sin(alpha) * pos[1], P=-f * speed,
                name="spring pendulum on a rough incline")

rd, thd = r.diff(t), theta.diff(t)
v = sp.sqrt(rd**2 + r**2 * thd**2)
PROBLEM = Problem(
    id="p6.9",
    title="Spring pendulum on a rough incline: coefficients of delta r and delta theta in delta W",
    chapter=6,
    source="Wells, Problem 6.9",
    system=system,
    answers=[GeneralizedForces({
        r: -k * (r - r0) + m * g * sp.sin(alpha) * sp.cos(theta) - f * rd / v,
        theta: -(m * g * r * sp.sin(alpha) * sp.sin(theta) + f * r**2 * thd / v),
    }, which="total")],
    simulation=Simulation(params={m: 1, g: 9.81, k: 30, r0: 1, alpha: 0.4, f: 0.5},
                          initial={r: 1.2, theta: 0.5, r.diff(t): 0.3, theta.diff(t): 1}, t_end=0.5),
    ranges={"alpha": (0.1, 1.2)},
    correction="OCR prints (r^2 + r^2 thd^2)^(1/2) in the friction terms; the speed is (rd^2 + r^2 thd^2)^(1/2).",
)
