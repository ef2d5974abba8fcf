r"""Joints: the loop-closure constraints of a mechanism, written from its bodies' points.

Each helper returns a tuple of :class:`~lagrange.Holonomic` constraints ``φ(q, t) = 0`` for
``System(constraints=...)`` (a tuple may be given there as it is: ``constraints=[revolute(a, b), pin(c)]``).
Points are material points of bodies (``body.point("P")``, :class:`~lagrange.model.bodies.MaterialPoint`) or,
where a helper says so, particles and fixed positions. The multipliers follow :mod:`lagrange.model.constraints`:
``λ`` of a component of a joint is the force along that inertial axis that the joint exerts on the first
point's body (and minus it on the second's).

Planar (:class:`~lagrange.model.planar.PlanarBody`, motion in the xy plane):

* :func:`revolute` — two bodies' points coincide (2 equations: x, y);
* :func:`slider` — a prismatic joint: a point of one body stays on a line of another body (or of the ground)
  and the two keep their relative angle (2 equations);
* :func:`pin` — a point fixed to the ground (2 equations; 3 for a spatial body);
* :func:`on_line` — a point stays on a fixed line (1 equation: a pin in a slot).

Spatial (:class:`~lagrange.RigidBody`): :func:`spherical` (two bodies' points coincide, 3 equations) and
:func:`pin`.

A component that vanishes identically — already implied by the bodies' positions, as when a body is hinged
through ``PlanarBody(position=other.point("P"))`` — is left out (proved zero by
:func:`lagrange.simplification.is_zero`); what remains are the closures. Springs and dampers between points
(:func:`spring_potential`, :func:`damper_power`) give the V and P terms Wells writes for them.

References: E. J. Haug, *Computer-Aided Kinematics and Dynamics of Mechanical Systems* (1989), ch. 3 (the
planar joints as constraints in body coordinates); Wells, *Lagrangian Dynamics*, ch. 12 (multipliers).
"""

from __future__ import annotations

import sympy as sp

from ..errors import DeclarationError
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, simplify
from .bodies import MaterialPoint, Particle
from .constraints import Holonomic
from .coordinates import normalize_time, time_derivative
from .planar import PlanarBody, _finite

__all__ = ["revolute", "slider", "pin", "on_line", "spherical", "spring_potential", "damper_power"]

_AXES = "xyz"


def _label(p) -> str:
    if isinstance(p, MaterialPoint):
        if isinstance(p.body, PlanarBody):
            return p.body.point_name(p)
        return f"{p.body.name or 'body'}{tuple(p.r_body)}"
    if isinstance(p, Particle):
        return p.name or "particle"
    return str(tuple(p))


def _body_point(p, joint: str, which: str, problems: list, *, planar: bool) -> MaterialPoint | None:
    """``p`` as a material point of a (planar, when ``planar``) rigid body, else a problem."""
    if not isinstance(p, MaterialPoint):
        what = "a body's point" + (" (planar_body.point('P'))" if planar else " (body.point(r))")
        problems.append(f"the {which} point {p!r} is not {what}; a point fixed to the ground is pin()")
        return None
    if planar and not isinstance(p.body, PlanarBody):
        problems.append(f"the {which} point is on the spatial rigid body {p.body.name!r}; a revolute "
                        "or slider joint here is planar (PlanarBody); two spatial bodies' points are joined by "
                        "spherical()")
        return None
    if planar and p.r_body[2] != 0:
        problems.append(f"the {which} point {tuple(p.r_body)} leaves the plane (z ≠ 0)")
        return None
    return p


def _two_bodies(p, q, joint: str, problems: list) -> None:
    if p is not None and q is not None and p.body is q.body:
        problems.append(f"both points are on body {p.body.name or p.body!r}; a joint connects two "
                        "different bodies (a point of a body fixed to the ground is pin())")


def _position(p, what: str, problems: list) -> sp.Matrix | None:
    if isinstance(p, (MaterialPoint, Particle)):
        return p.position
    if isinstance(p, (sp.MatrixBase, list, tuple)) and 1 <= len(p) <= 3:
        try:
            comps = [_finite(normalize_time(_sympify(c)), what, problems) for c in p]
        except (sp.SympifyError, TypeError, SyntaxError):
            problems.append(f"{what} = {p!r} is not a position (1 to 3 expressions)")
            return None
        return sp.Matrix(comps + [sp.S.Zero] * (3 - len(comps)))
    problems.append(f"{what} = {p!r} is not a point (a body's point, a particle or 1 to 3 expressions)")
    return None


def _closures(differences, name: str) -> tuple[Holonomic, ...]:
    """One Holonomic per component that is not identically zero."""
    out = []
    for axis, d in differences:
        if not is_zero(d):
            out.append(Holonomic(d, f"{name} ({axis})" if axis else name))
    return tuple(out)


def _raise(problems: list, joint: str) -> None:
    if problems:
        raise DeclarationError(problems, subject=joint)


