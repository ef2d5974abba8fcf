"""Wells, Problem 4.26 — double pendulum: accelerations of each particle along the θ line, (4.16)–(4.21)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import Problem, Quantity

theta, phi = coordinates("theta phi")
m1, m2, r1, r2, g = parameters("m1 m2 r1 r2 g")

X1, Y1 = r1 * sp.sin(theta), r1 * sp.cos(theta)  # Y downward
X2, Y2 = X1 + r2 * sp.sin(phi), Y1 + r2 * sp.cos(phi)
system = System(
    [theta, phi],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    forces=m1 * g * delta(Y1) + m2 * g * delta(Y2),
    name="double pendulum",
)


def _h(p, q):
    qs = sp.Dummy("q")
    return sp.sqrt(sp.trigsimp(sum(sp.diff(comp.subs(q, qs), qs) ** 2 for comp in p.position))).subs(qs, q)


def h_values(s):
    p1, p2 = s.bodies
    return [_h(p1, theta), _h(p2, theta), _h(p1, phi), _h(p2, phi)]


def a_theta(s):
    """(4.21): m_i a_iθ = [d/dt ∂T_i/∂θ̇ − ∂T_i/∂θ] / h_iθ, T_i from each particle alone (unit mass)."""
    out = []
    for p in s.bodies:
        single = System(list(s.coordinates), bodies=[Particle(1, tuple(p.position))])
        eq = single.equations()[0]
        out.append(sp.simplify((eq.lhs - eq.rhs) / _h(p, theta)))
    return out


def f_theta(s):
    """(4.18): f_iθ = (F_i · ∂r_i/∂θ) / h_iθ with the weights F_i = (0, m_i g)."""
    out = []
    for p in s.bodies:
        F = sp.Matrix([0, p.mass * g, 0])
        out.append(sp.simplify((F.T * p.position.diff(theta))[0, 0] / _h(p, theta)))
    return out


PROBLEM = Problem(
    id="p4.26",
    title="Double pendulum: h, a and f along the theta coordinate line for each particle",
    chapter=4,
    source="Wells, Problem 4.26",
    system=system,
    answers=[
        Quantity("h_1theta, h_2theta, h_1phi, h_2phi", h_values, [r1, r1, 0, r2]),
        Quantity("a_1theta, a_2theta", a_theta, [
            r1 * theta.diff(t, 2),
            r1 * theta.diff(t, 2) + r2 * phi.diff(t, 2) * sp.cos(phi - theta) - r2 * phi.diff(t) ** 2 * sp.sin(phi - theta),
        ]),
        Quantity("f_1theta, f_2theta", f_theta, [-m1 * g * sp.sin(theta), -m2 * g * sp.sin(theta)]),
    ],
)
