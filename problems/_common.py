"""Shared pieces of the corpus: a variant of a problem states only what differs from its base, and builders for
kinematics several of Wells' problems repeat (a point of a body moving in a plane, a uniform rod given by one end).

Everything here is plain sympy or a public class of the library; a problem file still declares its own System,
so a reader sees the physics (bodies, energies, forces, constraints) where the problem is. The corpus registry
and index skip modules whose name starts with ``_`` (this one holds no problem).
"""

from __future__ import annotations

import dataclasses

import sympy as sp

from lagrange import Particle, t
from lagrange.corpus import Problem

__all__ = ["variant", "planar_point", "planar_point_velocity", "rod_from_end", "dry_friction_along_rod"]


def variant(base: Problem, *, id: str, title: str, source: str, **changes) -> Problem:  # noqa: A002 - Problem's field
    """``base`` with a new id, title and citation and any other field changed (``system``, ``answers``,
    ``correction``, ``simulation``, ``chapter``, …); every other field is the base problem's.

    Use it when a book case restates another one's system (P17.12 derives (14.15) again by Hamilton's principle;
    a problem that reruns an example with other numbers). ``answers`` replaces the base's answers; to keep them
    and add more, pass ``answers=[*base.answers, extra]``. Unknown field names raise ``TypeError``.
    """
    unknown = sorted(set(changes) - {f.name for f in dataclasses.fields(Problem)})
    if unknown:
        raise TypeError(f"variant of {base.id}: unknown Problem field(s) {', '.join(unknown)}")
    return dataclasses.replace(base, id=id, title=title, source=source, **changes)


def planar_point(x, y, theta, a, b):
    """Position ``(X, Y)`` of the point at body coordinates ``(a, b)`` of a body whose body-frame origin is at
    ``(x, y)`` and whose axes are turned by ``theta`` (Wells' (2.1) in the plane)."""
    return (x + a * sp.cos(theta) - b * sp.sin(theta), y + a * sp.sin(theta) + b * sp.cos(theta))


def planar_point_velocity(x, y, theta, a, b):
    """Velocity ``(Ẋ, Ẏ)`` of that point: ``(ẋ − θ̇(a sin θ + b cos θ), ẏ + θ̇(a cos θ − b sin θ))``."""
    X, Y = planar_point(x, y, theta, a, b)
    return (X.diff(t), Y.diff(t))


def rod_from_end(M, l, x, y, theta, name: str = "rod"):
    """A uniform rod (mass ``M``, length ``l``) given by the end ``(x, y)`` and its angle ``theta`` to X:
    its centre of mass as a Particle and its rotational T about the centre, ``M l² θ̇²/24``."""
    cm = planar_point(x, y, theta, l / 2, 0)
    return Particle(M, cm, name=name), M * l**2 * theta.diff(t) ** 2 / 24


def dry_friction_along_rod(f, x, y, theta, lo, hi):
    r"""Closed form of Wells' power function of dry friction ``f`` per unit length along a rod,

    .. math:: P = -f\int_{lo}^{hi} |v(r)|\,dr,\qquad |v(r)|^2 = a r^2 + b r + c,

    with :math:`a = \dot\theta^2`, :math:`b = 2\dot\theta(\dot y\cos\theta - \dot x\sin\theta)`,
    :math:`c = \dot x^2 + \dot y^2` for the point at distance ``r`` from ``(x, y)`` along the rod. The antiderivative
    of :math:`\sqrt{Q}` is :math:`\frac{(2ar+b)\sqrt Q}{4a} + \frac{4ac-b^2}{8a^{3/2}}\ln(2\sqrt a\sqrt Q + 2ar + b)`
    (valid for a > 0, i.e. a turning rod; here :math:`4ac - b^2 = 4\dot\theta^2(\dot x\cos\theta + \dot y\sin\theta)^2`).
    """
    xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
    a = thd**2
    b = 2 * thd * (yd * sp.cos(theta) - xd * sp.sin(theta))
    c = xd**2 + yd**2
    ra = sp.sqrt(a)

    def F(r):
        Q = sp.sqrt(a * r**2 + b * r + c)
        return (2 * a * r + b) * Q / (4 * a) + (4 * a * c - b**2) / (8 * ra**3) * sp.log(2 * ra * Q + 2 * a * r + b)

    return -f * (F(hi) - F(lo))
