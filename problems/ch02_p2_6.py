"""Wells, Problem 2.6 — a point of a rigid body turning about the fixed point O (Fig. 2-13)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters
from lagrange.corpus import Problem, Quantity

theta, phi, alpha = coordinates("theta phi alpha")
m, R, r = parameters("m R r")

w = R * sp.sin(theta) - r * sp.cos(alpha) * sp.cos(theta)
system = System(
    [theta, phi, alpha],
    bodies=[Particle(m, (w * sp.cos(phi) + r * sp.sin(alpha) * sp.sin(phi),
                         w * sp.sin(phi) - r * sp.sin(alpha) * sp.cos(phi),
                         R * sp.cos(theta) + r * sp.cos(alpha) * sp.sin(theta)))],
    name="point of a rigid body about a fixed point",
)


def _dist2(s):
    p = s.bodies[0].position_vectors()[0]
    return sum(c**2 for c in p)


PROBLEM = Problem(
    id="p2.6",
    title="Rigid body about a fixed point: transformation equations of a body point (|r|^2 = R^2 + r^2)",
    chapter=2,
    source="Wells, Problem 2.6 (Fig. 2-13)",
    system=system,
    answers=[Quantity("x^2 + y^2 + z^2", _dist2, R**2 + r**2)],
    correction="The book's answer is the transformation equations; the check is the consistency condition "
    "that the point stays at distance (R^2 + r^2)^(1/2) from O. Three angles for one point on a sphere: "
    "singular mass matrix, no simulation.",
)
