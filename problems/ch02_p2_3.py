"""Wells, Problem 2.3(a) — parabola-family coordinates (x, b) with y = b x²."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

x, b = coordinates("x b")
m = parameters("m")

system = System([x, b], bodies=[Particle(m, (x, b * x**2))], name="particle in parabola coordinates")

PROBLEM = Problem(
    id="p2.3",
    title="Particle in coordinates (x, b), y = b x^2: kinetic energy",
    chapter=2,
    source="Wells, Problem 2.3(a)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (x.diff(t) ** 2 + (b.diff(t) * x**2 + 2 * b * x * x.diff(t)) ** 2)),
    ],
    simulation=Simulation(params={m: 1}, initial={x: 1.0, b: 0.5, x.diff(t): 0.2, b.diff(t): 0.1}, t_end=1.0),
    correction="Part (b) (T in (b, θ)) has no printed final form and is not included.",
)
