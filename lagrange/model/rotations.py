r"""Orientations of rigid bodies: elementary rotations, Wells' Euler angles, quaternions, angular velocity.

Convention (stated once)
------------------------
An orientation is a rotation matrix ``R`` whose **columns are the body axes x, y, z expressed in the
inertial frame** (it maps body components to inertial components: ``r_inertial = R r_body``). Wells'
direction cosines are its transpose, ``α_ij = R_ji`` (row i = body axis, column j = inertial axis; Table
8.2). The angular velocity's body components follow from ``Rᵀ Ṙ = [ω]×`` and its inertial components
from ``Ṙ Rᵀ = [ω]×``.

Wells' Euler angles (Fig. 8-16, z-x-z): ψ precession about Z1, θ nutation about the line of nodes, φ spin
about the body z; ``R = R_z(ψ) R_x(θ) R_z(φ)`` and (Wells 8.11)

.. math:: \omega_x = \dot\psi s\theta s\phi + \dot\theta c\phi,\quad
          \omega_y = \dot\psi s\theta c\phi - \dot\theta s\phi,\quad
          \omega_z = \dot\phi + \dot\psi c\theta .

The Euler-angle mass matrix is singular at θ = 0, π (gimbal lock: only ψ + φ is defined). The remedy is
:class:`Quaternion` orientation — four coordinates with the unit-norm constraint, which the body adds to
the system itself — valid at every orientation (a sleeping top).
"""

from __future__ import annotations

import sympy as sp

from ..conventions import t
from ..records import record
from ..safe_sympify import matrix as _matrix
from ..safe_sympify import sympify as _sympify
from ..simplification import trigsimp
from .coordinates import normalize_fields, time_derivative

__all__ = [
    "rot_x",
    "rot_y",
    "rot_z",
    "EulerAngles",
    "Quaternion",
    "RotationSequence",
    "as_rotation",
    "defining_expressions",
    "body_angular_velocity",
    "space_angular_velocity",
]


def rot_x(a) -> sp.Matrix:
    """Rotation by angle ``a`` about x (columns: the rotated axes in the old frame)."""
    a = _sympify(a, where="rotation angle")
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(a) -> sp.Matrix:
    """Rotation by angle ``a`` about y."""
    a = _sympify(a, where="rotation angle")
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(a) -> sp.Matrix:
    """Rotation by angle ``a`` about z."""
    a = _sympify(a, where="rotation angle")
    c, s = sp.cos(a), sp.sin(a)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


@record(frozen=True)
class EulerAngles:
    """Wells' Euler angles (z-x-z): ψ precession, θ nutation, φ spin (Fig. 8-16, Table 8.2).

    >>> from lagrange import coordinates
    >>> psi, theta, phi = coordinates("psi theta phi")
    >>> EulerAngles(psi, theta, phi).matrix.T[0, 2]  # α13 = sθ sφ
    sin(phi(t))*sin(theta(t))
    """

    psi: sp.Expr
    theta: sp.Expr
    phi: sp.Expr

    def __post_init__(self):
        normalize_fields(self, ("psi", "theta", "phi"))  # sympy.physics.mechanics dynamicsymbols are accepted

    @property
    def matrix(self) -> sp.Matrix:
        """``R_z(ψ) R_x(θ) R_z(φ)`` multiplied out (Wells Table 8.2; the same expressions as the product, built
        without its zeros and ones: a quarter of its cost)."""
        columns = [self.column(j) for j in range(3)]
        return sp.Matrix(3, 3, lambda i, j: columns[j][i])

    def column(self, j: int) -> list:
        """Column ``j`` of :attr:`matrix` (body axis x, y or z in inertial components), without building the
        other two: the body z axis needs neither sin φ nor cos φ (a top's centre of mass)."""
        c1, s1 = sp.cos(self.psi), sp.sin(self.psi)
        c2, s2 = sp.cos(self.theta), sp.sin(self.theta)
        if j == 2:
            return [s1 * s2, -c1 * s2, c2]
        c3, s3 = sp.cos(self.phi), sp.sin(self.phi)
        if j == 0:
            return [c1 * c3 - s1 * c2 * s3, s1 * c3 + c1 * c2 * s3, s2 * s3]
        return [-c1 * s3 - s1 * c2 * c3, -s1 * s3 + c1 * c2 * c3, s2 * c3]

    def body_angular_velocity(self) -> sp.Matrix:
        """Wells (8.11), in closed form."""
        ps, th, ph = self.psi, self.theta, self.phi
        pd, td, fd = ps.diff(t), th.diff(t), ph.diff(t)
        return sp.Matrix([
            pd * sp.sin(th) * sp.sin(ph) + td * sp.cos(ph),
            pd * sp.sin(th) * sp.cos(ph) - td * sp.sin(ph),
            fd + pd * sp.cos(th),
        ])

    def constraints(self) -> tuple:
        return ()


