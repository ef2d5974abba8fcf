"""Wells, Problem 3.28 — the paraboloid parameter b as a coordinate: (b, r, φ) with z = b r², Z vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Simulation

b, r, phi = coordinates("b r phi")
m, g = parameters("m g")

Z = b * r**2
system = System([b, r, phi], bodies=[Particle(m, (r * sp.cos(phi), r * sp.sin(phi), Z), name="particle")],
                forces=-m * g * delta(Z), name="particle in (b, r, phi) coordinates")

PROBLEM = Problem(
    id="p3.28",
    title="Particle in coordinates (b, r, phi) with z = b r^2: T and generalized forces",
    chapter=3,
    source="Wells, Problem 3.28",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (r.diff(t) ** 2 * (1 + 4 * b**2 * r**2) + r**2 * phi.diff(t) ** 2
                                                + b.diff(t) ** 2 * r**4 + 4 * b * r**3 * b.diff(t) * r.diff(t))),
        GeneralizedForces({r: -2 * m * g * b * r, b: -m * g * r**2, phi: 0}),
    ],
    simulation=Simulation(params={m: 1, g: 9.81},
                          initial={b: 0.5, r: 1.0, phi: 0, b.diff(t): 0, r.diff(t): 0, phi.diff(t): 1.0}, t_end=0.3),
)
