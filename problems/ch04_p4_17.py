"""Wells, Problem 4.17 — the Example 4.8 rotating table on a cart accelerating horizontally."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

q1, q2 = coordinates("q1 q2")
m1, m2, a, w, s, al = parameters("m1 m2 a omega s alpha")

# Geometry inferred from the printed T (Ex. 4.8's figure not available): the table turns at ω about a vertical axis
# whose foot moves as a t²/2 along X; each m_i slides on a line inclined at α, at horizontal distance s + q_i cosα
# from the axis and height q_i sinα.


def on_table(mass, qi, name):
    rho = s + qi * sp.cos(al)
    return Particle(mass, (a * t**2 / 2 + rho * sp.cos(w * t), rho * sp.sin(w * t), qi * sp.sin(al)), name=name)


system = System([q1, q2], bodies=[on_table(m1, q1, "m1"), on_table(m2, q2, "m2")],
                name="rotating table on an accelerating cart")


def T_i(mi, qi):
    return sp.Rational(1, 2) * mi * (a**2 * t**2 + (s + qi * sp.cos(al)) ** 2 * w**2 + qi.diff(t) ** 2
                                     - 2 * a * t * w * (s + qi * sp.cos(al)) * sp.sin(w * t)
                                     + 2 * a * t * qi.diff(t) * sp.cos(al) * sp.cos(w * t))


PROBLEM = Problem(
    id="p4.17",
    title="Rotating table of Ex. 4.8 on a horizontally accelerating cart: kinetic energy",
    chapter=4,
    source="Wells, Problem 4.17",
    system=system,
    answers=[KineticEnergy(T_i(m1, q1) + T_i(m2, q2))],
    simulation=Simulation(params={m1: 1, m2: 1, a: 1, w: 1, s: 0.5, al: 0.5},
                          initial={q1: 0.2, q2: 0.3, q1.diff(t): 0, q2.diff(t): 0}, t_end=1),
    correction="Geometry reconstructed from the printed T (Ex. 4.8 is not in the catalog); only T is checked. "
               "The generalized forces 'as in Ex. 4.8' are not included.",
)