def revolute(p: MaterialPoint, q: MaterialPoint, name: str = "") -> tuple[Holonomic, ...]:
    r"""A revolute joint: point ``p`` of one planar body and point ``q`` of another coincide,
    :math:`\mathbf r_p - \mathbf r_q = 0` (x and y).

    Raises
    ------
    DeclarationError
        A point that is not a planar body's point, both points on the same body, a point out of the plane.

    Examples
    --------
    >>> from lagrange import PlanarBody, coordinates, revolute
    >>> a, b = coordinates("a b")
    >>> crank = PlanarBody(1, 1, angle=a, points={"P": (1, 0)}, name="crank")
    >>> rod = PlanarBody(1, 1, (2, 0), angle=b, points={"Q": (-1, 0)}, name="rod")
    >>> [c.expr for c in revolute(crank.point("P"), rod.point("Q"))]
    [cos(a(t)) + cos(b(t)) - 2, sin(a(t)) + sin(b(t))]
    """
    return _coincident(p, q, "revolute", name, planar=True)


def spherical(p: MaterialPoint, q: MaterialPoint, name: str = "") -> tuple[Holonomic, ...]:
    r"""A spherical (ball) joint: points ``p`` and ``q`` of two rigid bodies coincide,
    :math:`\mathbf r_p - \mathbf r_q = 0` (x, y and z; a component zero by construction is left out)."""
    return _coincident(p, q, "spherical", name, planar=False)


def _coincident(p, q, kind: str, name: str, *, planar: bool) -> tuple[Holonomic, ...]:
    """Points ``p`` and ``q`` of two bodies coincide: x and y (``planar``), or x, y and z."""
    problems: list[str] = []
    joint = f"{kind} joint {name!r}" if name else f"{kind} joint"
    p = _body_point(p, joint, "first", problems, planar=planar)
    q = _body_point(q, joint, "second", problems, planar=planar)
    _two_bodies(p, q, joint, problems)
    _raise(problems, joint)
    name = name or f"{kind} {_label(p)}-{_label(q)}"
    d = p.position - q.position
    return _closures([(_AXES[i], d[i]) for i in range(2 if planar else 3)], name)


def pin(p, at=(0, 0), name: str = "") -> tuple[Holonomic, ...]:
    r"""A point fixed to the ground: :math:`\mathbf r_p - \mathbf r_{at} = 0`, x and y for a planar body's
    point (``at`` has 2 components), x, y and z for a spatial body's point or a particle.

    ``at`` may depend on t (a point moved along a prescribed path).

    >>> from lagrange import PlanarBody, coordinates, pin
    >>> x, y, th = coordinates("x y th")
    >>> rod = PlanarBody(1, 1, (x, y), th, points={"O": (-1, 0)}, name="rod")
    >>> [c.expr for c in pin(rod.point("O"), (0, 2))]
    [x(t) - cos(th(t)), y(t) - sin(th(t)) - 2]
    """
    problems: list[str] = []
    joint = f"pin {name!r}" if name else "pin"
    if not isinstance(p, (MaterialPoint, Particle)):
        problems.append(f"{p!r} is not a body's point or a particle")
    where = _position(at, "at", problems)
    _raise(problems, joint)
    planar = isinstance(p, MaterialPoint) and isinstance(p.body, PlanarBody)
    if planar and where[2] != 0:
        problems.append(f"at = {tuple(where)} leaves the plane of planar body {p.body.name!r}")
    _raise(problems, joint)
    d = p.position - where
    name = name or f"pin {_label(p)}"
    return _closures([(_AXES[i], d[i]) for i in range(2 if planar else 3)], name)


def _unit(direction, what: str, problems: list) -> tuple | None:
    pos = _position(direction, what, problems)
    if pos is None:
        return None
    if pos[2] != 0:
        problems.append(f"{what} = {tuple(pos)} leaves the plane")
        return None
    nx, ny = pos[0], pos[1]
    if nx == 0 and ny == 0:
        problems.append(f"{what} is the zero vector")
        return None
    norm = sp.sqrt(nx**2 + ny**2)
    return simplify(nx / norm), simplify(ny / norm)


def on_line(p, through=(0, 0), direction=(1, 0), name: str = "") -> tuple[Holonomic, ...]:
    r"""A point on a fixed line of the plane (a pin in a slot): with u the unit ``direction``,
    :math:`u \times (\mathbf r_p - \mathbf r_{through}) = u_x (y_p - y_0) - u_y (x_p - x_0) = 0`.

    Its multiplier is the slot's force on the point, along the normal ``(−u_y, u_x)``.
    """
    problems: list[str] = []
    joint = f"on_line {name!r}" if name else "on_line"
    if not isinstance(p, (MaterialPoint, Particle)):
        problems.append(f"{p!r} is not a body's point or a particle")
    base = _position(through, "through", problems)
    u = _unit(direction, "direction", problems)
    _raise(problems, joint)
    d = p.position - base
    name = name or f"on_line {_label(p)}"
    return _closures([("", u[0] * d[1] - u[1] * d[0])], name)


