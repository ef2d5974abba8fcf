"""Wells, Example 4.4 — pendulum (m2, length r) hung from a block m1 sliding freely on a horizontal line."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import (
    ConservedMomenta,
    EquationsOfMotion,
    GeneralizedForces,
    KineticEnergy,
    Problem,
    Quantity,
    Simulation,
)

x1, theta = coordinates("x1 theta")
m1, m2, r, g = parameters("m1 m2 r g")

# Y downward: x2 = x1 + r sinθ, y2 = r cosθ; gravity +m2 g δy2.
y2 = r * sp.cos(theta)
system = System(
    [x1, theta],
    bodies=[Particle(m1, (x1, 0), name="block"), Particle(m2, (x1 + r * sp.sin(theta), y2), name="bob")],
    forces=m2 * g * delta(y2),
    name="pendulum on a sliding block",
)


def omega_squared(s):
    """Linearize about θ = 0: nonzero root of det(K − ω² M) = 0 (the other mode is ω = 0)."""
    qs = s.coordinates
    rest = {q.diff(t): 0 for q in qs}
    at0 = {q: 0 for q in qs}
    F = s.generalized_forces()
    K = (-sp.Matrix([F[q] for q in qs]).subs(rest).jacobian(qs)).subs(at0)
    M = s.mass_matrix.subs(rest).subs(at0)
    lam = sp.Symbol("lam")
    roots = [w2 for w2 in sp.solve(sp.det(K - lam * M), lam) if w2 != 0]
    return roots[0]


PROBLEM = Problem(
    id="ex4.4",
    title="Pendulum on a freely sliding block: equations, conserved x-momentum, frequency",
    chapter=4,
    source="Wells, Example 4.4",
    system=system,
    answers=[
        KineticEnergy(m1 / 2 * x1.diff(t) ** 2 + m2 / 2 * (x1.diff(t) ** 2 + 2 * r * x1.diff(t) * theta.diff(t)
                                                            * sp.cos(theta) + r**2 * theta.diff(t) ** 2)),
        GeneralizedForces({x1: 0, theta: -m2 * g * r * sp.sin(theta)}),
        EquationsOfMotion([
            sp.Eq((m1 + m2) * x1.diff(t, 2) + m2 * r * theta.diff(t, 2) * sp.cos(theta)
                  - m2 * r * theta.diff(t) ** 2 * sp.sin(theta), 0),
            sp.Eq(m2 * r * x1.diff(t, 2) * sp.cos(theta) + m2 * r**2 * theta.diff(t, 2), -m2 * g * r * sp.sin(theta)),
        ], per_equation=True),
        # The book integrates the linearized x1 equation to x1 + m2 r θ/(m1 + m2) = C1 t + C2; the exact
        # first integral behind it is the x1-momentum (x1 is ignorable).
        ConservedMomenta({x1: (m1 + m2) * x1.diff(t) + m2 * r * theta.diff(t) * sp.cos(theta)}),
        Quantity("omega^2 of the linearized oscillation", omega_squared, (m1 + m2) * g / (r * m1)),
    ],
    simulation=Simulation(params={m1: 2, m2: 1, r: 1, g: 9.81},
                          initial={x1: 0, theta: 0.5, x1.diff(t): 0, theta.diff(t): 0}, t_end=5),
    correction="Linearized equations are printed with single dots (OCR); the accelerations are meant. The exact "
               "conserved momentum of the ignorable x1 is the nonlinear form of the book's C1 (derived).",
)
