"""Wells, Problem 1.6 — freely falling elevator: gravity cancels in the elevator frame."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation

x2, y2 = coordinates("x2 y2")
m, g, y0, v0 = parameters("m g y0 v0")
F_x, F_y = parameters("F_x F_y", real=True)

Y1 = y2 + y0 + v0 * t - sp.Rational(1, 2) * g * t**2  # elevator in free fall
system = System(
    [x2, y2],
    bodies=[Particle(m, (x2, Y1))],
    forces=F_x * delta(x2) + F_y * delta(Y1) - m * g * delta(Y1),
    name="particle in a freely falling elevator",
)

PROBLEM = Problem(
    id="p1.6",
    title="Freely falling elevator: m y2'' = F_y, gravity cancels",
    chapter=1,
    source="Wells, Problem 1.6",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(m * x2.diff(t, 2), F_x), sp.Eq(m * y2.diff(t, 2), F_y)], per_equation=True),
    ],
    simulation=Simulation(
        params={m: 1, g: 9.81, v0: 1.0, F_x: 0.0, F_y: 0.0},
        initial={x2: 0, y2: 0, x2.diff(t): 1.0, y2.diff(t): 0.5},
        t_end=2.0,
    ),
    ranges={"F_x": (-2, 2), "F_y": (-2, 2)},
    correction="The x2 equation (m x2'' = F_x) is the trivial companion of the book's y2 statement.",
)
