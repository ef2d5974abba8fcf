"""Wells, Example 6.1 — particle sliding on a rough incline (angle α), dry friction by a power function."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

x, y = coordinates("x y")
m, g, mu, alpha = parameters("m g mu alpha")
speed = sp.sqrt(x.diff(t) ** 2 + y.diff(t) ** 2)

# y up the slope; gravity through V; friction μ m g cosα opposite to the velocity through Wells' P.
system = System(
    [x, y],
    bodies=[Particle(m, (x, y))],
    V=m * g * sp.sin(alpha) * y,
    P=-mu * m * g * sp.cos(alpha) * speed,
    name="particle on a rough incline",
)

PROBLEM = Problem(
    id="ex6.1",
    title="Particle sliding on a rough incline: Coulomb friction through P",
    chapter=6,
    source="Wells, Example 6.1 (and Prob. 6.21 for the P form)",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq(m * x.diff(t, 2), -mu * m * g * sp.cos(alpha) * x.diff(t) / speed),
                sp.Eq(m * y.diff(t, 2), -mu * m * g * sp.cos(alpha) * y.diff(t) / speed - m * g * sp.sin(alpha)),
            ],
            per_equation=True,
        ),
        GeneralizedForces(
            {
                x: -mu * m * g * sp.cos(alpha) * x.diff(t) / speed,
                y: -mu * m * g * sp.cos(alpha) * y.diff(t) / speed,
            }
        ),
    ],
    simulation=Simulation(
        params={m: 1, g: 9.81, mu: 0.3, alpha: 0.4},
        initial={x: 0, y: 0, x.diff(t): 1.0, y.diff(t): 2.0},
        t_end=1.0,
    ),
    ranges={"alpha": (0.1, 1.2)},
)
