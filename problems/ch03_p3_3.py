"""Wells, Problem 3.3 — the hyperbola parameter C used as a coordinate: (x, C) with y = C/x, Y vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Simulation

x, C = coordinates("x C")
m, g = parameters("m g")

system = System([x, C], bodies=[Particle(m, (x, C / x), name="particle")], forces=-m * g * delta(C / x),
                name="particle in (x, C) coordinates")

PROBLEM = Problem(
    id="p3.3",
    title="Particle in coordinates (x, C), y = C/x: T and generalized forces",
    chapter=3,
    source="Wells, Problem 3.3",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (x.diff(t) ** 2 + ((x * C.diff(t) - C * x.diff(t)) / x**2) ** 2)),
        GeneralizedForces({x: m * g * C / x**2, C: -m * g / x}),
    ],
    simulation=Simulation(params={m: 1, g: 9.81}, initial={x: 1.0, C: 1.0, x.diff(t): 0.5, C.diff(t): 0},
                          t_end=0.3),
)
