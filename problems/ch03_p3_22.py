"""Wells, Problem 3.22 — the cup z = b r² on a platform accelerating along Y1, with φ free (m inside the cup)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

r, phi = coordinates("r phi")
m, g, b, a = parameters("m g b a")

Z = b * r**2
bead = Particle(m, (r * sp.cos(phi), a * t**2 / 2 + r * sp.sin(phi), Z), name="particle")
system = System([r, phi], bodies=[bead], forces=-m * g * delta(Z), name="particle in a cup on an accelerating platform")

rd, pd = r.diff(t), phi.diff(t)
PROBLEM = Problem(
    id="p3.22",
    title="Particle in a paraboloidal cup on an accelerating platform: T, forces, equations of motion",
    chapter=3,
    source="Wells, Problem 3.22",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (
            rd**2 + r**2 * pd**2 + a**2 * t**2 + 2 * rd * a * t * sp.sin(phi)
            + 2 * r * pd * a * t * sp.cos(phi) + 4 * b**2 * r**2 * rd**2)),
        GeneralizedForces({r: -2 * m * g * b * r, phi: 0}),
        EquationsOfMotion([
            sp.Eq((1 + 4 * b**2 * r**2) * r.diff(t, 2) + 4 * b**2 * r * rd**2 - r * pd**2 + a * sp.sin(phi)
                  + 2 * g * b * r, 0),
            sp.Eq(r**2 * phi.diff(t, 2) + 2 * r * rd * pd + a * r * sp.cos(phi), 0),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, b: 1, a: 0.5},
                          initial={r: 0.3, phi: 0, r.diff(t): 0, phi.diff(t): 2.0}, t_end=2),
    correction="The book gives T and the forces; the equations of motion (per unit m) are derived in the catalog.",
)
