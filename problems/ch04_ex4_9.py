"""Wells, Example 4.9 — the Fig. 4-1 system with s2 prescribed, s2 = s0 + A sin ωt (one degree of freedom)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

y1, s2 = coordinates("y1 s2")
m1, m2, m3, g, s0, A, w = parameters("m1 m2 m3 g s0 A omega")

s2_t = s0 + A * sp.sin(w * t)
# Heights (Y up), coordinates (y1, s2) of Example 4.1: s3 = 2 y1 − s2.
Y1, Y2, Y3 = -y1, s2, 2 * y1 - s2
# Virtual work with t frozen: the driven mass m2 does no virtual work (δs2 = 0), so δW is written with the
# prescribed s2(t) already in place.
frozen = {s2: s2_t}
system = System(
    [y1],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    forces=-g * (m1 * delta(Y1) + m2 * delta(Y2.subs(frozen)) + m3 * delta(Y3.subs(frozen))),
    prescribed={s2: s2_t},
    name="Fig. 4-1 with m2 driven",
)

PROBLEM = Problem(
    id="ex4.9",
    title="Pulley system with one mass driven sinusoidally: a single-DOF forced equation",
    chapter=4,
    source="Wells, Example 4.9",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m1 * y1.diff(t) ** 2 + sp.Rational(1, 2) * m2 * A**2 * w**2 * sp.cos(w * t) ** 2
                      + sp.Rational(1, 2) * m3 * (2 * y1.diff(t) - A * w * sp.cos(w * t)) ** 2),
        GeneralizedForces({y1: (m1 - 2 * m3) * g}),
        EquationsOfMotion([sp.Eq((m1 + 4 * m3) * y1.diff(t, 2) + 2 * m3 * A * w**2 * sp.sin(w * t), (m1 - 2 * m3) * g)],
                          per_equation=True),
    ],
    simulation=Simulation(params={m1: 3, m2: 1, m3: 1, g: 9.81, A: 0.1, w: 5},
                          initial={y1: 0, y1.diff(t): 0}, t_end=2),
)
