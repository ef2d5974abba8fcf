"""Wells, Problem 4.1 — the Fig. 4-1 pulley system with the upper pulley hung on a spring k."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

y1, y2, l = coordinates("y1 y2 l")
m1, m2, m3, g, k, C, h0 = parameters("m1 m2 m3 g k C h0")

# Heights (Y up): the upper pulley is at l; the spring above it has length h = C − l (free length h0).
Y1, Y2, Y3 = l - y1, l + y1 - y2, l + y1 + y2
system = System(
    [y1, y2, l],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    forces=-k * ((C - l) - h0) * delta(C - l) - g * (m1 * delta(Y1) + m2 * delta(Y2) + m3 * delta(Y3)),
    name="Fig. 4-1 pulleys hung on a spring",
)

Fl = k * (C - l - h0) - (m1 + m2 + m3) * g
PROBLEM = Problem(
    id="p4.1",
    title="Pulley system hung on a spring: T and generalized forces",
    chapter=4,
    source="Wells, Problem 4.1",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (m1 * (l.diff(t) - y1.diff(t)) ** 2 + m2 * (l.diff(t) + y1.diff(t) - y2.diff(t)) ** 2
                                            + m3 * (l.diff(t) + y1.diff(t) + y2.diff(t)) ** 2)),
        GeneralizedForces({y1: (m1 - m2 - m3) * g, y2: (m2 - m3) * g, l: Fl}),
        # Derived in the catalog: Ex. 4.7's equations with a -> l'', plus the l equation.
        EquationsOfMotion([
            sp.Eq((m1 + m2 + m3) * y1.diff(t, 2) + (m3 - m2) * y2.diff(t, 2) + (m2 + m3 - m1) * l.diff(t, 2),
                  (m1 - m2 - m3) * g),
            sp.Eq((m3 - m2) * y1.diff(t, 2) + (m2 + m3) * y2.diff(t, 2) + (m3 - m2) * l.diff(t, 2), (m2 - m3) * g),
            sp.Eq((m1 + m2 + m3) * l.diff(t, 2) + (m2 + m3 - m1) * y1.diff(t, 2) + (m3 - m2) * y2.diff(t, 2), Fl),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m1: 3, m2: 1, m3: 1.5, g: 9.81, k: 100, C: 2, h0: 1},
                          initial={y1: 0, y2: 0, l: 0.5, y1.diff(t): 0, y2.diff(t): 0, l.diff(t): 0}, t_end=1),
    correction="The book prints T and the F_q; the equations of motion are derived in the catalog from them.",
)
