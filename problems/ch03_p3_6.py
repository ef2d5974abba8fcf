"""Wells, Problem 3.6 — Example 1.2 rederived by Lagrange: particle in axes rotating at constant ω."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

x2, y2 = coordinates("x2 y2")
m, w, Fx2, Fy2 = parameters("m omega F_x2 F_y2")

c, s = sp.cos(w * t), sp.sin(w * t)
p = Particle(m, (x2 * c - y2 * s, x2 * s + y2 * c), name="particle")
# Applied force with constant components F_x2, F_y2 along the rotating axes.
system = System([x2, y2], bodies=[p], forces=[Force(p, (Fx2 * c - Fy2 * s, Fx2 * s + Fy2 * c))],
                name="particle in rotating axes")

PROBLEM = Problem(
    id="p3.6",
    title="Particle in axes rotating at constant omega: Coriolis and centrifugal terms (Ex. 1.2 by Lagrange)",
    chapter=3,
    source="Wells, Problem 3.6 (answer of Example 1.2, eqs. 11-12)",
    system=system,
    answers=[
        GeneralizedForces({x2: Fx2, y2: Fy2}),
        EquationsOfMotion(
            [
                sp.Eq(Fx2, m * x2.diff(t, 2) - m * x2 * w**2 - 2 * m * w * y2.diff(t)),
                sp.Eq(Fy2, m * y2.diff(t, 2) - m * y2 * w**2 + 2 * m * w * x2.diff(t)),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, w: 1, Fx2: 0.0, Fy2: 0.0},
                          initial={x2: 1.0, y2: 0, x2.diff(t): 0, y2.diff(t): -1.0}, t_end=3),
)
