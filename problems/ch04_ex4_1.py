"""Wells, Example 4.1 — three masses and two massless pulleys (Fig. 4-1), gravity, two coordinate choices."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

y1, y2, s2 = coordinates("y1 y2 s2")
m1, m2, m3, g = parameters("m1 m2 m3 g")

# Heights (Y up, constants dropped). m1 hangs on one side of the fixed pulley, y1 downward; the movable pulley
# on the other side rises by y1 and carries m2, m3 on its cord; y2 is m2's descent relative to that pulley.
Y1, Y2, Y3 = -y1, y1 - y2, y1 + y2
set_a = System(
    [y1, y2],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    forces=-g * (m1 * delta(Y1) + m2 * delta(Y2) + m3 * delta(Y3)),
    name="Fig. 4-1 pulleys in (y1, y2)",
)
# Alternative set (y1, s2), s2 the rise of m2, s3 = 2 y1 − s2 the rise of m3.
Z1, Z2, Z3 = -y1, s2, 2 * y1 - s2
set_b = System(
    [y1, s2],
    bodies=[Particle(m1, (0, Z1), name="m1"), Particle(m2, (0, Z2), name="m2"), Particle(m3, (0, Z3), name="m3")],
    forces=-g * (m1 * delta(Z1) + m2 * delta(Z2) + m3 * delta(Z3)),
    name="Fig. 4-1 pulleys in (y1, s2)",
)

PROBLEMS = [
    Problem(
        id="ex4.1",
        title="Three masses on two pulleys: T, F_q and equations in (y1, y2)",
        chapter=4,
        source="Wells, Example 4.1",
        system=set_a,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * (m1 * y1.diff(t) ** 2 + m2 * (y1.diff(t) - y2.diff(t)) ** 2
                                                + m3 * (y1.diff(t) + y2.diff(t)) ** 2)),
            GeneralizedForces({y1: (m1 - m2 - m3) * g, y2: (m2 - m3) * g}),
            EquationsOfMotion([
                sp.Eq((m1 + m2 + m3) * y1.diff(t, 2) + (m3 - m2) * y2.diff(t, 2), (m1 - m2 - m3) * g),
                sp.Eq((m2 + m3) * y2.diff(t, 2) + (m3 - m2) * y1.diff(t, 2), (m2 - m3) * g),
            ], per_equation=True),
            # Closed-form accelerations (derived in the catalog from the book's equations).
        ],
        simulation=Simulation(params={m1: 3, m2: 1, m3: 1.5, g: 9.81},
                              initial={y1: 0, y2: 0, y1.diff(t): 0, y2.diff(t): 0}, t_end=1),
    ),
    Problem(
        id="ex4.1-alt",
        title="Three masses on two pulleys in (y1, s2): F_y1 changes with the coordinate set",
        chapter=4,
        source="Wells, Example 4.1 (alternative coordinates)",
        system=set_b,
        answers=[
            GeneralizedForces({y1: (m1 - 2 * m3) * g, s2: (m3 - m2) * g}),
            EquationsOfMotion([
                sp.Eq((m1 + 4 * m3) * y1.diff(t, 2) - 2 * m3 * s2.diff(t, 2), (m1 - 2 * m3) * g),
                sp.Eq((m2 + m3) * s2.diff(t, 2) - 2 * m3 * y1.diff(t, 2), (m3 - m2) * g),
            ], per_equation=True),
        ],
        simulation=Simulation(params={m1: 3, m2: 1, m3: 1.5, g: 9.81},
                              initial={y1: 0, s2: 0, y1.diff(t): 0, s2.diff(t): 0}, t_end=1),
    ),
]
