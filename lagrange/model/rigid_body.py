r"""Rigid bodies: Wells' general kinetic energy (8.10) and torques as generalized forces (8.12).

With O a point fixed in the body (the body origin, inertial position ``origin``), ``r̄`` the centre of
mass relative to O along the body axes, J the inertia tensor about O along the body axes (Wells'
positive products, :mod:`lagrange.model.inertia`), ω and v₀ along the body axes:

.. math::

    T = \tfrac12 M v_0^2 + \tfrac12\,\omega^{\mathsf T} J\,\omega
        + M\, v_0 \cdot (\omega \times \bar r) \qquad \text{(Wells 8.10)}

The last term vanishes when O is the centre of mass; the first and last when O is fixed. A torque τ on
the body (along the body axes, or the inertial axes with ``frame="inertial"``) has the generalized force
``F_q = τ · ∂ω/∂q̇`` (Wells 8.12); a force on the body is a :class:`~lagrange.Force` at one of its material
points, ``body.point(r_body)`` or ``body.point_at(position)`` (:class:`~lagrange.model.bodies.MaterialPoint`:
``F_q = F · ∂v_P/∂q̇`` with the body's velocity field ``v_P = v_O + ω × r_OP``).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import sympy as sp

from ..records import record
from ..safe_sympify import sympify as _sympify
from .bodies import MaterialPoint, as_vector
from .coordinates import normalize_time, time_derivative
from .inertia import Inertia
from .rotations import EulerAngles, Quaternion, RotationSequence, _compact, as_rotation, body_angular_velocity

__all__ = ["RigidBody", "Torque"]


def _tensor(inertia) -> sp.Matrix:
    if isinstance(inertia, Inertia):
        return inertia.tensor
    if isinstance(inertia, sp.MatrixBase):
        J = sp.Matrix(inertia)
        if J.shape != (3, 3) or J != J.T:
            raise ValueError("an inertia matrix must be a symmetric 3x3 matrix (the signed tensor)")
        return J
    if isinstance(inertia, Sequence) and len(inertia) == 3:
        return sp.diag(*[_sympify(v) for v in inertia])
    raise ValueError("inertia must be an Inertia, a signed 3x3 tensor or three principal moments (I_x, I_y, I_z)")


class RigidBody:
    """A rigid body for ``System(bodies=...)``.

    Parameters
    ----------
    mass : expression
    inertia : :class:`~lagrange.model.inertia.Inertia`, signed 3x3 tensor, or (I_x, I_y, I_z) principal
        moments — about the body origin O, along the body axes
    origin : inertial position of O (1–3 expressions in the coordinates and t); default the fixed origin
    orientation : :class:`EulerAngles` (Wells' z-x-z), :class:`Quaternion`, :class:`RotationSequence`
        (elementary rotations about body axes, compact angular velocity for long chains), or a rotation matrix R whose
        columns are the body axes in inertial components; default: axes parallel to the inertial ones
    com : centre of mass relative to O along the body axes (default O itself)
    name : label

    >>> from lagrange import coordinates, parameters, t
    >>> from lagrange.model.rotations import rot_z
    >>> th = coordinates("theta"); I = parameters("I")
    >>> RigidBody(1, (I, I, I), orientation=rot_z(th)).kinetic_energy()
    I*Derivative(theta(t), t)**2/2
    """

    def __init__(self, mass, inertia, origin=(0, 0, 0), orientation=None, com=(0, 0, 0), name: str = ""):
        mass, inertia, origin, com = (normalize_time(x) for x in (_sympify(mass), inertia, origin, com))
        if isinstance(orientation, (sp.MatrixBase, list, tuple)):  # dynamicsymbols accepted
            orientation = normalize_time(orientation)
        self.mass = mass
        self.inertia = _tensor(inertia)
        self.origin = as_vector(origin, f"origin of rigid body {name!r}")
        self.orientation = orientation if orientation is not None else sp.eye(3)
        if not isinstance(self.orientation, (EulerAngles, Quaternion, RotationSequence)):
            self.R = as_rotation(self.orientation)  # (checked now: a matrix of the wrong shape is refused here)
        self.com = as_vector(com, f"centre of mass of rigid body {name!r}")
        self.name = name

    @cached_property
    def R(self) -> sp.Matrix:
        """The rotation matrix: columns are the body axes in inertial components (built on first use for
        Euler angles, quaternions and rotation sequences; a warm re-run of a top never needs it whole)."""
        return as_rotation(self.orientation)

    # --- kinematics (computed once: the body never changes) --------------------------------------
    @cached_property
    def angular_velocity(self) -> sp.Matrix:
        """ω along the body axes (Wells 8.11 for Euler angles)."""
        return body_angular_velocity(self.orientation)

    @cached_property
    def space_angular_velocity(self) -> sp.Matrix:
        """ω along the inertial axes (``R ω_body``)."""
        if isinstance(self.orientation, RotationSequence):
            return self.orientation.space_angular_velocity()
        return self.R * self.angular_velocity

    def point(self, r_body) -> MaterialPoint:
        """The material point of the body with body coordinates ``r_body`` (relative to O, along the body
        axes; they may depend on the coordinates and t — then a different material point at each instant).

        A force at it acts on the body (``F_q = F · ∂v_P/∂q̇``, :class:`~lagrange.model.bodies.MaterialPoint`); its
        inertial position is ``.position`` (``O + R r_body``), its velocity ``.velocity``.
        """
        return MaterialPoint(self, r_body)

    def point_at(self, position) -> MaterialPoint:
        """The material point of the body that is at the inertial ``position`` (1–3 expressions in the
        coordinates and t) now: ``r_body = Rᵀ (position − O)``.

        Use it for a point located geometrically, e.g. the contact point ``centre − r n`` of a rolling
        wheel; a force there acts on the body with the body's velocity field.
        """
        d = as_vector(position, f"position of a point of rigid body {self.name!r}") - self.origin
        return MaterialPoint(self, (self.R.T * d).applyfunc(_compact))

    @property
    def centre_of_mass(self) -> sp.Matrix:
        """Inertial position of the centre of mass."""
        if "R" not in self.__dict__ and type(self.orientation) is EulerAngles:  # the columns it needs, not R
            return self.origin + _rotate(self.orientation.column, self.com)
        return self.origin + _rotate(lambda j: self.R[:, j], self.com)

    # --- energy ---------------------------------------------------------------------------------
    def kinetic_energy(self) -> sp.Expr:
        """Wells (8.10) with v₀ and ω along the body axes."""
        w = self.angular_velocity
        v0 = time_derivative(self.origin)
        T = sp.Rational(1, 2) * self.mass * (v0.T * v0)[0, 0] + sp.Rational(1, 2) * (w.T * self.inertia * w)[0, 0]
        if any(c != 0 for c in self.com) and any(c != 0 for c in v0):  # (a fixed origin: no cross term)
            v0_body = self.R.T * v0
            T += self.mass * (v0_body.T * w.cross(self.com))[0, 0]
        return T

    def constraints(self) -> tuple:
        """Constraints the orientation brings (the unit norm of a quaternion)."""
        return self.orientation.constraints() if isinstance(self.orientation, (EulerAngles, Quaternion)) else ()

    def position_vectors(self) -> tuple[sp.Matrix, ...]:
        """The body origin and the centre of mass (inertial positions)."""
        return (self.origin, self.centre_of_mass)

    def subs(self, mapping) -> RigidBody:
        """The body with ``mapping`` substituted (used by :func:`lagrange.eliminate`)."""

        def s(x):
            return _sympify(x).subs(mapping).doit()

        orient = self.orientation
        if isinstance(orient, EulerAngles):
            orient = EulerAngles(s(orient.psi), s(orient.theta), s(orient.phi))
        elif isinstance(orient, Quaternion):
            orient = Quaternion(*(s(c) for c in orient.components), name=orient.name)
        elif isinstance(orient, RotationSequence):
            orient = orient.subs(mapping)
        else:
            orient = self.R.subs(mapping).doit()
        return RigidBody(s(self.mass), self.inertia.subs(mapping), self.origin.subs(mapping).doit(), orient,
                         self.com.subs(mapping), self.name)

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return f"RigidBody{label}(mass={self.mass})"


def _rotate(column, v: sp.Matrix) -> sp.Matrix:
    """``R v`` from ``column(j)``, the j-th column of R, summed over v's non-zero components: the entries
    ``R * v`` gives (sympy drops the zero terms), without the matrix product's domain conversion (about 10 ms
    on a first use: a top's centre of mass), and with only the columns v needs."""
    columns = {j: column(j) for j in range(3) if v[j] != 0}
    return sp.Matrix([sp.Add(*[columns[j][i] * v[j] for j in columns]) for i in range(3)])


@record(frozen=True, eq=False, init=False)  # (its own __init__)
class Torque:
    """A torque ``vector`` acting on ``body``: along its body axes (default) or the inertial axes.

    Generalized force ``F_q = τ · ∂ω/∂q̇`` (Wells 8.12). For an internal motor between two bodies give
    equal and opposite torques on both.
    """

    body: RigidBody
    vector: sp.Matrix
    frame: str = "body"

    def __init__(self, body: RigidBody, vector, frame: str = "body"):
        if frame not in ("body", "inertial"):
            raise ValueError("Torque frame must be 'body' or 'inertial'")
        object.__setattr__(self, "body", body)
        object.__setattr__(self, "vector", as_vector(normalize_time(vector), "torque"))
        object.__setattr__(self, "frame", frame)

    def angular_velocity(self) -> sp.Matrix:
        """ω in the torque's frame (what ``τ·∂ω/∂q̇`` needs)."""
        return self.body.angular_velocity if self.frame == "body" else self.body.space_angular_velocity
