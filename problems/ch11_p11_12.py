"""Wells, Problem 11.12 — double arm (m1, m2 on rigid links r1, r2) hinged on a bar of inertia I turning about
O in a horizontal plane (Fig. 11-15): with β1 = φ1 − θ, β2 = φ2 − θ the angle θ is ignorable, and
β1 = β2 = 0 is a steady motion for any θ̇."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

theta, b1, b2 = coordinates("theta beta1 beta2")
I, m1, m2, s, r1, r2 = parameters("I m_1 m_2 s r_1 r_2")
p1, p2 = theta + b1, theta + b2
X1 = (s * sp.cos(theta) + r1 * sp.cos(p1), s * sp.sin(theta) + r1 * sp.sin(p1))
X2 = (X1[0] + r2 * sp.cos(p2), X1[1] + r2 * sp.sin(p2))
system = System([theta, b1, b2], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(m1, X1), Particle(m2, X2)],
                name="double arm on a rotating bar")

thd, w1, w2 = theta.diff(t), b1.diff(t) + theta.diff(t), b2.diff(t) + theta.diff(t)
L_book = (I * thd**2 / 2
          + m1 * (s**2 * thd**2 + r1**2 * w1**2 + 2 * s * r1 * thd * w1 * sp.cos(b1)) / 2
          + m2 * (s**2 * thd**2 + r1**2 * w1**2 + r2**2 * w2**2 + 2 * s * r1 * thd * w1 * sp.cos(b1)
                  + 2 * s * r2 * thd * w2 * sp.cos(b2) + 2 * r1 * r2 * w1 * w2 * sp.cos(b2 - b1)) / 2)


def _steady_at_zero(sys_):
    """Wells (11.10): the β1, β2 equations at β1 = β2 = 0, β̇ = 0, all accelerations 0, θ̇ arbitrary."""
    rest = {c.diff(t, 2): 0 for c in sys_.coordinates}
    rest.update({b1.diff(t): 0, b2.diff(t): 0})
    eqs = sys_.equations()
    return [(e.lhs - e.rhs).subs(rest).subs({b1: 0, b2: 0}) for e in eqs[1:]]


PROBLEM = Problem(
    id="p11.12",
    title="Double arm on a rotating bar: θ ignorable in (θ, β1, β2), steady motion at β1 = β2 = 0",
    chapter=11,
    source="Wells, Problem 11.12 (Fig. 11-15)",
    system=system,
    answers=[
        KineticEnergy(L_book),
        Quantity("θ is ignorable: ∂T/∂θ = 0", lambda sys_: sp.diff(sys_.T, theta), 0),
        Quantity("p_θ = ∂L/∂θ̇ (book's L)", lambda sys_: sp.diff(sys_.T, thd), sp.diff(L_book, thd)),
        Quantity("steady-motion conditions at β1 = β2 = 0", _steady_at_zero, [0, 0]),
    ],
    simulation=Simulation(params={I: 1, m1: 1, m2: 0.5, s: 1, r1: 0.5, r2: 0.4},
                          initial={theta: 0, b1: 0.2, b2: -0.1, thd: 2.0, b1.diff(t): 0, b2.diff(t): 0}, t_end=3),
    correction="The OCR misplaces a bracket in L; the physically re-derived form (catalog) is used. p_θ is "
               "∂L/∂θ̇ of the book's L. Horizontal plane: no potential energy.",
)
