"""Wells, Problem 3.13 — the parabola y = b x² with the polar angle θ as coordinate."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters
from lagrange.corpus import GeneralizedForces, Problem

theta = coordinates("theta")
m, b, Fx, Fy = parameters("m b F_x F_y")

# Point of the parabola seen from the origin at angle θ: x = tanθ / b, y = tan²θ / b.
p = Particle(m, (sp.tan(theta) / b, sp.tan(theta) ** 2 / b), name="bead")
system = System([theta], bodies=[p], forces=[Force(p, (Fx, Fy))], name="bead on a parabola, polar angle coordinate")

PROBLEM = Problem(
    id="p3.13",
    title="Bead on y = b x^2 with the polar angle as coordinate: F_theta from F_x, F_y",
    chapter=3,
    source="Wells, Problem 3.13",
    system=system,
    answers=[
        GeneralizedForces({theta: Fx / (b * sp.cos(theta) ** 2) + 2 * Fy * sp.tan(theta) / (b * sp.cos(theta) ** 2)}),
    ],
    correction="Only the generalized force is printed; the repeat of Problem 3.2 asked there has no printed answer.",
)
