r"""Planar rigid bodies: a position, an angle, a mass, a moment of inertia and named points.

A :class:`PlanarBody` moves in the xy plane of the inertial frame. Its reference point O is at
``position = (x, y)`` and its body x axis is turned by ``angle`` θ from the inertial X axis; a point with body
coordinates ``(a, b)`` is at

.. math:: \mathbf r = \mathbf r_O + R(\theta)\begin{pmatrix} a \\ b\end{pmatrix}, \qquad
   R(\theta) = \begin{pmatrix}\cos\theta & -\sin\theta\\ \sin\theta & \cos\theta\end{pmatrix},

and the kinetic energy is that of a rigid body in plane motion (Wells 8.10 with ω = θ̇ k):

.. math:: T = \tfrac12 m\,\dot{\mathbf r}_c^2 + \tfrac12 \bar I\,\dot\theta^2

with c the centre of mass and Ī the moment of inertia about it, perpendicular to the plane.

The body **is** a :class:`~lagrange.model.rigid_body.RigidBody` (origin ``(x, y, 0)``, orientation
``rot_z(θ)``, central inertia ``(0, 0, Ī)`` moved to O by the parallel-axis theorem), so it takes everything a
rigid body takes: forces at its material points (:class:`~lagrange.Force` at ``body.point("name")``), torques
(:meth:`PlanarBody.torque`), the structural derivation, Gauss' check and the joints of
:mod:`lagrange.model.joints`, which write the loop-closure constraints.

``position`` may also be a material point of another planar body (``position=crank.point("P")``): the body is
then hinged there, a revolute joint written into the kinematics rather than as a constraint (a tree of bodies
in relative coordinates; the loops that close it are the joints).
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from ..errors import DeclarationError
from ..safe_sympify import sympify as _sympify
from .bodies import MaterialPoint
from .coordinates import normalize_time
from .rigid_body import RigidBody, Torque
from .rotations import rot_z

__all__ = ["PlanarBody"]


def _scalar(value, what: str, problems: list):
    """One expression (not a sequence, matrix or string that is not an expression)."""
    if isinstance(value, (sp.MatrixBase, list, tuple, Mapping)):
        problems.append(f"{what} must be one expression, got {value!r}")
        return sp.S.Zero
    try:
        return _finite(normalize_time(_sympify(value)), what, problems)
    except (sp.SympifyError, TypeError, SyntaxError):
        problems.append(f"{what} = {value!r} is not an expression")
        return sp.S.Zero


def _finite(e, what: str, problems: list):
    """``e`` when it is an expression free of nan and infinities, else a problem (and 0)."""
    if not isinstance(e, sp.Expr):
        problems.append(f"{what} = {e!r} is not an expression")
        return sp.S.Zero
    if e.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        problems.append(f"{what} = {e} is not finite")
        return sp.S.Zero
    return e


def _plane_pair(value, what: str, problems: list) -> tuple:
    """``(a, b)`` from 2 components, or 3 whose third is zero; anything out of the plane is refused."""
    if isinstance(value, MaterialPoint):
        comps = list(value.position)
    elif isinstance(value, (sp.MatrixBase, list, tuple)):
        comps = list(value)
    else:
        problems.append(f"{what} must be two expressions (a, b) in the plane, got {value!r}")
        return sp.S.Zero, sp.S.Zero
    if len(comps) not in (2, 3):
        problems.append(f"{what} must have 2 components (x, y in the plane), got {len(comps)}")
        return sp.S.Zero, sp.S.Zero
    out = []
    for c in comps:
        try:
            out.append(_finite(normalize_time(_sympify(c)), what, problems))
        except (sp.SympifyError, TypeError, SyntaxError):
            problems.append(f"{what}: {c!r} is not an expression")
            out.append(sp.S.Zero)
    if len(out) == 3 and out[2] != 0:
        problems.append(f"{what} = {tuple(out)} leaves the plane (z = {out[2]}): a planar body moves in the xy "
                        "plane; give 2 components, or use RigidBody for spatial motion")
    return out[0], out[1]


class PlanarBody(RigidBody):
    """A rigid body in plane motion.

    Parameters
    ----------
    mass : expression
    inertia : expression
        Moment of inertia about the centre of mass, perpendicular to the plane (one number, not a tensor).
    position : 2 expressions, or a MaterialPoint of another planar body
        Inertial position ``(x, y)`` of the body's reference point O, in the coordinates and t; a material
        point ``other.point("P")`` hinges O there (default: the fixed origin).
    angle : expression
        Angle θ of the body x axis from the inertial X axis (radians, counter-clockwise).
    com : 2 expressions
        Centre of mass in body coordinates, relative to O (default O itself).
    points : mapping ``{name: (a, b)}``
        Named points in body coordinates, relative to O; ``body.point(name)`` is the material point there.
    name : label

    Raises
    ------
    DeclarationError
        Listing every problem: a tensor or sequence for the inertia, a component out of the plane (a third
        component that is not zero), a position that is a point of a spatial rigid body, a point name that is
        not an identifier or a point given by more or fewer than 2 body coordinates.

    Examples
    --------
    >>> from lagrange import PlanarBody, coordinates, parameters
    >>> th = coordinates("theta"); m, l = parameters("m l")
    >>> rod = PlanarBody(m, m*l**2/12, angle=th, com=(l/2, 0), points={"tip": (l, 0)})
    >>> rod.kinetic_energy()
    l**2*m*Derivative(theta(t), t)**2/6
    >>> rod.position_of("tip").T
    Matrix([[l*cos(theta(t)), l*sin(theta(t))]])
    """

    def __init__(self, mass, inertia, position=(0, 0), angle=0, *, com=(0, 0), points: Mapping | None = None,
                 name: str = ""):
        label = f"planar body {name!r}" if name else "planar body"
        problems: list[str] = []
        m = _scalar(mass, f"mass of {label}", problems)
        if isinstance(inertia, (sp.MatrixBase, list, tuple)) or type(inertia).__name__ == "Inertia":
            problems.append(f"inertia of {label} is one moment about the centre of mass, perpendicular to the "
                            f"plane, got {inertia!r}; use RigidBody for a tensor")
            inertia = 0
        I_c = _scalar(inertia, f"inertia of {label}", problems)
        if isinstance(position, MaterialPoint) and not isinstance(position.body, PlanarBody):
            problems.append(f"position of {label} is a point of the spatial rigid body {position.body.name!r}: "
                            "hinge a planar body to a planar body")
        x, y = _plane_pair(position, f"position of {label}", problems)
        theta = _scalar(angle, f"angle of {label}", problems)
        cx, cy = _plane_pair(com, f"centre of mass of {label}", problems)
        named: dict[str, tuple] = {}
        if points is not None and not isinstance(points, Mapping):
            problems.append(f"points of {label} must be a mapping {{name: (a, b)}}, got {points!r}")
            points = {}
        for key, r in (points or {}).items():
            if not isinstance(key, str) or not key.isidentifier():
                problems.append(f"point name {key!r} of {label} is not an identifier")
                continue
            named[key] = _plane_pair(r, f"point {key!r} of {label}", problems)
        if problems:
            raise DeclarationError(problems, subject=label)
        # the central inertia (0, 0, Ī) moved to O: J_O = J_c + m(|c|² E − c cᵀ), the signed tensor
        c = sp.Matrix([cx, cy, 0])
        J_O = sp.diag(0, 0, I_c) + m * ((c.T * c)[0, 0] * sp.eye(3) - c * c.T)
        super().__init__(m, J_O, (x, y, 0), rot_z(theta), (cx, cy, 0), name)
        self.angle = theta
        self.moment = I_c
        self.points = named

    # --- points -----------------------------------------------------------------------------------
    def point(self, r_body) -> MaterialPoint:
        """The material point named ``r_body`` (a key of ``points``), or at body coordinates ``(a, b)``.

        Raises
        ------
        DeclarationError
            An unknown name (the known ones are listed) or body coordinates out of the plane.
        """
        if isinstance(r_body, str):
            if r_body not in self.points:
                known = ", ".join(self.points) or "none"
                raise DeclarationError(f"no point named {r_body!r} (its points: {known}); name points with "
                                       "PlanarBody(..., points={'P': (a, b)})", subject=f"planar body {self.name!r}")
            a, b = self.points[r_body]
        else:
            problems: list[str] = []
            a, b = _plane_pair(r_body, f"a point of planar body {self.name!r}", problems)
            if problems:
                raise DeclarationError(problems, subject=f"planar body {self.name!r}")
        return MaterialPoint(self, (a, b, 0))

    def position_of(self, r_body) -> sp.Matrix:
        """Inertial ``(X, Y)`` (shape (2, 1)) of the point named ``r_body`` or at body coordinates ``(a, b)``."""
        return self.point(r_body).position[:2, 0]

    def point_name(self, point: MaterialPoint) -> str:
        """``"body.P"`` for a named point of this body, else ``"body(a, b)"`` (for messages and joint names)."""
        r = tuple(point.r_body[:2])
        for key, value in self.points.items():
            if tuple(value) == r:
                return f"{self.name or 'body'}.{key}"
        return f"{self.name or 'body'}({r[0]}, {r[1]})"

    def torque(self, tau) -> Torque:
        """The torque ``tau`` (counter-clockwise, about the plane's normal) on this body: ``F_θ = τ ∂θ̇/∂q̇``."""
        problems: list[str] = []
        value = _scalar(tau, f"torque on planar body {self.name!r}", problems)
        if problems:
            raise DeclarationError(problems, subject=f"planar body {self.name!r}")
        return Torque(self, (0, 0, value), frame="inertial")

    # --- protocol ---------------------------------------------------------------------------------
    def subs(self, mapping) -> PlanarBody:
        """The body with ``mapping`` substituted (then ``doit``)."""

        def s(e):
            return _sympify(e).subs(mapping).doit()

        return PlanarBody(s(self.mass), s(self.moment), (s(self.origin[0]), s(self.origin[1])), s(self.angle),
                          com=(s(self.com[0]), s(self.com[1])),
                          points={k: (s(a), s(b)) for k, (a, b) in self.points.items()}, name=self.name)

    def __repr__(self) -> str:
        label = f" {self.name!r}" if self.name else ""
        return f"PlanarBody{label}(mass={self.mass}, inertia={self.moment})"

