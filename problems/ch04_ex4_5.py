"""Wells, Example 4.5 — three masses in a vertical chain with springs k1 (m1–m2) and k2 (m2–m3); y is the CM."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

q2, q3, y = coordinates("q2 q3 y")
m1, m2, m3, k1, k2, l1, l2, g = parameters("m1 m2 m3 k1 k2 l1 l2 g")
M = m1 + m2 + m3

# Y up. y1 = y + q1, y2 = y − q2, y3 = y − q3 with the CM relation m1 q1 = m2 q2 + m3 q3 (q1 eliminated).
q1 = (m2 * q2 + m3 * q3) / m1
Y1, Y2, Y3 = y + q1, y - q2, y - q3
system = System(
    [q2, q3, y],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    forces=(-k1 * (Y1 - Y2 - l1) * delta(Y1 - Y2) - k2 * (Y2 - Y3 - l2) * delta(Y2 - Y3)
            - g * (m1 * delta(Y1) + m2 * delta(Y2) + m3 * delta(Y3))),
    name="three masses and two springs, CM coordinates",
)

br = (m1 + m2) / m1 * q2 + m3 / m1 * q3 - l1
Fq2 = -k1 * (m1 + m2) / m1 * br + k2 * (q3 - q2 - l2)
Fq3 = -k1 * m3 / m1 * br - k2 * (q3 - q2 - l2)
PROBLEM = Problem(
    id="ex4.5",
    title="Three masses and two springs in a vertical chain: CM and relative coordinates",
    chapter=4,
    source="Wells, Example 4.5 (Fig. 4-5)",
    system=system,
    answers=[
        KineticEnergy(M / 2 * y.diff(t) ** 2 + m1 / 2 * (m2 / m1 * q2.diff(t) + m3 / m1 * q3.diff(t)) ** 2
                      + m2 / 2 * q2.diff(t) ** 2 + m3 / 2 * q3.diff(t) ** 2),
        GeneralizedForces({q2: Fq2, q3: Fq3, y: -M * g}),
        EquationsOfMotion([
            sp.Eq(m2 / m1 * (m1 + m2) * q2.diff(t, 2) + m2 * m3 / m1 * q3.diff(t, 2), Fq2),
            sp.Eq(m2 * m3 / m1 * q2.diff(t, 2) + m3 * (m1 + m3) / m1 * q3.diff(t, 2), Fq3),
            sp.Eq(M * y.diff(t, 2), -M * g),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, m3: 1.5, k1: 20, k2: 30, l1: 1, l2: 1, g: 9.81},
                          initial={q2: 0.5, q3: 2.0, y: 0, q2.diff(t): 0, q3.diff(t): 0, y.diff(t): 0}, t_end=2),
    correction="The book prints m3(m1 + m2)/m1 for the q3'' coefficient of the q3 equation; T gives "
               "d/dt ∂T/∂q3' = (m3²/m1 + m3) q3'' + ..., i.e. m3(m1 + m3)/m1 (catalog, sym ✓).",
)
