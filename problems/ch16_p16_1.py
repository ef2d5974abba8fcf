"""Wells, Problem 16.1 — mass on a spring: H = p^2/2m + kx^2/2."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x = coordinates("x")
m, k = parameters("m k")
xs, px = sp.Symbol("x", real=True), sp.Symbol("p_x", real=True)

system = System([x], bodies=[Particle(m, (x,))], V=k * x**2 / 2, name="spring-mass")

PROBLEM = Problem(
    id="p16.1",
    title="Spring-mass: H = p_x^2/2m + kx^2/2",
    chapter=16,
    source="Wells, Problem 16.1",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H, px**2 / (2 * m) + k * xs**2 / 2),
        Quantity("canonical equations (xdot, pdot)", lambda s: [*hamiltonian(s).qdot, *hamiltonian(s).pdot],
                 [px / m, -k * xs]),
    ],
    simulation=Simulation(params={m: 1, k: 4}, initial={x: 1, x.diff(t): 0}, t_end=5),
)
