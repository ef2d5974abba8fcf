r"""Material points of rigid bodies: where a force on a body acts, and how that point moves.

A force on a rigid body acts on the **material point** of the body that is at the point of application
*now*. Its virtual displacement — and so its generalized force — comes from the body's velocity field,
not from the derivative of a position expression:

.. math::

    v_P = \dot{\mathbf r}_O + \dot R\,\bar r\big|_{\bar r\ \text{frozen}}
        = v_O + \omega \times (R\,\bar r), \qquad
    F_{q_k} = F \cdot \frac{\partial v_P}{\partial \dot q_k}

with O the body origin, R the orientation (columns: body axes in inertial components, see
:mod:`lagrange.model.rotations`) and :math:`\bar r` the body coordinates of the point relative to O,
*evaluated* at the current configuration but not differentiated (Kane & Levinson, *Dynamics: Theory and
Applications*, 1985, eq. 2.7.1 and the partial velocities of sec. 4.1; Wells 4.10 is the special case of a
point whose body coordinates are constant, where :math:`\partial v_P/\partial\dot q = \partial r/\partial q`).

The two readings differ exactly when :math:`\bar r` changes with the coordinates: the contact point of a
rolling wheel (always the lowest point of the rim, a different material point at every instant) or the
rim point of a top that faces a fixed direction. The position expression of such a point moves along the
ground, without the body's spin, so ``F · ∂r/∂q`` loses the spin part of the virtual work; the material
point keeps it.

For the unit-quaternion orientation, ``Ṙ r̄`` and ``ω × (R r̄)`` coincide on the unit sphere; off it they
differ only along the norm constraint's gradient, which its multiplier absorbs (same q̈).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy as sp

from ..conventions import t
from .bodies import as_vector
from .coordinates import time_derivative, to_functions, to_symbols

if TYPE_CHECKING:
    from .rigid_body import RigidBody

__all__ = ["MaterialPoint"]


@dataclass(frozen=True, eq=False)
class MaterialPoint:
    r"""The material point of a rigid ``body`` whose body coordinates (relative to the body origin O, along
    the body axes) are ``r_body`` now.

    Made by :meth:`RigidBody.point(r_body) <lagrange.model.rigid_body.RigidBody.point>` or
    :meth:`RigidBody.point_at(position) <lagrange.model.rigid_body.RigidBody.point_at>`; pass it as ``at``
    of a :class:`~lagrange.Force` to apply a force **to the body** there. ``r_body`` may depend on the
    coordinates and t (the contact point of a rolling wheel, ``−r (sin φ, cos φ, 0)`` for Wells' Euler
    angles): it is evaluated, never differentiated, so the point moves with the body (equation in
    :mod:`lagrange.model.material_point`).

    Parameters
    ----------
    body : RigidBody
    r_body : 1–3 expressions in the coordinates and t (no velocities)

    Attributes
    ----------
    position : Matrix, shape (3, 1)
        ``O + R r̄`` in inertial components (where the point is now; also accepted wherever a position is
        expected, e.g. ``Particle(m, body.point(r))``).
    velocity : Matrix, shape (3, 1)
        ``v_O + Ṙ r̄`` with r̄ frozen (= ``v_O + ω × R r̄``), inertial components.

    Examples
    --------
    >>> from lagrange import RigidBody, coordinates, parameters, rot_z, t
    >>> th, s = coordinates("theta s"); a = parameters("a")
    >>> rod = RigidBody(1, (0, 1, 1), orientation=rot_z(th))
    >>> rod.point((s, 0, 0)).velocity.T     # the rod's point at distance s: ω × r only, no ṡ
    Matrix([[-s(t)*sin(theta(t))*Derivative(theta(t), t), s(t)*cos(theta(t))*Derivative(theta(t), t), 0]])
    """

    body: RigidBody
    r_body: sp.Matrix

    def __init__(self, body: RigidBody, r_body):
        from ..errors import DeclarationError

        r = as_vector(r_body, f"body point of rigid body {body.name!r}")
        if r.atoms(sp.Derivative):
            raise DeclarationError(
                f"the body coordinates {tuple(r)} of a point of rigid body {body.name!r} contain velocities: a "
                "material point is located by the coordinates and t only")
        object.__setattr__(self, "body", body)
        object.__setattr__(self, "r_body", r)

    @property
    def position(self) -> sp.Matrix:
        """Inertial position ``O + R r̄`` of the point now."""
        return self.body.origin + self.body.R * self.r_body

    @property
    def velocity(self) -> sp.Matrix:
        """Inertial velocity of the material point, ``v_O + Ṙ r̄`` with r̄ frozen."""
        return time_derivative(self.body.origin) + time_derivative(self.body.R) * self.r_body

    def partial_velocities(self, coords: Sequence) -> dict:
        r"""``{q: ∂v_P/∂q̇}`` (Kane's partial velocities, inertial components) for each coordinate."""
        v = to_symbols(self.velocity, coords)
        return {q: to_functions(v.diff(to_symbols(q.diff(t), coords)), coords) for q in coords}

    def subs(self, mapping) -> MaterialPoint:
        """The point with ``mapping`` substituted in its body and body coordinates (then ``doit``)."""
        return MaterialPoint(self.body.subs(mapping), self.r_body.subs(mapping).doit())

    def __repr__(self) -> str:
        label = f" of {self.body.name!r}" if self.body.name else ""
        return f"MaterialPoint{label}(r_body={tuple(self.r_body)})"
