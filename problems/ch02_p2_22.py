"""Wells, Problem 2.22 — three masses in a vertical line: CM height and two separations."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

y1, y2, y3 = coordinates("y1 y2 y3")
m1, m2, m3 = parameters("m1 m2 m3")
M = m1 + m2 + m3

# Heights u1, u2 = u1 + y2, u3 = u2 + y3 with the CM at y1 (coordinate meanings inferred, see correction).
u1 = y1 - (m2 * y2 + m3 * (y2 + y3)) / M
u2 = u1 + y2
u3 = u2 + y3
system = System(
    [y1, y2, y3],
    bodies=[Particle(m1, (u1,)), Particle(m2, (u2,)), Particle(m3, (u3,))],
    name="three masses in a vertical line",
)

PROBLEM = Problem(
    id="p2.22",
    title="Three masses in a vertical line: T in CM height and separations",
    chapter=2,
    source="Wells, Problem 2.22 (answer key)",
    system=system,
    answers=[
        KineticEnergy(
            sp.Rational(1, 2) * M * y1.diff(t) ** 2
            + m1 * m3 / (2 * M) * (y2.diff(t) + y3.diff(t)) ** 2
            + m2 / (2 * M) * (m1 * y2.diff(t) ** 2 + m3 * y3.diff(t) ** 2)
        ),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 2, m3: 3},
        initial={y1: 0, y2: 1, y3: 1, y1.diff(t): 0.5, y2.diff(t): 0.1, y3.diff(t): -0.2},
        t_end=1.0,
    ),
    correction="Coordinate meanings inferred (figure not available): y1 = CM height, y2 = m1–m2 separation, "
    "y3 = m2–m3 separation. M = m1 + m2 + m3. The springs of the figure do not enter T and are not modelled.",
)
