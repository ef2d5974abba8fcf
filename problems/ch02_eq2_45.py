"""Wells, eq. (2.45) — particle in a translating frame with constant acceleration."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EnergySplit, KineticEnergy, Problem, Simulation

x2, y2, z2 = coordinates("x2 y2 z2")
m, v_x, v_y, v_z, a_x, a_y, a_z = parameters("m v_x v_y v_z a_x a_y a_z")
half = sp.Rational(1, 2)

system = System(
    [x2, y2, z2],
    bodies=[Particle(m, (x2 + v_x * t + half * a_x * t**2,
                         y2 + v_y * t + half * a_y * t**2,
                         z2 + v_z * t + half * a_z * t**2))],
    name="particle in a uniformly accelerating frame",
)

ux, uy, uz = v_x + a_x * t, v_y + a_y * t, v_z + a_z * t
PROBLEM = Problem(
    id="eq2.45",
    title="Particle in a translating frame with constant acceleration: T",
    chapter=2,
    source="Wells, Sec. 2.9, eq. (2.45)",
    system=system,
    answers=[
        KineticEnergy(half * m * ((ux + x2.diff(t)) ** 2 + (uy + y2.diff(t)) ** 2 + (uz + z2.diff(t)) ** 2)),
        EnergySplit(B=[m * ux, m * uy, m * uz], C=half * m * (ux**2 + uy**2 + uz**2)),
    ],
    simulation=Simulation(
        params={m: 1, v_x: 1, v_y: 0.5, v_z: 0.2, a_x: 1, a_y: 2, a_z: 0.3},
        initial={x2: 0, y2: 0, z2: 0, x2.diff(t): 1, y2.diff(t): 0, z2.diff(t): 0},
        t_end=1.0,
    ),
    correction="EnergySplit: B and C of (2.55) read off the expanded book T (the linear and velocity-free parts).",
)
