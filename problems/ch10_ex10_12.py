"""Wells, Example 10.12 — triple pendulum of Example 10.6 in a viscous fluid: approximate power function."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th1, th2, th3 = coordinates("theta1 theta2 theta3")
m1, m2, m3, r1, r2, r3, g, b1, b2, b3 = parameters("m1 m2 m3 r1 r2 r3 g b1 b2 b3")

X1, Y1 = r1 * sp.sin(th1), -r1 * sp.cos(th1)
pts = [(X1, Y1), (X1 + r2 * sp.sin(th2), Y1 - r2 * sp.cos(th2)), (X1 + r3 * sp.sin(th3), Y1 - r3 * sp.cos(th3))]
system = System(
    [th1, th2, th3],
    bodies=[Particle(mi, p, name=f"m{i + 1}") for i, (mi, p) in enumerate(zip((m1, m2, m3), pts))],
    V=g * sum(mi * p[1] for mi, p in zip((m1, m2, m3), pts)),
    P=-sp.Rational(1, 2) * sum(bi * (p[0].diff(t) ** 2 + p[1].diff(t) ** 2) for bi, p in zip((b1, b2, b3), pts)),
    name="triple pendulum in a viscous fluid",
)
# P_approx = −½[(b1+b2+b3) r1² θ1'² + b2 r2² θ2'² + b3 r3² θ3'² + 2 b2 r1 r2 θ1'θ2' + 2 b3 r1 r3 θ1'θ3']
BOOK_B = sp.Matrix([[(b1 + b2 + b3) * r1**2, b2 * r1 * r2, b3 * r1 * r3],
                    [b2 * r1 * r2, b2 * r2**2, 0],
                    [b3 * r1 * r3, 0, b3 * r3**2]])

PROBLEM = Problem(
    id="ex10.12",
    title="Triple pendulum in a viscous fluid: P_approx (b matrix)",
    chapter=10,
    source="Wells, Example 10.12",
    system=system,
    answers=[Quantity("b (P_approx)", lambda s: linearize(s).b, BOOK_B, description="b_rl from P_approx")],
    simulation=Simulation(params={m1: 250, m2: 200, m3: 300, r1: 15, r2: 12, r3: 20, g: 980, b1: 20.0, b2: 15.0,
                                  b3: 25.0},
                          initial={th1: 0.05, th2: -0.05, th3: 0.08, th1.diff(t): 0.0, th2.diff(t): 0.0,
                                   th3.diff(t): 0.0}, t_end=3.0),
    units="CGS in the simulation",
    correction="OCR prints r1 instead of r1² in the first term of P (dimensions: every term must be b·length²·θ'²). "
               "Catalog marks the example PARTIAL (no numbers for b); only P_approx is checked.",
)
