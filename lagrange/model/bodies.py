r"""Bodies that carry kinetic energy, and applied forces.

A body is anything with ``kinetic_energy()`` returning T in the coordinate functions and ``t``,
``name``, ``position_vectors()`` (the points drawn by animations) and ``subs(mapping)``. Particles live
here; :class:`~lagrange.model.rigid_body.RigidBody` follows the same protocol. A force on a rigid body acts
at one of its :class:`MaterialPoint` s (``body.point(r_body)``, ``body.point_at(position)``), whose virtual
displacement comes from the body's velocity field ``v_P = v_O + ω × r_OP``, not from a position expression.

Positions are Wells' *transformation equations* :math:`x_i = x_i(q_1..q_n, t)`: explicit ``t`` covers
moving frames, moving constraints and prescribed motions. T is always reckoned from velocities
relative to an inertial frame (Wells 2.37):

.. math:: T = \tfrac12 \sum_i m_i (\dot x_i^2 + \dot y_i^2 + \dot z_i^2),
   \qquad \dot x_i = \sum_k \frac{\partial x_i}{\partial q_k}\dot q_k + \frac{\partial x_i}{\partial t}.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import sympy as sp

from ..conventions import t
from ..errors import DeclarationError
from ..records import record
from ..safe_sympify import sympify as _sympify
from .coordinates import normalize_time, time_derivative, to_functions, to_symbols

if TYPE_CHECKING:
    from .rigid_body import RigidBody

__all__ = ["Body", "Particle", "MaterialPoint", "Force", "as_vector"]


def as_vector(components, what: str) -> sp.Matrix:
    """A 3-component column vector from 1, 2 or 3 expressions (missing ones are 0); a
    :class:`MaterialPoint` gives its position."""
    if isinstance(components, MaterialPoint):
        return components.position
    if isinstance(components, sp.MatrixBase):
        comps = list(components)
    elif isinstance(components, Sequence) and not isinstance(components, str):
        comps = list(components)
    else:
        comps = [components]
    if not 1 <= len(comps) <= 3:
        raise DeclarationError(f"{what} needs 1 to 3 components (x, y, z), got {len(comps)}")
    comps = [_sympify(c) for c in comps] + [sp.S.Zero] * (3 - len(comps))
    return sp.Matrix(comps)


@runtime_checkable
class Body(Protocol):
    name: str

    def kinetic_energy(self) -> sp.Expr: ...

    def position_vectors(self) -> tuple[sp.Matrix, ...]: ...

    def subs(self, mapping) -> Body: ...


@record(frozen=True, eq=False, init=False, repr=False)  # (its own __init__ and __repr__)
class Particle:
    """A point mass at ``position`` (1 to 3 Cartesian components, inertial frame).

    Parameters
    ----------
    mass : sympy expression
    position : sequence of 1–3 expressions in the coordinates and ``t``
    name : optional label used in messages and plots

    >>> from lagrange import coordinates, parameters, Particle, t
    >>> import sympy as sp
    >>> theta = coordinates("theta"); m, l = parameters("m l")
    >>> bob = Particle(m, (l*sp.sin(theta), -l*sp.cos(theta)))
    >>> sp.simplify(bob.kinetic_energy())
    l**2*m*Derivative(theta(t), t)**2/2
    """

    mass: sp.Expr
    position: sp.Matrix
    name: str = ""

    def __init__(self, mass, position, name: str = ""):
        mass, position = normalize_time(_sympify(mass)), normalize_time(position)  # dynamicsymbols accepted
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "position", as_vector(position, f"position of particle {name!r}"))
        object.__setattr__(self, "name", name)

    @property
    def velocity(self) -> sp.Matrix:
        """Inertial velocity, d(position)/dt including explicit time dependence."""
        return time_derivative(self.position)

    def kinetic_energy(self) -> sp.Expr:
        """½ m v·v with the inertial velocity."""
        v = self.velocity
        return sp.Rational(1, 2) * self.mass * (v.T * v)[0, 0]

    def position_vectors(self) -> tuple[sp.Matrix, ...]:
        """The points to draw: the particle's position."""
        return (self.position,)

    def subs(self, mapping) -> Particle:
        """The particle with ``mapping`` substituted in its mass and position (then ``doit``)."""
        return Particle(_sympify(self.mass).subs(mapping).doit(), self.position.subs(mapping).doit(), self.name)

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return f"Particle{label}(mass={self.mass}, position={tuple(self.position)})"


