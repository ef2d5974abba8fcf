"""Wells, Example 4.5 with the centre-of-mass relation kept — three masses in a vertical chain with springs.

Multiplier form: coordinates (q2, q3, y, q1) with y1 = y + q1, y2 = y − q2, y3 = y − q3 and the relation
``m1 q1 − m2 q2 − m3 q3 = 0`` (y is the centre of mass) as a holonomic constraint, A = (−m2, −m3, 0, m1).
The applied forces are Wells' δW_total (his (2)): springs plus −M g δy. That δW already used the relation
— gravity's full virtual work is −g(M δy + m1 δq1 − m2 δq2 − m3 δq3), and the bracket is the variation of
the constraint. So in the multiplier form the constraint supplies the missing part: λ·A = −g(m1, −m2, −m3) on
(q1, q2, q3), i.e. λ = −g (engine convention: λ A_kr is added to the applied forces; derived). With gravity
applied particle by particle the multiplier would vanish: the relation is a definition, not a support.
Eliminating q1 gives the book's equations (typo corrected).

The full-coordinate mass matrix is singular here (four coordinates, three particles on a line: T depends on
three combinations only), although the augmented matrix [[M, −Aᵀ], [A, 0]] is regular. The engine's integrator
refuses a singular M even with constraints, so this variant has no simulation; λ is checked instead by solving
the augmented system symbolically from the derived M, f, A and c (Quantity).
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, delta, eliminate, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation

q2, q3, y, q1 = coordinates("q2 q3 y q1")
m1, m2, m3, k1, k2, l1, l2, g = parameters("m1 m2 m3 k1 k2 l1 l2 g")
M = m1 + m2 + m3

system = System(
    [q2, q3, y, q1],
    bodies=[Particle(m1, (0, y + q1), name="m1"), Particle(m2, (0, y - q2), name="m2"),
            Particle(m3, (0, y - q3), name="m3")],
    forces=(-k1 * (q1 + q2 - l1) * delta(q1 + q2) - k2 * (q3 - q2 - l2) * delta(q3 - q2) - M * g * delta(y)),
    constraints=[Holonomic(m1 * q1 - m2 * q2 - m3 * q3, name="centre of mass")],
    name="three masses and two springs, CM relation as a multiplier",
)
reduced = eliminate(system, {q1: (m2 * q2 + m3 * q3) / m1})

br = (m1 + m2) / m1 * q2 + m3 / m1 * q3 - l1
Fq2 = -k1 * (m1 + m2) / m1 * br + k2 * (q3 - q2 - l2)
Fq3 = -k1 * m3 / m1 * br - k2 * (q3 - q2 - l2)



def _kkt(s):
    """(q̈, λ) from the derived M q̈ = f + Bλ, A q̈ = c, solved together (M alone is singular here)."""
    e = s.derived
    n, m = e.n, e.m
    K = sp.zeros(n + m, n + m)
    K[:n, :n] = e.mass_matrix
    K[:n, n:] = -e.reaction_matrix
    K[n:, :n] = e.constraint_matrix
    rhs = sp.Matrix(list(e.forcing) + list(e.constraint_rhs))
    sol = K.LUsolve(rhs)
    return list(sol[:n]), list(sol[n:])


PARAMS = {m1: 1.0, m2: 2.0, m3: 1.5, k1: 40.0, k2: 30.0, l1: 1.0, l2: 1.0, g: 9.81}

PROBLEMS = [
    Problem(
        id="ex4.5-multipliers",
        title="Three masses and two springs with the CM relation m1 q1 = m2 q2 + m3 q3 as a multiplier",
        chapter=4,
        source="Wells, Example 4.5",
        system=system,
        answers=[
            GeneralizedForces({q1: -k1 * (q1 + q2 - l1), q2: -k1 * (q1 + q2 - l1) + k2 * (q3 - q2 - l2),
                               q3: -k2 * (q3 - q2 - l2), y: -M * g}, which="applied"),
            Quantity("multiplier of the CM relation (augmented solve)", lambda s: _kkt(s)[1][0], -g),
            Quantity("generalized constraint force on q1, lambda*m1", lambda s: _kkt(s)[1][0] * m1, -m1 * g),
        ],
        correction="The book eliminates q1; λ = −g is derived (see the module docstring).",
    ),
    Problem(
        id="ex4.5-multipliers-reduced",
        title="Three masses and two springs: q1 eliminated from the multiplier form gives the book's equations",
        chapter=4,
        source="Wells, Example 4.5",
        system=reduced,
        answers=[
            GeneralizedForces({q2: Fq2, q3: Fq3, y: -M * g}),
            EquationsOfMotion(
                [sp.Eq(m2 / m1 * (m1 + m2) * q2.diff(t, 2) + m2 * m3 / m1 * q3.diff(t, 2), Fq2),
                 sp.Eq(m2 * m3 / m1 * q2.diff(t, 2) + m3 * (m1 + m3) / m1 * q3.diff(t, 2), Fq3),
                 sp.Eq(M * y.diff(t, 2), -M * g)],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params=PARAMS, initial={q2: 0.4, q3: 1.2, y: 0.0, q2.diff(t): 0.1,
                                                       q3.diff(t): -0.2, y.diff(t): 0.0}, t_end=2),
        correction="The book prints m3(m1 + m2)/m1 for the q3'' coefficient of the second equation; the correct "
        "value is m3(m1 + m3)/m1 (catalog, sym ✓).",
    ),
]
