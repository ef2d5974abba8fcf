"""Wells, Problem 2.14 — velocity squared for x1 = x0 + r cos(α+θ), y1 = y0 + r sin(α+θ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity

x0, y0, r, alpha, theta = coordinates("x0 y0 r alpha theta")
m = parameters("m")

u = alpha + theta
system = System(
    [x0, y0, r, alpha, theta],
    bodies=[Particle(m, (x0 + r * sp.cos(u), y0 + r * sp.sin(u)))],
    name="particle about a moving point",
)

x0d, y0d, rd, ud = x0.diff(t), y0.diff(t), r.diff(t), alpha.diff(t) + theta.diff(t)
v2 = (x0d**2 + y0d**2 + rd**2 + r**2 * ud**2 + 2 * rd * (y0d * sp.sin(u) + x0d * sp.cos(u))
      + 2 * r * ud * (y0d * sp.cos(u) - x0d * sp.sin(u)))

PROBLEM = Problem(
    id="p2.14",
    title="Particle about a moving point: v^2 in (x0, y0, r, α, θ)",
    chapter=2,
    source="Wells, Problem 2.14",
    system=system,
    answers=[Quantity("v^2 = 2T/m", lambda s: 2 * s.T / m, v2), KineticEnergy(sp.Rational(1, 2) * m * v2)],
    correction="Five coordinates for one planar particle (the book's set, superfluous on purpose): singular "
    "mass matrix, no simulation.",
)
