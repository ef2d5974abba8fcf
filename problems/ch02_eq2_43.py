"""Wells, eqs. (2.18), (2.43) — four masses on the Fig. 2-9 pulleys (pulley masses neglected), T in (y1, y2)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, MassMatrix, Problem, Simulation

y1, y2 = coordinates("y1 y2")
m1, m2, m3, m4, C1, C2 = parameters("m1 m2 m3 m4 C1 C2")

# Constraints y1 + y3 = C1 and (y3 − y4) + (y3 − y2) = C2 eliminate y3, y4.
y3 = C1 - y1
y4 = 2 * y3 - y2 - C2
system = System(
    [y1, y2],
    bodies=[Particle(m1, (y1,)), Particle(m2, (y2,)), Particle(m3, (y3,)), Particle(m4, (y4,))],
    name="four masses on pulleys",
)

PROBLEM = Problem(
    id="eq2.43",
    title="Four-mass pulley system (Fig. 2-9): T after eliminating y3, y4",
    chapter=2,
    source="Wells, Sec. 2.9, eqs. (2.18), (2.43)",
    system=system,
    answers=[
        KineticEnergy(
            sp.Rational(1, 2) * (m1 + m3 + 4 * m4) * y1.diff(t) ** 2
            + sp.Rational(1, 2) * (m2 + m4) * y2.diff(t) ** 2
            + 2 * m4 * y1.diff(t) * y2.diff(t)
        ),
        MassMatrix(sp.Matrix([[m1 + m3 + 4 * m4, 2 * m4], [2 * m4, m2 + m4]])),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 2, m3: 1.5, m4: 0.5},
        initial={y1: 0, y2: 0, y1.diff(t): 1.0, y2.diff(t): -0.5},
        t_end=1.0,
    ),
    correction="MassMatrix is M = ∂²T/∂q̇∂q̇ read off the book's T. Only T is given (gravity enters in "
    "Sec. 2.14, see sec2.14); the simulation is force-free.",
)
