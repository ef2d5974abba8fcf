"""Wells, Problem 3.1 — projectile in oblique axes q1, q2 (at angles α, β to X), Y vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

q1, q2 = coordinates("q1 q2")
m, g, alpha, beta = parameters("m g alpha beta")

X = q1 * sp.cos(alpha) + q2 * sp.cos(beta)
Y = q1 * sp.sin(alpha) + q2 * sp.sin(beta)
system = System([q1, q2], bodies=[Particle(m, (X, Y), name="projectile")], forces=-m * g * delta(Y),
                name="projectile in oblique axes")

PROBLEM = Problem(
    id="p3.1",
    title="Projectile in oblique coordinates",
    chapter=3,
    source="Wells, Problem 3.1",
    system=system,
    answers=[
        GeneralizedForces({q1: -m * g * sp.sin(alpha), q2: -m * g * sp.sin(beta)}),
        EquationsOfMotion(
            [
                sp.Eq(m * (q1.diff(t, 2) + q2.diff(t, 2) * sp.cos(beta - alpha)), -m * g * sp.sin(alpha)),
                sp.Eq(m * (q2.diff(t, 2) + q1.diff(t, 2) * sp.cos(beta - alpha)), -m * g * sp.sin(beta)),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, alpha: 0.3, beta: 1.2},
                          initial={q1: 0, q2: 0, q1.diff(t): 2.0, q2.diff(t): 5.0}, t_end=1.0),
    ranges={"alpha": (0.1, 0.6), "beta": (0.9, 1.5)},
)
