r"""Driving forces for a prescribed motion, and statics (Wells ch. 13).

Given the motion ``q(t)`` of every coordinate, the generalized forces that must act besides the
declared ones follow from Lagrange's equations (Wells 13.1):

.. math:: F'_r = \frac{d}{dt}\frac{\partial T}{\partial\dot q_r} - \frac{\partial T}{\partial q_r}
          + \frac{\partial V}{\partial q_r} - F_{q_r} - \frac{\partial P}{\partial\dot q_r}.

Actuator forces ``f_1..f_k`` enter F′ linearly through their virtual work (e.g. Ex. 13.4: ``F'_s = f_1 − f_2``,
``F'_x = f_2``); :func:`actuator_forces` solves for them. Statics: the same equations at rest,
:func:`static_equilibrium` solves them for any unknowns (positions, forces, angles), symbolically or with
a root finder when transcendental.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import scipy.optimize
import sympy as sp

from ..conventions import t
from ..errors import LagrangeError
from ..model.coordinates import to_functions, to_symbols
from ..simplification import simplify, solve

__all__ = ["driving_forces", "actuator_forces", "static_equilibrium"]


def driving_forces(system, motion: Mapping) -> dict:
    """``{q: F'_q(t)}`` needed to produce ``motion = {q: q(t)}`` (every coordinate), Wells (13.1)."""
    missing = [q for q in system.coordinates if q not in motion]
    if missing:
        raise LagrangeError(f"the prescribed motion must give every coordinate; missing {missing}")
    out = {}
    for q, eq in zip(system.coordinates, system.equations()):
        residual = eq.lhs - eq.rhs
        sub = {}
        for c in system.coordinates:
            sub[c.diff(t, 2)] = sp.diff(motion[c], t, 2)
            sub[c.diff(t)] = sp.diff(motion[c], t)
        e = residual.subs(sub).subs({c: motion[c] for c in system.coordinates})
        out[q] = simplify(e, limit=299)
    return out


def actuator_forces(system, virtual_work, unknowns: Sequence, motion: Mapping | None = None) -> dict:
    """Solve for actuator forces ``unknowns`` whose virtual work ``virtual_work`` (written with
    :func:`~lagrange.delta`) produces the system's motion — the prescribed ``motion`` if given, else the
    equations in terms of q, q̇, q̈."""
    from ..model.forces import generalized_forces

    problems: list = []
    Fp = generalized_forces(virtual_work, system.coordinates, problems)
    if problems:
        raise LagrangeError("; ".join(problems))
    if motion is not None:
        need = driving_forces(system, motion)
    else:
        need = {q: eq.lhs - eq.rhs for q, eq in zip(system.coordinates, system.equations())}
    eqs = [sp.Eq(Fp[q], need[q]) for q in system.coordinates]
    sol = solve(eqs, list(unknowns), dict=True, what="the driving-force equations")
    if len(sol) != 1:
        raise LagrangeError(f"the actuator forces {list(unknowns)} are not determined uniquely ({len(sol)} solutions)")
    return {u: simplify(sol[0][u]) for u in unknowns}


def static_equilibrium(system, unknowns: Sequence, params: Mapping | None = None, guess: Mapping | None = None):
    """Solve the equilibrium conditions (all velocities and accelerations zero) for ``unknowns``
    (coordinates or parameters such as an applied force). Symbolic without ``params``; with ``params``
    numeric values are substituted and ``scipy.optimize.root`` is used from ``guess``."""
    eqs = system.derived
    rest = {v: 0 for v in eqs.qd}
    conds = [sp.sympify(e).subs(rest) for e in eqs.forcing]
    unk = [to_symbols(u, system.coordinates) for u in unknowns]
    if params is None:
        sols = solve(conds, unk, dict=True, what="the equilibrium conditions")
        return [{u: to_functions(s[to_symbols(u, system.coordinates)], system.coordinates) for u in unknowns
                 if to_symbols(u, system.coordinates) in s} for s in sols]
    by_name = {getattr(k, "name", str(k)): v for k, v in params.items()}
    sub = {s: by_name[s.name] for c in conds for s in c.free_symbols if s.name in by_name and s not in unk}
    f = sp.lambdify([unk], [c.subs(sub) for c in conds], "numpy")
    x0 = np.array([float((guess or {}).get(u, 0.0)) for u in unknowns])
    def F(x):
        v = np.asarray(f(x), dtype=float)
        return v[: len(unk)] if len(conds) > len(unk) else v

    res = scipy.optimize.root(F, x0, tol=1e-12)
    scale = max(1.0, float(np.max(np.abs(F(x0)))))
    if not (res.success or float(np.max(np.abs(F(res.x)))) <= 1e-10 * scale):
        raise LagrangeError(f"static equilibrium not found from {dict(zip(map(str, unknowns), x0))}: {res.message}")
    return dict(zip(unknowns, (float(v) for v in res.x)))