def slider(guide, follower: MaterialPoint, axis=(1, 0), angle=0, name: str = "") -> tuple[Holonomic, ...]:
    r"""A prismatic joint: the ``follower`` point of one planar body slides along the line through the
    ``guide`` point along ``axis``, and the two bodies keep the relative angle ``angle``.

    ``guide`` is a point of another planar body (``axis`` in that body's coordinates: "along the body's
    axis") or a fixed position (``axis`` in inertial components: a slider on the ground). With e the unit axis
    turned with the guide body (θ_g = 0 for the ground):

    .. math:: e \times (\mathbf r_f - \mathbf r_g) = 0, \qquad \theta_f - \theta_g - \text{angle} = 0.

    Raises
    ------
    DeclarationError
        A follower that is not a planar body's point, guide and follower on the same body, a zero axis.
    """
    problems: list[str] = []
    joint = f"slider {name!r}" if name else "slider"
    f = _body_point(follower, joint, "follower", problems, planar=True)
    if isinstance(guide, MaterialPoint):
        g = _body_point(guide, joint, "guide", problems, planar=True)
        _two_bodies(g, f, joint, problems)
        base = g.position if g is not None else None
        theta_g = g.body.angle if g is not None else sp.S.Zero
    else:
        base = _position(guide, "guide", problems)
        theta_g = sp.S.Zero
        if base is not None and base[2] != 0:
            problems.append(f"the guide position {tuple(base)} leaves the plane")
    u = _unit(axis, "axis", problems)
    if isinstance(angle, (list, tuple, sp.MatrixBase)):
        problems.append(f"angle must be one expression, got {angle!r}")
    _raise(problems, joint)
    rel = _coefficient(angle, "angle", joint)
    ex = u[0] * sp.cos(theta_g) - u[1] * sp.sin(theta_g)
    ey = u[0] * sp.sin(theta_g) + u[1] * sp.cos(theta_g)
    d = f.position - base
    name = name or f"slider {_label(guide) if isinstance(guide, MaterialPoint) else 'ground'}-{_label(f)}"
    return _closures([("line", ex * d[1] - ey * d[0]), ("angle", f.body.angle - theta_g - rel)],
                     name)


def _separation(p, q, what: str) -> sp.Matrix:
    problems: list[str] = []
    a = _position(p, "first point", problems)
    b = _position(q, "second point", problems)
    _raise(problems, what)
    return a - b


def _coefficient(value, what: str, subject: str):
    problems: list[str] = []
    try:
        e = _finite(normalize_time(_sympify(value)), what, problems)
    except (sp.SympifyError, TypeError, SyntaxError):
        problems.append(f"{what} = {value!r} is not an expression")
    _raise(problems, subject)
    return e


def spring_potential(p, q, k, rest_length=0) -> sp.Expr:
    r"""Potential energy of a linear spring of stiffness ``k`` and free length ``rest_length`` between points
    ``p`` and ``q`` (bodies' points, particles or positions): :math:`V = \tfrac12 k (\ell - \ell_0)^2`,
    :math:`\ell = |\mathbf r_p - \mathbf r_q|`. Add it to ``V``.

    >>> from lagrange import coordinates, spring_potential
    >>> x = coordinates("x")
    >>> spring_potential((x, 0), (0, 0), 3)
    3*x(t)**2/2
    """
    d = _separation(p, q, "spring")
    k, l0 = _coefficient(k, "stiffness", "spring"), _coefficient(rest_length, "rest length", "spring")
    sq = (d.T * d)[0, 0]
    if l0 == 0:
        return sp.Rational(1, 2) * k * sq
    return sp.Rational(1, 2) * k * (sp.sqrt(sq) - l0) ** 2


def damper_power(p, q, c) -> sp.Expr:
    r"""Wells' power function of a linear damper ``c`` between points ``p`` and ``q``:
    :math:`P = -\tfrac12 c\,\dot\ell^2` with :math:`\dot\ell = \mathbf d\cdot\dot{\mathbf d}/|\mathbf d|`,
    :math:`\mathbf d = \mathbf r_p - \mathbf r_q` (``F = ∂P/∂q̇ = −c ℓ̇ ∂ℓ/∂q``). Add it to ``P``.

    The velocity of a body's point is the body's velocity field (:class:`~lagrange.model.bodies.MaterialPoint`).
    """
    problems: list[str] = []
    what = "damper"
    vel = []
    for which, x in (("first", p), ("second", q)):
        if isinstance(x, MaterialPoint):
            vel.append(x.velocity)
        elif isinstance(x, Particle):
            vel.append(x.velocity)
        else:
            pos = _position(x, f"{which} point", problems)
            vel.append(time_derivative(pos) if pos is not None else None)
    _raise(problems, what)
    d = _separation(p, q, what)
    dd = vel[0] - vel[1]
    c = _coefficient(c, "damping coefficient", "damper")
    return -c * (d.T * dd)[0, 0] ** 2 / (2 * (d.T * d)[0, 0])

