"""Wells, Example 3.7 — acceleration component a_θ in spherical coordinates via (3.24)."""

import sympy as sp

from lagrange import Particle, System, coordinates, t
from lagrange.corpus import KineticEnergy, Problem, Quantity

r, theta, phi = coordinates("r theta phi")

# Unit mass, so T is Wells' T' = v²/2.
pos = (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta))
system = System([r, theta, phi], bodies=[Particle(1, pos, name="unit mass")], name="particle, spherical coordinates")


def a_theta(s):
    """(3.24): a_θ = [d/dt ∂T'/∂θ̇ − ∂T'/∂θ] / h_θ, h_θ = |∂r/∂θ|."""
    eq = s.equations()[1]
    lagrangian_side = eq.lhs - eq.rhs  # no forces: this is d/dt ∂T'/∂θ̇ − ∂T'/∂θ
    P = s.bodies[0].position
    th = sp.Dummy("theta")
    h = sp.sqrt(sp.trigsimp(sum(sp.diff(c.subs(theta, th), th) ** 2 for c in P))).subs(th, theta)
    return lagrangian_side / h


PROBLEM = Problem(
    id="ex3.7",
    title="Spherical acceleration component a_theta from Lagrange's expression (3.24)",
    chapter=3,
    source="Wells, Example 3.7",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2
                                            + r**2 * sp.sin(theta) ** 2 * phi.diff(t) ** 2)),
        Quantity("d/dt dT'/dthetadot - dT'/dtheta", lambda s: s.equations()[1].lhs - s.equations()[1].rhs,
                 r**2 * theta.diff(t, 2) + 2 * r * r.diff(t) * theta.diff(t)
                 - r**2 * phi.diff(t) ** 2 * sp.sin(theta) * sp.cos(theta)),
        Quantity("a_theta", a_theta,
                 r * theta.diff(t, 2) + 2 * r.diff(t) * theta.diff(t) - r * phi.diff(t) ** 2 * sp.sin(theta) * sp.cos(theta)),
    ],
    correction="Printed a_θ has '2 r ṙ θ̇' (an extra r) and T' has 'r²' for ṙ²; dividing the printed intermediate "
               "r²θ̈ + 2rṙθ̇ − r²φ̇² sinθ cosθ by h_θ = r gives 2ṙθ̇ (catalog, sym ✓).",
)
