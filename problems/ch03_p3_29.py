"""Wells, Problem 3.29 — acceleration components of a bead on a rod at fixed θ on a shaft with φ'' = c (φ' = c t)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

r, theta, phi = coordinates("r theta phi")
c = parameters("c")

# All three spherical coordinates kept (superfluous coordinates, end of Sec. 3.2), unit mass so T = T'.
pos = (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta))
system = System([r, theta, phi], bodies=[Particle(1, pos, name="unit mass")], name="spherical coordinates")


def accelerations(s):
    """(3.24): a_q = [d/dt ∂T'/∂q̇ − ∂T'/∂q] / h_q, then the rod's motion θ = const, φ' = c t, φ'' = c."""
    P = s.bodies[0].position
    out = []
    for i, q in enumerate(s.coordinates):
        eq = s.equations()[i]
        qs = sp.Dummy("q")
        h = sp.sqrt(sp.trigsimp(sum(sp.diff(comp.subs(q, qs), qs) ** 2 for comp in P))).subs(qs, q)
        a = (eq.lhs - eq.rhs) / h
        a = a.subs({theta.diff(t, 2): 0, phi.diff(t, 2): c}).subs({theta.diff(t): 0, phi.diff(t): c * t})
        out.append(a)
    return out


PROBLEM = Problem(
    id="p3.29",
    title="Bead on a rod at fixed angle on a uniformly accelerating shaft: a_r, a_theta, a_phi",
    chapter=3,
    source="Wells, Problem 3.29 (Fig. 3-9 shaft)",
    system=system,
    answers=[
        Quantity("(a_r, a_theta, a_phi)", accelerations, [
            r.diff(t, 2) - r * c**2 * t**2 * sp.sin(theta) ** 2,
            -r * c**2 * t**2 * sp.sin(theta) * sp.cos(theta),
            2 * r.diff(t) * c * t * sp.sin(theta) + r * c * sp.sin(theta),
        ]),
    ],
)
