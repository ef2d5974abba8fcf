"""Wells, Problem 3.21 — bead on a parabolic wire z = b r² turning at φ = ωt on a platform accelerating along Y1."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

r, phi = coordinates("r phi")
m, g, b, a, w = parameters("m g b a omega")

Z = b * r**2
bead = Particle(m, (r * sp.cos(phi), a * t**2 / 2 + r * sp.sin(phi), Z), name="bead")
system = System([r], bodies=[bead], forces=-m * g * delta(Z), prescribed={phi: w * t},
                name="bead on a rotating parabolic wire on an accelerating platform")

pd = phi.diff(t)
T_book = sp.Rational(1, 2) * m * (
    r.diff(t) ** 2 + r**2 * pd**2 + a**2 * t**2 + 2 * r.diff(t) * a * t * sp.sin(phi)
    + 2 * r * pd * a * t * sp.cos(phi) + 4 * b**2 * r**2 * r.diff(t) ** 2
)
on = {phi: w * t}

PROBLEM = Problem(
    id="p3.21",
    title="Bead on a rotating parabolic wire on an accelerating platform: T, F_r, equation of motion",
    chapter=3,
    source="Wells, Problem 3.21",
    system=system,
    answers=[
        KineticEnergy(T_book.subs(on).doit()),
        GeneralizedForces({r: -2 * m * g * b * r}),
        EquationsOfMotion([
            sp.Eq((1 + 4 * b**2 * r**2) * r.diff(t, 2) + 4 * b**2 * r * r.diff(t) ** 2 - w**2 * r
                  + a * sp.sin(w * t) + 2 * g * b * r, 0)
        ], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, b: 1, a: 0.5, w: 2}, initial={r: 0.3, r.diff(t): 0}, t_end=3),
    correction="The book gives T (φ general) and F_r; the equation of motion for φ = ωt is derived in the catalog "
               "(per unit mass).",
)