@record(frozen=True)
class Quaternion:
    """Unit quaternion orientation ``(q0, q1, q2, q3)`` (scalar first); adds ``Σ q_i² − 1 = 0``.

    ``R = (q0² − |v|²) I + 2 v vᵀ + 2 q0 [v]×`` and ``ω_body = 2 E q̇`` with
    ``E = [[−q1, q0, q3, −q2], [−q2, −q3, q0, q1], [−q3, q2, −q1, q0]]``. The kinetic energy does not
    depend on the velocity along q itself, so the mass matrix is singular alone; the norm constraint
    makes the augmented system regular (see :mod:`lagrange.derive.multipliers`).
    """

    q0: sp.Expr
    q1: sp.Expr
    q2: sp.Expr
    q3: sp.Expr
    name: str = "unit quaternion"

    def __post_init__(self):
        normalize_fields(self, ("q0", "q1", "q2", "q3"))

    @property
    def components(self) -> tuple:
        return (self.q0, self.q1, self.q2, self.q3)

    @property
    def matrix(self) -> sp.Matrix:
        q0, q1, q2, q3 = self.components
        return sp.Matrix([
            [q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
            [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
            [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2],
        ])

    def body_angular_velocity(self) -> sp.Matrix:
        q0, q1, q2, q3 = self.components
        E = sp.Matrix([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])
        return 2 * E * sp.Matrix([q.diff(t) for q in self.components])

    def constraints(self) -> tuple:
        from .constraints import Holonomic

        return (Holonomic(sum(q**2 for q in self.components) - 1, self.name),)


_ELEMENTARY = {"x": rot_x, "y": rot_y, "z": rot_z}
_AXIS = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}


class RotationSequence:
    r"""An orientation composed of elementary rotations about the current body axes,
    ``R = R_{a_1}(θ_1) R_{a_2}(θ_2) ⋯ R_{a_k}(θ_k)`` (each ``a_i`` one of ``"x"``, ``"y"``, ``"z"``; each
    ``θ_i`` an expression in coordinates, t and parameters — a constant tilt is an angle without coordinates).

    Its angular velocity along the body axes has the closed form

    .. math:: \omega = \sum_{i=1}^{k} (R_{i+1} \cdots R_k)^{\mathsf T}\, e_{a_i}\, \dot\theta_i ,

    which stays compact for long chains (a bicycle's front wheel: yaw, roll, pitch, steer, spin), where
    ``vee(RᵀṘ)`` of the multiplied-out matrix needs trigonometric simplification to shrink back.

    >>> from lagrange import coordinates, t
    >>> a, b = coordinates("a b")
    >>> RotationSequence(("z", a), ("x", b)).body_angular_velocity().T
    Matrix([[Derivative(b(t), t), sin(b(t))*Derivative(a(t), t), cos(b(t))*Derivative(a(t), t)]])
    """

    def __init__(self, *rotations):
        steps = []
        for item in rotations:
            try:
                axis, angle = item
            except (TypeError, ValueError):
                raise ValueError(f"RotationSequence takes (axis, angle) pairs, got {item!r}") from None
            if axis not in _ELEMENTARY:
                raise ValueError(f"rotation axis {axis!r} must be 'x', 'y' or 'z'")
            steps.append((axis, _sympify(angle, where=f"RotationSequence angle about {axis}")))
        if not steps:
            raise ValueError("RotationSequence needs at least one (axis, angle) pair")
        self.rotations: tuple = tuple(steps)

    @property
    def matrix(self) -> sp.Matrix:
        R = sp.eye(3)
        for axis, angle in self.rotations:
            R = R * _ELEMENTARY[axis](angle)
        return R

    def body_angular_velocity(self) -> sp.Matrix:
        """The closed form above: each rate carried back through the rotations after it."""
        w = sp.zeros(3, 1)
        for axis, angle in self.rotations:
            w = _ELEMENTARY[axis](angle).T * w + sp.Matrix(_AXIS[axis]) * angle.diff(t)
        return w

    def space_angular_velocity(self) -> sp.Matrix:
        """ω along the inertial axes: ``Σ_i R_1 ⋯ R_{i−1} e_{a_i} θ̇_i``."""
        w, R = sp.zeros(3, 1), sp.eye(3)
        for axis, angle in self.rotations:
            w += R * sp.Matrix(_AXIS[axis]) * angle.diff(t)
            R = R * _ELEMENTARY[axis](angle)
        return w

    def subs(self, mapping) -> RotationSequence:
        return RotationSequence(*((a, _sympify(th).subs(mapping).doit()) for a, th in self.rotations))

    def constraints(self) -> tuple:
        return ()

    def __repr__(self) -> str:
        return "RotationSequence(" + ", ".join(f"({a!r}, {th})" for a, th in self.rotations) + ")"


def defining_expressions(orientation) -> list:
    """What an orientation is built from: the three Euler angles, the angles of a rotation sequence, the four
    quaternion components, or the nine entries of a matrix. Its rotation matrix and angular velocity hold the
    same coordinates, functions, derivatives and integrals, so declarations are checked on these. (A subclass
    may build its matrix otherwise: its matrix is what it is defined by.)"""
    if type(orientation) is EulerAngles:
        return [orientation.psi, orientation.theta, orientation.phi]
    if type(orientation) is RotationSequence:
        return [angle for _, angle in orientation.rotations]
    if type(orientation) is Quaternion:
        return list(orientation.components)
    return list(as_rotation(orientation))


def as_rotation(orientation) -> sp.Matrix:
    """The rotation matrix of an orientation (EulerAngles, Quaternion, RotationSequence or a 3x3 matrix)."""
    if isinstance(orientation, (EulerAngles, Quaternion, RotationSequence)):
        return orientation.matrix
    R = _matrix(orientation, where="orientation")
    if R.shape != (3, 3):
        raise ValueError(f"an orientation must be a 3x3 rotation matrix, got shape {R.shape}")
    return R


def _vee(W: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def _compact(e):
    """Cheap, bounded simplification of an angular-velocity component: expand, Pythagorean cleanup,
    and ``trigsimp`` only on small results (it is slow on long chains of rotations)."""
    from ..derive.lagrange import _pythagoras

    e = _pythagoras(e)
    if sp.count_ops(e) < 60:
        e = trigsimp(e)
    return e


def body_angular_velocity(orientation) -> sp.Matrix:
    """ω along the body axes: closed forms for EulerAngles, Quaternion and RotationSequence, ``vee(Rᵀ Ṙ)``
    otherwise."""
    if isinstance(orientation, (EulerAngles, Quaternion, RotationSequence)):
        return orientation.body_angular_velocity()
    R = as_rotation(orientation)
    return _vee(R.T * time_derivative(R)).applyfunc(_compact)


def space_angular_velocity(orientation) -> sp.Matrix:
    """ω along the inertial axes, ``R ω_body``."""
    if isinstance(orientation, RotationSequence):
        return orientation.space_angular_velocity()
    return (as_rotation(orientation) * body_angular_velocity(orientation)).applyfunc(_compact)
