"""Wells, Problem 10.1 — Example 10.3 (m1 on k1 from the ceiling, m2 on k2 below m1) plus a spring k3 from
m2 to the floor: frequency equation."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

y1, y2 = coordinates("y1 y2")  # down, from the static equilibrium
m1, m2, k1, k2, k3 = parameters("m1 m2 k1 k2 k3")
w = sp.Symbol("omega", positive=True)
system = System(
    [y1, y2],
    bodies=[Particle(m1, (y1,), name="m1"), Particle(m2, (y2,), name="m2")],
    V=sp.Rational(1, 2) * (k1 * y1**2 + k2 * (y2 - y1) ** 2 + k3 * y2**2),
    name="two masses, three springs (vertical)",
)

PROBLEM = Problem(
    id="p10.1",
    title="Two masses between ceiling and floor on three springs: frequency equation (derived)",
    chapter=10,
    source="Wells, Problem 10.1",
    system=system,
    answers=[
        Quantity("|a ω² − c|", lambda s: sp.expand(linearize(s).frequency_equation(w)),
                 m1 * m2 * w**4 - (m1 * (k2 + k3) + m2 * (k1 + k2)) * w**2 + (k1 * k2 + k1 * k3 + k2 * k3),
                 description="m1m2ω⁴ − [m1(k2+k3) + m2(k1+k2)]ω² + (k1k2 + k1k3 + k2k3) = 0"),
    ],
    simulation=Simulation(params={m1: 400.0, m2: 300.0, k1: 6e4, k2: 5e4, k3: 3e4},
                          initial={y1: 1.0, y2: 0.0, y1.diff(t): 0.0, y2.diff(t): 0.0}, t_end=2.0),
    correction="The book prints no answer (catalog: PARTIAL); the frequency equation is the catalog's derivation. "
               "Coordinates from static equilibrium, so gravity and preloads drop out as in Example 10.3.",
)
