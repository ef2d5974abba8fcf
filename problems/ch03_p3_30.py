"""Wells, Problem 3.30 — acceleration component along the q1 line of oblique axes."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

q1, q2 = coordinates("q1 q2")
alpha, beta = parameters("alpha beta")

X = q1 * sp.cos(alpha) + q2 * sp.cos(beta)
Y = q1 * sp.sin(alpha) + q2 * sp.sin(beta)
system = System([q1, q2], bodies=[Particle(1, (X, Y), name="unit mass")], name="oblique axes")


def a_q1(s):
    eq = s.equations()[0]
    h = sp.sqrt(sp.diff(X, q1) ** 2 + sp.diff(Y, q1) ** 2)
    return (eq.lhs - eq.rhs) / sp.trigsimp(h)


PROBLEM = Problem(
    id="p3.30",
    title="Oblique axes: a_q1 from (3.24) with h = 1",
    chapter=3,
    source="Wells, Problem 3.30",
    system=system,
    answers=[Quantity("a_q1", a_q1, q1.diff(t, 2) + q2.diff(t, 2) * sp.cos(beta - alpha))],
)
