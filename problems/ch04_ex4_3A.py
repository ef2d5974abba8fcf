"""Wells, Example 4.3A — dumbbell (m1, m2, rod l) in a vertical plane, coordinates (x1, y1, θ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x1, y1, theta = coordinates("x1 y1 theta")
m1, m2, l, g = parameters("m1 m2 l g")

x2, y2 = x1 + l * sp.cos(theta), y1 + l * sp.sin(theta)
system = System(
    [x1, y1, theta],
    bodies=[Particle(m1, (x1, y1), name="m1"), Particle(m2, (x2, y2), name="m2")],
    forces=-m1 * g * delta(y1) - m2 * g * delta(y2),
    name="dumbbell in (x1, y1, theta)",
)

xd, yd, thd = x1.diff(t), y1.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="ex4.3A",
    title="Dumbbell with gravity in the coordinates (x1, y1, theta)",
    chapter=4,
    source="Wells, Example 4.3A",
    system=system,
    answers=[
        KineticEnergy((m1 + m2) / 2 * (xd**2 + yd**2)
                      + m2 / 2 * (l**2 * thd**2 - 2 * l * xd * thd * sp.sin(theta) + 2 * l * yd * thd * sp.cos(theta))),
        GeneralizedForces({x1: 0, y1: -(m1 + m2) * g, theta: -m2 * g * l * sp.cos(theta)}),
        EquationsOfMotion([
            sp.Eq((m1 + m2) * x1.diff(t, 2) - m2 * l * theta.diff(t, 2) * sp.sin(theta) - m2 * l * thd**2 * sp.cos(theta), 0),
            sp.Eq((m1 + m2) * y1.diff(t, 2) + m2 * l * theta.diff(t, 2) * sp.cos(theta) - m2 * l * thd**2 * sp.sin(theta),
                  -(m1 + m2) * g),
            sp.Eq(m2 * (l**2 * theta.diff(t, 2) - l * x1.diff(t, 2) * sp.sin(theta) + l * y1.diff(t, 2) * sp.cos(theta)),
                  -m2 * g * l * sp.cos(theta)),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, l: 1, g: 9.81},
                          initial={x1: 0, y1: 0, theta: 0.3, x1.diff(t): 1, y1.diff(t): 3, theta.diff(t): 2}, t_end=1),
)
