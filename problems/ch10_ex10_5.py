"""Wells, Example 10.5 — fundamental determinant |a ω² − c| of the double pendulum (Fig. 10-1(b))."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th, ph = coordinates("theta phi")
m1, m2, r1, r2, g = parameters("m1 m2 r1 r2 g")
w = sp.Symbol("omega", positive=True)

X1, Y1 = r1 * sp.sin(th), -r1 * sp.cos(th)
X2, Y2 = X1 + r2 * sp.sin(ph), Y1 - r2 * sp.cos(ph)
system = System(
    [th, ph],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    V=m1 * g * Y1 + m2 * g * Y2,
    name="double pendulum",
)

BOOK_D = sp.Matrix([
    [(m1 + m2) * r1**2 * w**2 - (m1 + m2) * g * r1, m2 * r1 * r2 * w**2],
    [m2 * r1 * r2 * w**2, m2 * r2**2 * w**2 - m2 * g * r2],
]).det()

PROBLEM = Problem(
    id="ex10.5",
    title="Double pendulum: fundamental determinant |a ω² − c| = 0",
    chapter=10,
    source="Wells, Example 10.5 (Fig. 10-1(b)), eq. (10.10)",
    system=system,
    answers=[
        Quantity("|a ω² − c|", lambda s: linearize(s, about={th: 0, ph: 0}).frequency_equation(w), BOOK_D,
                 description="frequency determinant (10.10)"),
    ],
    simulation=Simulation(params={m1: 1.0, m2: 0.5, r1: 1.0, r2: 0.8, g: 9.8},
                          initial={th: 0.2, ph: -0.1, th.diff(t): 0.0, ph.diff(t): 0.0}, t_end=10.0),
    correction="OCR prints the (1,1) element as (m1+m2)r1²ω² − (m1+m2)g; the r1 is missing (dimensions: every "
               "element of row 1 must carry r1, c11 = (m1+m2) g r1). Corrected element used.",
)
