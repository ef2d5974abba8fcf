"""The plain ``sympy.physics.mechanics`` route for planar N-link pendulums — what a user writes without lagrange.

``LagrangesMethod`` derives ``M`` and ``f`` (dynamicsymbols, then ``msubs`` to plain symbols), ``lambdify``
(numpy, ``cse=True``) generates them, ``numpy.linalg.solve`` solves ``M q̈ = f`` inside the rhs, and
``scipy.integrate.solve_ivp`` integrates. The same model as :func:`lagrange.examples.n_link_pendulum`
(unit masses and rods, absolute angles from the downward vertical, parameter g).

:func:`kane_pendulum_route` is the same model through ``KanesMethod`` (generalized speeds ``u_i = q̇_i``, each
bob's velocity built from the one before it), sympy's faster formulation for chains.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np
import sympy as sp

__all__ = ["plain_pendulum_route", "kane_pendulum_route"]


def plain_pendulum_route(n: int, g: float = 9.81, *, cse: bool = True) -> tuple[float, float, Callable]:
    """Build the plain-sympy rhs of the N-link pendulum (``cse``: lambdify's common-subexpression option;
    ``benchmarks/nlink.py`` measures the plainest route, without it).

    Returns
    -------
    derive_s : seconds spent in ``LagrangesMethod`` (and ``msubs``)
    build_s : seconds spent in ``lambdify``
    rhs : ``rhs(t, y) -> ndarray (2n,)`` with ``y = [q, q̇]``

    >>> _, _, rhs = plain_pendulum_route(1)
    >>> bool(np.isclose(rhs(0.0, np.array([0.5, 0.0]))[1], -9.81 * np.sin(0.5)))
    True
    """
    from sympy.physics.mechanics import (
        LagrangesMethod,
        Lagrangian,
        Particle,
        Point,
        ReferenceFrame,
        dynamicsymbols,
        msubs,
    )

    t0 = time.perf_counter()
    q = dynamicsymbols(f"q1:{n + 1}")
    u = [qi.diff() for qi in q]
    gs = sp.Symbol("g")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    parts, prev = [], O
    for i in range(n):
        P = prev.locatenew(f"P{i}", sp.sin(q[i]) * N.x - sp.cos(q[i]) * N.y)
        P.set_vel(N, P.pos_from(O).dt(N))
        pa = Particle(f"pa{i}", P, 1)
        pa.potential_energy = gs * P.pos_from(O).dot(N.y)
        parts.append(pa)
        prev = P
    lm = LagrangesMethod(Lagrangian(N, *parts), q)
    lm.form_lagranges_equations()
    qs, us = sp.symbols(f"q0:{n}"), sp.symbols(f"u0:{n}")
    rep = dict(zip(u, us)) | dict(zip(q, qs))
    M, f = msubs(lm.mass_matrix, rep), msubs(lm.forcing, rep)
    t1 = time.perf_counter()
    rhs = _lambdified_rhs(M, f, qs, us, gs, g, cse)
    return t1 - t0, time.perf_counter() - t1, rhs


def kane_pendulum_route(n: int, g: float = 9.81, *, cse: bool = True) -> tuple[float, float, Callable]:
    """The N-link pendulum through ``sympy.physics.mechanics.KanesMethod``: ``u_i = q̇_i``, bob i's velocity
    ``v_{i−1} + u_i (cos q_i, sin q_i)``, gravity ``−g`` on each unit mass; ``kanes_equations`` gives
    ``M(q) u̇ = f(q, u)``, generated with ``lambdify`` (numpy, ``cse``) and solved with ``numpy.linalg.solve``.

    Returns ``(derive_s, build_s, rhs)`` as :func:`plain_pendulum_route`.

    >>> _, _, rhs = kane_pendulum_route(1)
    >>> bool(np.isclose(rhs(0.0, np.array([0.5, 0.0]))[1], -9.81 * np.sin(0.5)))
    True
    """
    from sympy.physics.mechanics import KanesMethod, Particle, Point, ReferenceFrame, dynamicsymbols

    t0 = time.perf_counter()
    q = dynamicsymbols(f"q1:{n + 1}")
    u = dynamicsymbols(f"u1:{n + 1}")
    gs = sp.Symbol("g")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    parts, forces, prev = [], [], O
    for i in range(n):
        P = prev.locatenew(f"P{i}", sp.sin(q[i]) * N.x - sp.cos(q[i]) * N.y)
        P.set_vel(N, prev.vel(N) + u[i] * (sp.cos(q[i]) * N.x + sp.sin(q[i]) * N.y))
        parts.append(Particle(f"pa{i}", P, 1))
        forces.append((P, -gs * N.y))
        prev = P
    kane = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u)])
    kane.kanes_equations(parts, forces)
    qs, us = sp.symbols(f"q0:{n}"), sp.symbols(f"u0:{n}")
    rep = dict(zip(u, us)) | dict(zip(q, qs))
    M, f = kane.mass_matrix.xreplace(rep), kane.forcing.xreplace(rep)
    t1 = time.perf_counter()
    rhs = _lambdified_rhs(M, f, qs, us, gs, g, cse)
    return t1 - t0, time.perf_counter() - t1, rhs


def _lambdified_rhs(M, f, qs, us, gs, g: float, cse: bool) -> Callable:
    """``rhs(t, y)`` of ``M(q, u) u̇ = f(q, u)`` with y = (q, u): M and f by ``lambdify`` (numpy, ``cse``),
    ``numpy.linalg.solve`` at each call — what a user of sympy.physics.mechanics writes."""
    n = len(qs)
    fM = sp.lambdify((qs, us, gs), M, modules="numpy", cse=cse)
    ff = sp.lambdify((qs, us, gs), f, modules="numpy", cse=cse)

    def rhs(t, y):
        acc = np.linalg.solve(np.asarray(fM(y[:n], y[n:], g), dtype=float),
                              np.asarray(ff(y[:n], y[n:], g), dtype=float).ravel())
        return np.concatenate([y[n:], acc])

    return rhs