@record(frozen=True, eq=False, init=False, repr=False)  # (its own __init__ and __repr__)
class MaterialPoint:
    r"""The material point of a rigid ``body`` whose body coordinates (relative to the body origin O, along
    the body axes) are ``r_body`` now.

    Made by :meth:`RigidBody.point(r_body) <lagrange.model.rigid_body.RigidBody.point>` or
    :meth:`RigidBody.point_at(position) <lagrange.model.rigid_body.RigidBody.point_at>`; pass it as ``at``
    of a :class:`~lagrange.Force` to apply a force **to the body** there. ``r_body`` may depend on the
    coordinates and t (the contact point of a rolling wheel, ``−r (sin φ, cos φ, 0)`` for Wells' Euler
    angles): it is evaluated, never differentiated, so the point moves with the body:

    .. math::

        v_P = \dot{\mathbf r}_O + \dot R\,\bar r\big|_{\bar r\ \text{frozen}}
            = v_O + \omega \times (R\,\bar r), \qquad
        F_{q_k} = F \cdot \frac{\partial v_P}{\partial \dot q_k}

    with O the body origin, R the orientation (columns: body axes in inertial components,
    :mod:`lagrange.model.rotations`) and r̄ the body coordinates (Kane & Levinson, *Dynamics: Theory and
    Applications*, 1985: velocities of two points fixed on a rigid body, ch. 2; partial velocities and
    generalized active forces, ch. 4). Wells (4.10) is the special case
    of constant r̄, where ``∂v_P/∂q̇ = ∂r/∂q``. The two readings differ when r̄ changes with the coordinates:
    the contact point of a rolling wheel, a rim point facing a fixed direction. For a unit-quaternion
    orientation ``Ṙ r̄`` and ``ω × (R r̄)`` coincide on the unit sphere; off it they differ only along the
    norm constraint's gradient, which its multiplier absorbs (same q̈).

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
    >>> from lagrange import RigidBody, coordinates, rot_z
    >>> th, s = coordinates("theta s")
    >>> rod = RigidBody(1, (0, 1, 1), orientation=rot_z(th))
    >>> rod.point((s, 0, 0)).velocity.T     # the rod's point at distance s: ω × r only, no ṡ
    Matrix([[-s(t)*sin(theta(t))*Derivative(theta(t), t), s(t)*cos(theta(t))*Derivative(theta(t), t), 0]])
    """

    body: RigidBody
    r_body: sp.Matrix

    def __init__(self, body: RigidBody, r_body):
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


@record(frozen=True, eq=False, init=False)  # (its own __init__)
class Force:
    r"""A force ``vector`` (1–3 Cartesian components, inertial axes) applied at a particle, a material point
    of a rigid body, or a geometric point.

    The vector may depend on t, the coordinates and the velocities (Lorentz force, drag, friction).

    Parameters
    ----------
    at : Particle, MaterialPoint, or a position (1–3 expressions in the coordinates and t)
        Where the force acts:

        * a :class:`Particle` — on the particle;
        * a :class:`MaterialPoint` (``body.point(r_body)``,
          ``body.point_at(position)``) — **on the rigid body**, at its material point there;
        * a position expression — at that *geometric* point (Wells 4.10).
    vector : 1–3 expressions
    name : optional label used in messages
    body : RigidBody, optional
        Apply the force to this body at its material point that is at the position ``at`` now; the same as
        ``at=body.point_at(at)``.

    Notes
    -----
    The generalized force is :math:`F_{q_k} = F\cdot\partial v_P/\partial\dot q_k` with ``v_P`` the
    velocity of the point of application. For a particle or a geometric point ``v_P = ṙ`` and this is Wells
    (4.10), ``F_q = F · ∂r/∂q`` with t frozen. For a material point ``v_P = v_O + ω × r_OP`` (the body's
    velocity field, :class:`MaterialPoint`).

    **A force on a body acts at a material point of that body; a position expression is a geometric
    point.** The two agree when the position is fixed in the body (``body.point`` with constant body
    coordinates, the centre of mass), and differ when it is not: the contact point of a rolling wheel written
    as ``centre − r n`` slides along the ground without the wheel's spin, so a force there given by its
    position alone loses the spin part of its virtual work. Give such a force with ``body=`` or at
    ``body.point_at(...)``.

    Raises
    ------
    DeclarationError
        ``body`` is not a rigid body, ``at`` is a material point of another body or a particle while
        ``body`` is given.
    """

    at: sp.Matrix | MaterialPoint
    vector: sp.Matrix
    name: str = ""

    def __init__(self, at, vector, name: str = "", body: RigidBody | None = None):
        label = name or "force"
        at = normalize_time(at)
        if body is not None:
            if not callable(getattr(body, "point_at", None)):
                raise DeclarationError(f"{label}: body={body!r} is not a RigidBody (a force on a particle is "
                                       "Force(particle, vector))")
            if isinstance(at, Particle):
                raise DeclarationError(f"{label}: at= is particle {at.name!r} and body= is {body.name!r}; a force "
                                       "acts on one of them: drop body= or give the position")
            if isinstance(at, MaterialPoint):
                if at.body is not body:
                    raise DeclarationError(f"{label}: at= is a material point of rigid body {at.body.name!r} but "
                                           f"body= is {body.name!r}")
            else:
                at = body.point_at(as_vector(at, f"point of application of {label}"))
        if isinstance(at, MaterialPoint):
            point = at
        elif isinstance(at, Particle):
            point = at.position
        else:
            point = as_vector(at, "point of application")
        object.__setattr__(self, "at", point)
        object.__setattr__(self, "vector", as_vector(normalize_time(vector), f"force {name!r}"))
        object.__setattr__(self, "name", name)

    @property
    def body(self):
        """The rigid body the force acts on (None for a particle or a geometric point)."""
        return self.at.body if isinstance(self.at, MaterialPoint) else None

    @property
    def position(self) -> sp.Matrix:
        """Where the force acts now (inertial position)."""
        return as_vector(self.at, "point of application")
