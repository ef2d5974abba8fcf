"""Wells, Problem 3.7 — pendulum hung from a massless point sliding on a horizontal line between two springs."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import Problem, Quantity

xp, theta = coordinates("x_p theta")
m, g, k, r = parameters("m g k r")

# p at (x_p, 0), restrained by two springs (each k, relaxed at x_p = 0); bob m on a string r, θ from the vertical.
Y = -r * sp.cos(theta)
system = System(
    [xp, theta],
    bodies=[Particle(m, (xp + r * sp.sin(theta), Y), name="bob")],
    forces=-2 * k * xp * delta(xp) - m * g * delta(Y),
    name="pendulum on a spring-restrained massless slider",
)


def period(s):
    """Linearize about x_p = θ = 0: K = −∂F/∂q, M the (singular) mass matrix; det(K − ω²M) = 0."""
    qs = s.coordinates
    rest = {q.diff(t): 0 for q in qs}
    at0 = {q: 0 for q in qs}
    F = s.generalized_forces()
    Fv = sp.Matrix([F[q] for q in qs]).subs(rest)
    K = (-Fv.jacobian(qs)).subs(at0)
    M = s.mass_matrix.subs(rest).subs(at0)
    lam = sp.Symbol("lam")
    roots = [w2 for w2 in sp.solve(sp.det(K - lam * M), lam) if w2 != 0]
    assert len(roots) == 1, roots  # singular M: one finite mode
    return 2 * sp.pi / sp.sqrt(roots[0])


PROBLEM = Problem(
    id="p3.7",
    title="Pendulum from a massless spring-restrained slider: small-oscillation period (singular mass matrix)",
    chapter=3,
    source="Wells, Problem 3.7 (same system as Experiment 3.1)",
    system=system,
    answers=[
        Quantity("mass matrix determinant at the equilibrium theta = 0 (massless point p)",
                 lambda s: sp.simplify(s.mass_matrix.subs(theta, 0).det()), 0),
        Quantity("period P", period, 2 * sp.pi * sp.sqrt((m * g + 2 * k * r) / (2 * k * g))),
    ],
)
