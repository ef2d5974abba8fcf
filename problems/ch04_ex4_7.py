"""Wells, Example 4.7 — the Fig. 4-1 pulley system with its support accelerating upward at a."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Simulation

y1, y2 = coordinates("y1 y2")
m1, m2, m3, g, a = parameters("m1 m2 m3 g a")

# Heights (Y up): the support is at a t²/2; the rest as in Example 4.1.
h = a * t**2 / 2
Y1, Y2, Y3 = h - y1, h + y1 - y2, h + y1 + y2
system = System(
    [y1, y2],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    forces=-g * (m1 * delta(Y1) + m2 * delta(Y2) + m3 * delta(Y3)),
    name="Fig. 4-1 pulleys on an accelerating support",
)

PROBLEM = Problem(
    id="ex4.7",
    title="Pulley system on a support accelerating upward: equivalent to g -> g + a",
    chapter=4,
    source="Wells, Example 4.7",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (m1 * (a * t - y1.diff(t)) ** 2 + m2 * (a * t + y1.diff(t) - y2.diff(t)) ** 2
                                            + m3 * (a * t + y1.diff(t) + y2.diff(t)) ** 2)),
        EquationsOfMotion([
            sp.Eq((m1 + m2 + m3) * y1.diff(t, 2) + (m3 - m2) * y2.diff(t, 2) + (m2 + m3 - m1) * a, (m1 - m2 - m3) * g),
            sp.Eq((m3 - m2) * y1.diff(t, 2) + (m2 + m3) * y2.diff(t, 2) + (m3 - m2) * a, (m2 - m3) * g),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m1: 3, m2: 1, m3: 1.5, g: 9.81, a: 2},
                          initial={y1: 0, y2: 0, y1.diff(t): 0, y2.diff(t): 0}, t_end=1),
)
