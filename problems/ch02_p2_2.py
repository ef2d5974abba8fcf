"""Wells, Problem 2.2 — (r2, α) ↔ (A, q = sin θ) for the point p of Fig. 2-6."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r2, alpha = coordinates("r2 alpha")
m, s = parameters("m s")

# Inferred geometry: a at the origin, b at (s, 0), p = (s − r2 cos α, r2 sin α); A = xy/2, θ = angle of ap.
system = System([r2, alpha], bodies=[Particle(m, (s - r2 * sp.cos(alpha), r2 * sp.sin(alpha)), name="p")],
                name="point p in bipolar-type coordinates")


def _two_A(sys_):
    x, y = sys_.bodies[0].position_vectors()[0][:2]
    return x * y


def _relation(sys_):
    # q(s − r2 cos α) − r2 sin α (1 − q²)^(1/2) with q = sin θ taken from the position of p
    x, y = sys_.bodies[0].position_vectors()[0][:2]
    q = y / sp.sqrt(x**2 + y**2)
    return q * (s - r2 * sp.cos(alpha)) - r2 * sp.sin(alpha) * sp.sqrt(1 - q**2)


PROBLEM = Problem(
    id="p2.2",
    title="Transformation (r2, α) → (A, q = sin θ) for the point p of Fig. 2-6",
    chapter=2,
    source="Wells, Problem 2.2 (answer key, printed under the label 2.1)",
    system=system,
    answers=[
        Quantity("2A", _two_A, s * r2 * sp.sin(alpha) - r2**2 * sp.sin(alpha) * sp.cos(alpha)),
        Quantity("q(s − r2 cos α) − r2 sin α (1 − q²)^(1/2)", _relation, sp.Integer(0)),
    ],
    simulation=Simulation(params={m: 1}, initial={r2: 1.0, alpha: 0.5, r2.diff(t): 0.1, alpha.diff(t): 0.2},
                          t_end=1.0),
    correction="Geometry inferred (figure not available): a at the origin, b at (s, 0), p = (s − r2 cos α, "
    "r2 sin α), A = xy/2 and θ the angle of ap from X. The key prints this answer under the label '2.1'.",
    ranges={"s": (2.5, 3.5)},
)
