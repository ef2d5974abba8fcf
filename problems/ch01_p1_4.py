"""Wells, Problem 1.4 — a frame moving at constant velocity is inertial."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation

x2, y2, z2 = coordinates("x2 y2 z2")
m, v = parameters("m v")
F_x, F_y, F_z = parameters("F_x F_y F_z", real=True)

X1 = x2 + v * t
system = System(
    [x2, y2, z2],
    bodies=[Particle(m, (X1, y2, z2))],
    forces=F_x * delta(X1) + F_y * delta(y2) + F_z * delta(z2),
    name="particle in a uniformly moving frame",
)

PROBLEM = Problem(
    id="p1.4",
    title="Frame translating at constant velocity: the equations keep the inertial form",
    chapter=1,
    source="Wells, Problem 1.4",
    system=system,
    answers=[
        EquationsOfMotion(
            [sp.Eq(m * x2.diff(t, 2), F_x), sp.Eq(m * y2.diff(t, 2), F_y), sp.Eq(m * z2.diff(t, 2), F_z)],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1, v: 2.0, F_x: 1.0, F_y: 0.0, F_z: -1.0},
        initial={x2: 0, y2: 0, z2: 0, x2.diff(t): 0, y2.diff(t): 1, z2.diff(t): 0},
        t_end=2.0,
    ),
    ranges={"F_x": (-2, 2), "F_y": (-2, 2), "F_z": (-2, 2)},
)
