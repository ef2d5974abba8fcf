"""Wells, Problem 2.11 — degrees of freedom of (a) two rigid bodies joined by a ball joint (9) and (b) the same
with one of them also ball-jointed to a fixed support (6).

Each body has six coordinates (its origin x, y, z and Wells' Euler angles ψ, θ, φ); a ball joint makes one
material point of each body coincide: three holonomic constraints. The degrees of freedom are the coordinates
less the rank of the constraints' Jacobian at a generic configuration, with the mass matrix of the free bodies of
full rank (the twelve coordinates independent).
"""

import sympy as sp

from lagrange import EulerAngles, Holonomic, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

q1 = coordinates("x1 y1 z1 psi1 theta1 phi1")
q2 = coordinates("x2 y2 z2 psi2 theta2 phi2")
M1, M2, A1, B1, C1, A2, B2, C2 = parameters("M1 M2 A1 B1 C1 A2 B2 C2")
a1, b1, c1, a2, b2, c2, d1, e1, f1 = parameters("a1 b1 c1 a2 b2 c2 d1 e1 f1")  # body coordinates of the joints

body1 = RigidBody(M1, (A1, B1, C1), origin=q1[:3], orientation=EulerAngles(*q1[3:]), name="body 1")
body2 = RigidBody(M2, (A2, B2, C2), origin=q2[:3], orientation=EulerAngles(*q2[3:]), name="body 2")
joint = body1.point((a1, b1, c1)).position - body2.point((a2, b2, c2)).position
support = body1.point((d1, e1, f1)).position  # (b): this point of body 1 is held at the fixed origin

free = System([*q1, *q2], bodies=[body1, body2], name="two free rigid bodies")
ball_joint = [Holonomic(joint[i], name=f"ball joint {'xyz'[i]}") for i in range(3)]
joined = System([*q1, *q2], bodies=[body1, body2], constraints=ball_joint,
                name="two rigid bodies joined by a ball joint")
supported = System([*q1, *q2], bodies=[body1, body2], name="two ball-jointed bodies, one on a fixed support",
                   constraints=[*ball_joint, *(Holonomic(support[i], name=f"support {'xyz'[i]}") for i in range(3))])


def _generic(s):
    pt = {q: sp.Rational(3 + i, 7 + 2 * i) for i, q in enumerate(s.coordinates)}
    pt.update({p: sp.Rational(11 + i, 9 + i) for i, p in enumerate(sorted(s.declared_symbols, key=str))})
    pt[t] = sp.Rational(2, 7)
    return pt


def _rank(matrix, pt):
    return matrix.subs(pt).evalf(30).rank(iszerofunc=lambda v: abs(v) < 1e-20)


def _dof(s):
    """Coordinates less the rank of the holonomic constraints' Jacobian, at a generic point."""
    jac = sp.Matrix([c.position for c in s.constraints]).jacobian(s.coordinates)
    return len(s.coordinates) - _rank(jac, _generic(s))


PROBLEMS = [
    Problem(
        id="p2.11-a",
        title="Two rigid bodies joined by a ball joint: 9 degrees of freedom",
        chapter=2,
        source="Wells, Problem 2.11(a)",
        system=None,
        answers=[Quantity("rank of the free bodies' mass matrix", lambda _: _rank(free.mass_matrix, _generic(free)),
                          12),
                 Quantity("degrees of freedom (12 less the joint's independent constraints)", lambda _: _dof(joined),
                          9),
                 Quantity("System.dof (configuration)", lambda _: joined.dof[0], 9)],
        correction="Body axes, inertias and joint positions are generic symbols (the book's figure is not "
        "needed for a count). No System is attached: a DOF count has no equations to check, and deriving the "
        "constrained 12-coordinate system would cost seconds for nothing; the Systems are built above.",
    ),
    Problem(
        id="p2.11-b",
        title="The two jointed bodies with one ball-jointed to a fixed support: 6 degrees of freedom",
        chapter=2,
        source="Wells, Problem 2.11(b)",
        system=None,
        answers=[Quantity("degrees of freedom (12 less six independent constraints)", lambda _: _dof(supported), 6),
                 Quantity("System.dof (configuration)", lambda _: supported.dof[0], 6)],
        correction="As in (a): generic geometry, a count only.",
    ),
]
