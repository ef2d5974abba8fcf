r"""Static equilibria (Wells ch. 10), also of constrained systems.

At rest (``q̇ = 0``) Lagrange's equations ``M q̈ = f + Aᵀλ`` give the equilibrium conditions

.. math:: f(q, 0) + A(q)^T\lambda = 0,\qquad \varphi_k(q) = 0\ \text{(holonomic)},\qquad
          b_k(q) = 0\ \text{(non-holonomic rows: rest must satisfy } A\dot q + b = 0),

``n + p (+ …)`` equations in the unknowns ``q`` and the multipliers ``λ`` (the constraint forces that hold
the equilibrium; their sign follows the way φ is written, see :mod:`lagrange.model.constraints`). Without
constraints they reduce to ``f(q, 0) = 0`` (``∂V/∂q = F_q`` at rest).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import scipy.optimize
import sympy as sp

from ..conventions import t
from ..errors import AnalysisError, LagrangeError
from ..model.coordinates import canonical_key, coordinate_name, position_symbol, to_functions
from ..safe_sympify import sympify as _sympify
from ..simplification import solve

__all__ = ["Equilibrium", "equilibrium_equations", "equilibria"]


class Equilibrium(dict):
    """One equilibrium ``{coordinate: value}``; ``multipliers`` is ``{constraint name: λ}`` (empty when
    unconstrained)."""

    def __init__(self, values: Mapping, multipliers: Mapping | None = None):
        super().__init__(values)
        self.multipliers = dict(multipliers or {})

    def __repr__(self) -> str:
        extra = f", multipliers={self.multipliers}" if self.multipliers else ""
        return f"Equilibrium({dict.__repr__(self)}{extra})"

    def _repr_latex_(self) -> str:
        from ..display import equilibrium_latex

        return equilibrium_latex(self)


def _conditions(system) -> tuple[list, list]:
    """The equilibrium conditions (in symbols) and the unknowns (positions, then multipliers)."""
    eqs = system.derived
    if eqs.is_rough:
        raise AnalysisError("equilibria of systems with rough (Coulomb-friction) constraints are not supported "
                            "(static friction is not modelled)")
    rest = {v: 0 for v in eqs.qd}
    conds = [_sympify(e).subs(rest) for e in eqs.forcing]
    if not eqs.m:
        return conds, list(eqs.q)
    moving = [nm for nm, ph, b in zip(eqs.constraint_names, eqs.constraint_positions, eqs.constraint_bias)
              if t in _sympify(b).free_symbols or (ph is not None and t in _sympify(ph).free_symbols)]
    if moving:
        raise AnalysisError(f"a system with moving (explicit-time) constraints ({', '.join(moving)}) has no static "
                            "equilibrium: eliminate the constraint or write it in a moving frame")
    A = sp.Matrix(eqs.constraint_matrix)
    lam = sp.Matrix(eqs.multipliers)
    conds = [e + r for e, r in zip(conds, A.T * lam)]
    for ph, b in zip(eqs.constraint_positions, eqs.constraint_bias):
        if ph is not None:
            conds.append(_sympify(ph))
        elif _sympify(b) != 0:
            conds.append(_sympify(b))
    return conds, list(eqs.q) + list(eqs.multipliers)


def equilibrium_equations(system) -> list:
    """The static equilibrium conditions ``f(q, q̇ = 0) = 0`` (= ∂V/∂q − F_q at rest), one per coordinate,
    in the coordinate functions; for a constrained system ``f + Aᵀλ = 0`` (with the multiplier symbols) and
    then the position constraints ``φ(q) = 0``."""
    conds, _ = _conditions(system)
    return [to_functions(sp.expand(-e) if k < system.derived.n else e, system.coordinates)
            for k, e in enumerate(conds)]


def equilibria(system, params: Mapping | None = None, guess: Mapping | None = None, *, symbolic: bool = True):
    """Static equilibria, with the constraint forces for a constrained system.

    With ``params is None`` and ``symbolic`` the conditions are solved with sympy: a list of
    :class:`Equilibrium` (possibly several; a family keeps free symbols). Otherwise they are solved
    numerically (``scipy.optimize.root``, least squares when there are more unknowns than equations) from
    ``guess`` (coordinate values and optionally multipliers by constraint name; default 0), returning one
    :class:`Equilibrium` with float values.

    Raises :class:`~lagrange.errors.LagrangeError` when the root finder does not converge or the conditions
    are singular at the guess, and :class:`~lagrange.errors.AnalysisError` for rough or moving constraints.
    """
    eqs = system.derived
    conds, unknowns = _conditions(system)
    n = eqs.n
    names = dict(zip(eqs.multipliers, eqs.constraint_names))
    if params is None and symbolic:
        sols = solve(conds, unknowns, dict=True, what="the equilibrium conditions")
        out = []
        for s in sols:
            q = {c: s.get(position_symbol(c), position_symbol(c)) for c in system.coordinates}
            out.append(Equilibrium(q, {names[lm]: s.get(lm, lm) for lm in eqs.multipliers}))
        return out
    by_name = {getattr(k, "name", str(k)): _sympify(v, where=f"parameter {getattr(k, 'name', k)}")
               for k, v in (params or {}).items()}
    sub = {s: by_name[s.name] for s in eqs.parameters if s.name in by_name}
    t0 = float(by_name.get("t", 0.0))
    conds = [_sympify(c).subs(sub).subs(t, t0) for c in conds]
    free = set().union(*[c.free_symbols for c in conds]) - set(unknowns)
    if free:
        raise LagrangeError(f"missing parameter values for {sorted(map(str, free))}")
    f = sp.lambdify([unknowns], conds, "numpy")
    x0 = np.zeros(len(unknowns))
    if guess:
        for k, v in guess.items():
            key = canonical_key(k, system.coordinates)  # dynamicsymbols
            for i, c in enumerate(system.coordinates):
                if key in (c, coordinate_name(c), position_symbol(c)):
                    x0[i] = float(v)
                    break
            else:
                if k in eqs.constraint_names:
                    x0[n + eqs.constraint_names.index(k)] = float(v)
                else:
                    raise AnalysisError(f"guess: {k} is not a coordinate or constraint name")

    def F(x):
        with np.errstate(all="ignore"):
            return np.asarray(f(x), dtype=float)

    r0 = F(x0)
    if not np.all(np.isfinite(r0)):
        raise LagrangeError(f"the equilibrium conditions are singular at the guess "
                            f"{dict(zip(map(str, unknowns), x0))}: give a `guess` on the constraint manifold")
    if len(conds) == len(unknowns):
        res = scipy.optimize.root(F, x0, tol=1e-12)
        x = res.x
    else:
        res = scipy.optimize.least_squares(F, x0, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        x = res.x
    scale = max(1.0, float(np.max(np.abs(r0))))
    rx = F(x)
    if not (np.all(np.isfinite(rx)) and float(np.max(np.abs(rx))) <= 1e-10 * scale):
        raise LagrangeError(f"no equilibrium found from {dict(zip(map(str, unknowns), x0))}: {res.message}")
    return Equilibrium({c: float(v) for c, v in zip(system.coordinates, x[:n])},
                       {names[lm]: float(v) for lm, v in zip(eqs.multipliers, x[n:])})
