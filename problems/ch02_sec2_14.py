"""Wells, Sec. 2.14(ii), eqs. (2.66)-(2.68) — virtual work of gravity on the Fig. 2-9 pulley system."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

s1, y2 = coordinates("s1 y2")
m1, m2, m3, m4, g = parameters("m1 m2 m3 m4 g")

# s1: m1 downward; y2: m2 upward. Constraints of the text: δs3 = −δs1 (m3, measured downward),
# δy4 = 2δs1 − δy2 (m4, upward). Heights of the four masses:
h1 = -s1
h2 = y2
h3 = s1
h4 = 2 * s1 - y2
system = System(
    [s1, y2],
    bodies=[Particle(m1, (h1,)), Particle(m2, (h2,)), Particle(m3, (h3,)), Particle(m4, (h4,))],
    forces=-g * (m1 * delta(h1) + m2 * delta(h2) + m3 * delta(h3) + m4 * delta(h4)),
    name="Fig. 2-9 pulleys under gravity",
)

F_s1 = (m1 - m3 - 2 * m4) * g
F_y2 = (m4 - m2) * g
PROBLEM = Problem(
    id="sec2.14",
    title="Fig. 2-9 pulleys: δW = (m1 g − m3 g − 2 m4 g)δs1 + (m4 g − m2 g)δy2",
    chapter=2,
    source="Wells, Sec. 2.14(ii), eqs. (2.66)-(2.68); T as in (2.43)",
    system=system,
    answers=[
        GeneralizedForces({s1: F_s1, y2: F_y2}, which="applied"),
        KineticEnergy(
            sp.Rational(1, 2) * (m1 + m3 + 4 * m4) * s1.diff(t) ** 2
            + sp.Rational(1, 2) * (m2 + m4) * y2.diff(t) ** 2
            - 2 * m4 * s1.diff(t) * y2.diff(t)
        ),
        EquationsOfMotion(
            [
                sp.Eq((m1 + m3 + 4 * m4) * s1.diff(t, 2) - 2 * m4 * y2.diff(t, 2), F_s1),
                sp.Eq((m2 + m4) * y2.diff(t, 2) - 2 * m4 * s1.diff(t, 2), F_y2),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m1: 2, m2: 1, m3: 1, m4: 0.5, g: 9.81},
        initial={s1: 0, y2: 0, s1.diff(t): 0, y2.diff(t): 0},
        t_end=1.0,
    ),
    correction="Only gravity is entered: the rope tensions and the pulley rotations θ1, θ2 of the text are not "
    "modelled (figure not available), so the cancellation of the τ terms is not tested here. T is (2.43) with "
    "y1 → −s1 (s1 downward); the equations of motion are T of (2.43) with the book's F_s1, F_y2 (Lagrange's "
    "equations applied by hand to the book's T and δW, not printed in the book).",
)
