"""Wells, Problem 3.2 — bead on the hyperbola xy = C, Y vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x = coordinates("x")
m, g, C = parameters("m g C")

system = System([x], bodies=[Particle(m, (x, C / x), name="bead")], forces=-m * g * delta(C / x),
                name="bead on a hyperbola")

PROBLEM = Problem(
    id="p3.2",
    title="Bead on the hyperbola xy = C, Y vertical",
    chapter=3,
    source="Wells, Problem 3.2",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * x.diff(t) ** 2 * (1 + C**2 / x**4)),
        GeneralizedForces({x: m * g * C / x**2}),
        # Derived in the catalog from the book's T and F_x (the book prints T and F_x only).
        EquationsOfMotion(
            [sp.Eq(m * x.diff(t, 2) * (1 + C**2 / x**4) - 2 * m * C**2 * x.diff(t) ** 2 / x**5, m * g * C / x**2)],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, C: 1}, initial={x: 1.0, x.diff(t): 0.5}, t_end=0.5),
    correction="Book gives T and F_x; the equation of motion is derived in the catalog from them (not printed).",
)
