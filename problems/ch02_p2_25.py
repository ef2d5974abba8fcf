"""Wells, Problem 2.25 — spring pendulum in a railway car running on a circular track."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

r, theta = coordinates("r theta")
m, R, omega, alpha, C = parameters("m R omega alpha C")

X = R * sp.cos(omega * t) + r * sp.sin(theta) * sp.cos(omega * t + alpha)
Y = R * sp.sin(omega * t) + r * sp.sin(theta) * sp.sin(omega * t + alpha)
Z = C - r * sp.cos(theta)
system = System([r, theta], bodies=[Particle(m, (X, Y, Z))], name="spring pendulum in a car on a curve")

PROBLEM = Problem(
    id="p2.25",
    title="Spring pendulum in a railway car on a circular track: T = ½m(ẋ²+ẏ²+ż²)",
    chapter=2,
    source="Wells, Problem 2.25",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (sp.diff(X, t) ** 2 + sp.diff(Y, t) ** 2 + sp.diff(Z, t) ** 2)),
    ],
    simulation=Simulation(
        params={m: 1, R: 10, omega: 0.5, alpha: 0.3},
        initial={r: 1.0, theta: 0.3, r.diff(t): 0, theta.diff(t): 0},
        t_end=1.0,
    ),
    correction="The book's answer is T = ½m(ẋ²+ẏ²+ż²) with the printed x, y, z (r, θ variable); the expected "
    "value differentiates exactly those expressions. No forces are given: the simulation is force-free.",
)
