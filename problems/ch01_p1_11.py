"""Wells, Problem 1.11 — rotating axes (constant ω) whose origin has constant acceleration a_x along X1."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Simulation

x2, y2 = coordinates("x2 y2")
m, omega, a_x = parameters("m omega a_x")
F_x2, F_y2 = parameters("F_x2 F_y2", real=True)

c, s = sp.cos(omega * t), sp.sin(omega * t)
X1 = sp.Rational(1, 2) * a_x * t**2 + x2 * c - y2 * s
Y1 = x2 * s + y2 * c
# F_x2, F_y2: applied-force components along the rotating axes, which are the generalized forces.
system = System(
    [x2, y2],
    bodies=[Particle(m, (X1, Y1))],
    forces={x2: F_x2, y2: F_y2},
    name="particle in rotating, accelerating axes",
)

PROBLEM = Problem(
    id="p1.11",
    title="Rotating axes with an accelerating origin: Coriolis, centrifugal and a_x terms",
    chapter=1,
    source="Wells, Problem 1.11",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (sp.diff(X1, t) ** 2 + sp.diff(Y1, t) ** 2)),
        EquationsOfMotion(
            [
                sp.Eq(F_x2, m * x2.diff(t, 2) - m * x2 * omega**2 - 2 * m * omega * y2.diff(t) + m * a_x * c),
                sp.Eq(F_y2, m * y2.diff(t, 2) - m * y2 * omega**2 + 2 * m * omega * x2.diff(t) - m * a_x * s),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1, omega: 1.0, a_x: 0.5, F_x2: 0.0, F_y2: 0.0},
        initial={x2: 1.0, y2: 0, x2.diff(t): 0, y2.diff(t): 0.5},
        t_end=5.0,
    ),
    ranges={"F_x2": (-2, 2), "F_y2": (-2, 2)},
    correction="KineticEnergy is T = (m/2)(Ẋ1² + Ẏ1²) of the problem's transformation equations (2.37); the "
    "book's answer is the pair of force equations.",
)
