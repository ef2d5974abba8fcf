"""Wells, Problem 2.7 — axes fixed in a car on a circular track of radius R with tangential acceleration a."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation

x2, y2, z2 = coordinates("x2 y2 z2")
m, R, omega, a = parameters("m R omega a")
F_x2, F_y2, F_z2 = parameters("F_x2 F_y2 F_z2", real=True)

beta = omega * t + a * t**2 / (2 * R)
X1 = (R + x2) * sp.cos(beta) - y2 * sp.sin(beta)
Y1 = (R + x2) * sp.sin(beta) + y2 * sp.cos(beta)
# F_x2, F_y2, F_z2: applied-force components along the car axes (= the generalized forces).
system = System(
    [x2, y2, z2],
    bodies=[Particle(m, (X1, Y1, z2))],
    forces={x2: F_x2, y2: F_y2, z2: F_z2},
    name="particle in a car on a circular track",
)

W = omega + a * t / R
PROBLEM = Problem(
    id="p2.7",
    title="Car on a circular track with tangential acceleration a: equations in car axes",
    chapter=2,
    source="Wells, Problem 2.7 (answer key)",
    system=system,
    answers=[
        EquationsOfMotion([
            sp.Eq(m * x2.diff(t, 2) - 2 * m * y2.diff(t) * W - m * y2 * a / R - m * (R + x2) * W**2, F_x2),
            sp.Eq(m * y2.diff(t, 2) + 2 * m * x2.diff(t) * W + m * (R + x2) * a / R - m * y2 * W**2, F_y2),
            sp.Eq(m * z2.diff(t, 2), F_z2),
        ], per_equation=True),
    ],
    simulation=Simulation(
        params={m: 1, R: 10, omega: 0.5, a: 0.2, F_x2: 0, F_y2: 0, F_z2: 0},
        initial={x2: 0, y2: 0, z2: 0, x2.diff(t): 0, y2.diff(t): 0, z2.diff(t): 0},
        t_end=2.0,
    ),
    ranges={"F_x2": (-2, 2), "F_y2": (-2, 2), "F_z2": (-2, 2)},
    correction="The key prints −m(R+x2)(ω+at/R)² in the y2 equation; the correct term is −m y2(ω+at/R)² "
    "(catalog: sym ✓ re-derived; the centrifugal term along y2 must be proportional to y2, as in Ex. 1.2).",
)
