"""Wells, Example 10.2 — approximate T, P and V (constant a, b, c matrices) of the damped double pendulum."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

th, ph = coordinates("theta phi")
m1, m2, r1, r2, g, b1, b2, x0, y0 = parameters("m1 m2 r1 r2 g b1 b2 x0 y0")

# Book's transformation equations, suspension point at (x0, y0), Y up.
X1, Y1 = x0 + r1 * sp.sin(th), y0 - r1 * sp.cos(th)
X2, Y2 = X1 + r2 * sp.sin(ph), Y1 - r2 * sp.cos(ph)
system = System(
    [th, ph],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    V=m1 * g * Y1 + m2 * g * Y2,
    P=-sp.Rational(1, 2) * (b1 * (X1.diff(t) ** 2 + Y1.diff(t) ** 2) + b2 * (X2.diff(t) ** 2 + Y2.diff(t) ** 2)),
    name="double pendulum with viscous drag",
)


def _lin(s):
    return linearize(s, about={th: 0, ph: 0})


PROBLEM = Problem(
    id="ex10.2",
    title="Double pendulum: approximate T, P, V about θ = φ = 0 (Wells' a_rl, b_rl, c_rl)",
    chapter=10,
    source="Wells, Example 10.2 (eqs. 10.4-10.6)",
    system=system,
    answers=[
        # T_approx = ½[(m1+m2) r1² θ'² + 2 m2 r1 r2 θ'φ' + m2 r2² φ'²]  ->  a matrix
        Quantity("a (T_approx)", lambda s: _lin(s).a,
                 sp.Matrix([[(m1 + m2) * r1**2, m2 * r1 * r2], [m2 * r1 * r2, m2 * r2**2]]),
                 description="a_rl from T_approx"),
        # P_approx = -½[(b1+b2) r1² θ'² + 2 b2 r1 r2 θ'φ' + b2 r2² φ'²]  ->  b matrix (Wells' P < 0)
        Quantity("b (P_approx)", lambda s: _lin(s).b,
                 sp.Matrix([[(b1 + b2) * r1**2, b2 * r1 * r2], [b2 * r1 * r2, b2 * r2**2]]),
                 description="b_rl from P_approx"),
        PotentialEnergy((m1 + m2) * g * r1 * (1 - sp.cos(th)) + m2 * g * r2 * (1 - sp.cos(ph))),
        # V_approx = ½[(m1+m2) g r1 θ² + m2 g r2 φ²]: c11 = (m1+m2) g r1, c12 = 0, c22 = m2 g r2
        Quantity("c (V_approx)", lambda s: _lin(s).c,
                 sp.Matrix([[(m1 + m2) * g * r1, 0], [0, m2 * g * r2]]), description="c_rl from V_approx"),
    ],
    simulation=Simulation(
        params={m1: 1.0, m2: 0.5, r1: 1.0, r2: 0.8, g: 9.8, b1: 0.3, b2: 0.2, y0: 0.0},
        initial={th: 0.2, ph: -0.1, th.diff(t): 0.0, ph.diff(t): 0.0},
        t_end=10.0,
    ),
)
