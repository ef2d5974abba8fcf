"""Wells, Problem 3.4 — plane polar motion in the coordinates (r, q = sin θ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

r, q = coordinates("r q")
m = parameters("m")

# x = r cosθ = r sqrt(1 − q²), y = r sinθ = r q (first quadrant).
system = System([r, q], bodies=[Particle(m, (r * sp.sqrt(1 - q**2), r * q), name="particle")],
                name="particle in (r, sin theta) coordinates")

PROBLEM = Problem(
    id="p3.4",
    title="Kinetic energy in the coordinates r and q = sin(theta)",
    chapter=3,
    source="Wells, Problem 3.4",
    system=system,
    answers=[KineticEnergy(sp.Rational(1, 2) * m * (r.diff(t) ** 2 + r**2 * q.diff(t) ** 2 / (1 - q**2)))],
    simulation=Simulation(params={m: 1}, initial={r: 1.0, q: 0.2, r.diff(t): 0.1, q.diff(t): 0.2}, t_end=1.0),
)
