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

__all__ = ["variant", "planar_point", "planar_point_velocity", "rod_from_end", "dry_friction_along_rod",
           "spinning_disc_friction"]


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


def spinning_disc_friction(eps):
    r"""Closed forms of the dry friction on a uniform disc (radius R, normal load N, friction coefficient μ)
    sliding at speed v and spinning at ω on a plane, as functions of :math:`\varepsilon = v/(R\omega)`
    (Farkas, Bartels, Unger & Wolf, Phys. Rev. Lett. 90, 248302 (2003), eq. (2)): the force
    :math:`F = \mu N\,\mathcal F(\varepsilon)` against the sliding and the torque :math:`\mu N R\,
    \mathcal T(\varepsilon)` against the spin, with E, K the complete elliptic integrals of parameter m = k²:

    .. math::

        \mathcal F = \tfrac{4}{3\pi}\,\frac{(\varepsilon^2+1)E(\varepsilon^2) + (\varepsilon^2-1)K(\varepsilon^2)}
        {\varepsilon},\qquad
        \mathcal T = \tfrac{4}{9\pi}\big[(4-2\varepsilon^2)E(\varepsilon^2) + (\varepsilon^2-1)K(\varepsilon^2)\big]
        \quad(\varepsilon\le 1),

        \mathcal F = \tfrac{4}{3\pi}\big[(\varepsilon^2+1)E(\varepsilon^{-2}) - (\varepsilon^2-1)K(\varepsilon^{-2})\big],
        \quad
        \mathcal T = \tfrac{4}{9\pi}\Big[(4\varepsilon-2\varepsilon^3)E(\varepsilon^{-2})
        + \frac{(\varepsilon^2-1)(2\varepsilon^2-3)}{\varepsilon}K(\varepsilon^{-2})\Big]\quad(\varepsilon\ge 1).

    Returns ``(F, T)`` as sympy Piecewise expressions of ``eps`` (the two branches agree at ε = 1: 8/(3π) and
    8/(9π)). They were checked against the disc taken as rings, each ring's integral of |v| in closed form with E
    (Wells Prob. 6.15), to 1e-14 (``tests/test_quadrature.py``)."""
    e2 = eps**2
    E, K = sp.elliptic_e, sp.elliptic_k
    F = sp.Piecewise((8 / (3 * sp.pi), sp.Eq(eps, 1)),  # (ε² − 1)K: 0·∞ at ε = 1; its limit
                     (4 / (3 * sp.pi) * ((e2 + 1) * E(e2) + (e2 - 1) * K(e2)) / eps, eps <= 1),
                     (4 / (3 * sp.pi) * ((e2 + 1) * E(1 / e2) - (e2 - 1) * K(1 / e2)), True))
    T = sp.Piecewise((8 / (9 * sp.pi), sp.Eq(eps, 1)),
                     (4 / (9 * sp.pi) * ((4 - 2 * e2) * E(e2) + (e2 - 1) * K(e2)), eps <= 1),
                     (4 / (9 * sp.pi) * ((4 * eps - 2 * eps**3) * E(1 / e2)
                                         + (e2 - 1) * (2 * e2 - 3) / eps * K(1 / e2)), True))
    return F, T
