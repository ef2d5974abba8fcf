"""Wells, Example 17.6 — spring pendulum (Ex. 16.2) equations of motion from Hamilton's principle (17.9)."""

import sympy as sp

from lagrange import Particle, System, coordinates, euler_lagrange, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

r, th = coordinates("r theta")
m, g, k, r0 = parameters("m g k r_0")

system = System([r, th], bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2, name="spring pendulum")

book = [
    m * r.diff(t, 2) - m * r * th.diff(t) ** 2 - m * g * sp.cos(th) + k * (r - r0),
    m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t) + m * g * r * sp.sin(th),
]

PROBLEM = Problem(
    id="ex17.6",
    title="Spring pendulum by Hamilton's principle: integrating delta L by parts gives Lagrange's equations",
    chapter=17,
    source="Wells, Example 17.6",
    system=system,
    answers=[
        # d/dt dL/dqdot - dL/dq (Wells) = -(euler_lagrange's dL/dq - d/dt dL/dqdot)
        Quantity("Euler-Lagrange equations of the action",
                 lambda s: [-e.lhs for e in euler_lagrange(s.T - s.V, s.coordinates, t)], book),
        EquationsOfMotion([sp.Eq(e, 0) for e in book], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1},
                          initial={r: 1.2, th: 0.5, r.diff(t): 0, th.diff(t): 0}, t_end=5),
)
