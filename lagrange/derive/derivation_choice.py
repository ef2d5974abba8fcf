"""Which derivation a :class:`~lagrange.System` uses: the values of ``derivation=``, what the structural
derivation (:mod:`lagrange.derive.structural`) cannot take, and the rule of ``derivation="auto"``.

Kept apart from the structural derivation itself so that declaring a System loads only this rule, not the
derivation machinery (a warm re-run takes its equations from the on-disk cache and never derives).
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from ..conventions import t
from ..model.bodies import Particle
from ..model.planar import PlanarBody
from ..model.rigid_body import RigidBody
from ..model.rotations import EulerAngles, Quaternion, RotationSequence, defining_expressions

__all__ = ["DERIVATIONS", "AUTO_MIN_COORDINATES", "structural_refusal", "auto_structural", "kinetic_declaration"]

#: the values of ``System(derivation=...)``
DERIVATIONS = ("auto", "expanded", "structural")


def structural_refusal(T_given, bodies) -> str | None:
    """Why the structural derivation cannot take a declaration (None when it can)."""
    if T_given is not None and sp.sympify(T_given) != 0:
        return ("T is given directly (in whole or in part): the structural derivation needs the kinetic energy "
                "to come wholly from bodies (Particle, RigidBody)")
    if not bodies:
        return "there are no bodies"
    for b in bodies:
        if type(b) not in (Particle, RigidBody, PlanarBody):  # (a PlanarBody is a RigidBody with rot_z)
            return f"body {b!r} is neither a Particle nor a RigidBody"
        if isinstance(b, RigidBody) and isinstance(b.orientation, Quaternion):
            return (f"rigid body {b.name or b!r} has a Quaternion orientation, whose ω = 2Eq̇ is the body's angular "
                    "velocity only on the unit sphere (Euler's equations need it everywhere)")
        for e in _kinematic_expressions(b):
            if sp.sympify(e).has(sp.Integral):
                return f"body {b.name or b!r} has an integral in its kinematics"
        constant = [b.mass] + ([*b.inertia, *b.com] if isinstance(b, RigidBody) else [])
        if any(sp.sympify(e).has(t) or sp.sympify(e).atoms(AppliedUndef) for e in constant):
            return (f"the mass, inertia or centre of mass of body {b.name or b!r} changes with the coordinates or t "
                    "(the structural form assumes them constant: m a and Euler's equations)")
    return None


def _kinematic_expressions(b) -> list:
    """Everything a body's kinetic energy is built from (for validation and the refusal checks): for a rigid
    body the expressions its orientation is defined by (:func:`~lagrange.model.rotations.defining_expressions`),
    not its rotation matrix, which holds the same symbols and is built only when used."""
    if isinstance(b, Particle):
        return [b.mass, *b.position]
    return [b.mass, *b.inertia, *b.origin, *b.com, *defining_expressions(b.orientation)]


def kinetic_declaration(bodies) -> tuple | None:
    """Everything the kinetic energy of ``bodies`` is built from, as plain data, when that pins T down without
    building it; else None. For a declaration :func:`structural_refusal` accepts (no T given directly, only
    Particles and RigidBodies, no Quaternion orientation, no integral, constant masses and inertias): the
    caller checks that first.

    ``("bodies", (body, ...))`` with a body ``("Particle", m, (x, y, z))`` or ``("RigidBody", m, inertia (9),
    origin (3), com (3), orientation)`` and an orientation ``("EulerAngles", ψ, θ, φ)``,
    ``("RotationSequence", ((axis, angle), ...))`` or ``("matrix", R (9))`` — the fields ``kinetic_energy()``
    reads (Wells 2.37 for a particle, 8.10 with 8.11 or ``vee(RᵀṘ)`` for a rigid body), whose code is in
    the derivation cache's source digest. None for an orientation of a subclass: then T itself is what
    identifies it. A :class:`~lagrange.System` builds T only on first use when this is not None (a warm re-run
    loads its equations by this key and never builds T), and checks the bodies' kinematics at declaration
    instead.
    """
    out = []
    for b in bodies:
        if type(b) is Particle:
            out.append(("Particle", b.mass, tuple(b.position)))
            continue
        o = b.orientation
        if type(o) is EulerAngles:
            orientation = ("EulerAngles", o.psi, o.theta, o.phi)
        elif type(o) is RotationSequence:
            orientation = ("RotationSequence", tuple(o.rotations))
        elif isinstance(o, (sp.MatrixBase, list, tuple)):
            orientation = ("matrix", tuple(b.R))
        else:
            return None
        out.append(("RigidBody", b.mass, tuple(b.inertia), tuple(b.origin), tuple(b.com), orientation))
    return ("bodies", tuple(out))


def auto_structural(n: int, bodies) -> bool:
    """The rule of ``derivation="auto"`` for a declaration the structural derivation can take: structural from
    :data:`AUTO_MIN_COORDINATES` coordinates on (measured in benchmarks/results/nlink_setup.md)."""
    return n >= AUTO_MIN_COORDINATES


#: from this many coordinates ``derivation="auto"`` picks the structural derivation
AUTO_MIN_COORDINATES = 6
