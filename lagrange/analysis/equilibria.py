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
from ..limits import bounded
from ..model.coordinates import canonical_key, coordinate_name, position_symbol, to_functions
from ..safe_sympify import expression as _expression
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import solve

__all__ = ["Equilibrium", "equilibrium_equations", "equilibria", "equilibria_near"]


class Equilibrium(dict):
    """One equilibrium ``{coordinate: value}``; ``multipliers`` is ``{constraint name: λ}`` (empty when
    unconstrained)."""

    def __init__(self, values: Mapping, multipliers: Mapping | None = None):
        super().__init__(values)
        self.multipliers = dict(multipliers or {})
        self.free: tuple = ()  # coordinates that appear in no condition (any value is an equilibrium)

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


@bounded("equilibria")
def without_drive_terms(expr):
    """``expr`` expanded, without its terms that depend on t explicitly (a drive ``A sin ωt``): the statics of
    a driven system."""
    return sp.Add(*[a for a in sp.Add.make_args(sp.expand(expr)) if not a.has(t)])


def equilibria(system, params: Mapping | None = None, guess: Mapping | None = None, *, symbolic: bool = True,
               without_drive: bool = False):
    """Static equilibria, with the constraint forces for a constrained system.

    With ``params is None`` and ``symbolic`` the conditions are solved with sympy: a list of
    :class:`Equilibrium` (possibly several; a family keeps free symbols). Otherwise they are solved
    numerically (``scipy.optimize.root``, least squares when there are more unknowns than equations) from
    ``guess`` (coordinate values and optionally multipliers by constraint name; default 0), returning one
    :class:`Equilibrium` with float values.

    ``without_drive`` (symbolic only): the terms of the conditions that depend on t explicitly (a drive
    ``A sin ωt``) are left out, giving the equilibria of the undriven system about which the driven one is
    linearized.

    Raises :class:`~lagrange.errors.LagrangeError` when the root finder does not converge or the conditions
    are singular at the guess, and :class:`~lagrange.errors.AnalysisError` for rough or moving constraints.
    """
    eqs = system.derived
    conds, unknowns = _conditions(system)
    if without_drive and params is None and symbolic:
        conds = [without_drive_terms(c) for c in conds]
    names = dict(zip(eqs.multipliers, eqs.constraint_names))
    if params is None and symbolic:
        sols = solve(conds, unknowns, dict=True, what="the equilibrium conditions")
        out = []
        for s in sols:
            q = {c: s.get(position_symbol(c), position_symbol(c)) for c in system.coordinates}
            out.append(Equilibrium(q, {names[lm]: s.get(lm, lm) for lm in eqs.multipliers}))
        return out
    F, unknowns, x0, fixed = _numeric_problem(system, params, guess, conds, unknowns)
    x, res = _solve_from(F, x0, unknowns, fixed, raise_singular=True)
    if x is None:
        raise LagrangeError(f"no equilibrium found from {dict(zip(map(str, unknowns), x0))}: {res}")
    return _as_equilibrium(system, unknowns, x, fixed)


def _numeric_problem(system, params, guess, conds, unknowns):
    """The conditions as a float function of the unknowns that appear in them, the start vector, and the
    coordinates that appear in no condition (a free family: held at their ``guess`` value)."""
    eqs = system.derived
    n = eqs.n
    by_name = {getattr(k, "name", str(k)): _expression(v, where=f"parameter {getattr(k, 'name', k)}")
               for k, v in (params or {}).items()}
    inputs = tuple(getattr(eqs, "inputs", ()))
    sub = {s: by_name[s.name] for s in eqs.parameters if s.name in by_name}
    sub.update({u: by_name.get(u.name, 0) for u in inputs})  # inputs held at their given value (default 0)
    t0 = float(by_name.get("t", 0.0))
    conds = [_sympify(c).subs(sub).subs(t, t0) for c in conds]
    free = set().union(*[c.free_symbols for c in conds]) - set(unknowns)
    if free:
        raise LagrangeError(f"missing parameter values for {sorted(map(str, free))}")
    x0 = np.zeros(len(unknowns))
    for k, v in (guess or {}).items():
        key = canonical_key(k, system.coordinates)  # dynamicsymbols
        for i, c in enumerate(system.coordinates):
            if key in (c, coordinate_name(c), position_symbol(c)):
                x0[i] = _start_value(k, v)
                break
        else:
            if k in eqs.constraint_names:
                x0[n + eqs.constraint_names.index(k)] = _start_value(k, v)
            else:
                valid = ", ".join([coordinate_name(c) for c in system.coordinates] + list(eqs.constraint_names))
                raise AnalysisError(f"guess: {k} is not a coordinate or constraint name (valid: {valid})")
    used = set().union(*[c.free_symbols for c in conds])
    fixed = {i: x0[i] for i, u in enumerate(unknowns) if u not in used}
    conds = [c for c in conds if c != 0]
    live = [u for i, u in enumerate(unknowns) if i not in fixed]
    f = _lambdify([live], conds, "numpy")

    def F(x):
        with np.errstate(all="ignore"):
            return np.asarray(f(x), dtype=float).ravel()

    keep = np.array([i not in fixed for i in range(len(unknowns))], dtype=bool)
    return F, unknowns, x0, (fixed, keep)


def _start_value(key, value) -> float:
    """A starting value as a finite float; AnalysisError naming the key otherwise (strings are not parsed)."""
    try:
        x = float(value) if not isinstance(value, str) else float("nan")
    except (TypeError, ValueError):
        x = float("nan")
    if not np.isfinite(x):
        raise AnalysisError(f"the starting value of {key} must be a finite number, got {value!r}")
    return x


def _solve_from(F, x0, unknowns, fixed, raise_singular=False):
    """One root-finder run from x0; (x, None) when it converges, else (None, the reason)."""
    fixed_at, keep = fixed
    y0 = x0[keep]
    r0 = F(y0)
    if r0.size == 0:
        return x0.copy(), None
    if not np.all(np.isfinite(r0)):
        if raise_singular:
            raise LagrangeError(f"the equilibrium conditions are singular at the guess "
                                f"{dict(zip(map(str, unknowns), x0))}: give a `guess` on the constraint manifold")
        return None, "singular start"
    if r0.size == y0.size:
        res = scipy.optimize.root(F, y0, tol=1e-12)
    else:
        res = scipy.optimize.least_squares(F, y0, xtol=1e-15, ftol=1e-15, gtol=1e-15)
    scale = max(1.0, float(np.max(np.abs(r0))))
    rx = F(res.x)
    if not (np.all(np.isfinite(rx)) and np.all(np.isfinite(res.x)) and float(np.max(np.abs(rx))) <= 1e-10 * scale):
        return None, res.message
    x = x0.copy()
    x[keep] = res.x
    return x, None


def _as_equilibrium(system, unknowns, x, fixed) -> Equilibrium:
    eqs = system.derived
    n = eqs.n
    names = dict(zip(eqs.multipliers, eqs.constraint_names))
    out = Equilibrium({c: float(v) for c, v in zip(system.coordinates, x[:n])},
                      {names[lm]: float(v) for lm, v in zip(eqs.multipliers, x[n:])})
    out.free = tuple(system.coordinates[i] for i in sorted(fixed[0]) if i < n)
    return out


#: at most this many starting points for :func:`equilibria_near` (the given point, steps along each
#: coordinate, then pseudo-random points from a fixed seed)
MAX_STARTS = 40


def equilibria_near(system, params: Mapping, near: Mapping | None = None) -> list[Equilibrium]:
    r"""The distinct static equilibria found from starting points around ``near``, nearest first.

    The root finder of :func:`equilibria` is run from ``near`` (coordinate values by object or name; default
    0 for each coordinate), from ``near`` moved by ±1 and ±π along each coordinate, and from pseudo-random
    points (fixed seed: the result is reproducible), at most :data:`MAX_STARTS` starts. A coordinate in which
    the conditions are 2π-periodic (an angle) is reported within π of its ``near`` value. The converged
    points are merged when they agree to 1e-6 and sorted by their distance from ``near``. A coordinate
    that appears in no condition (an ignorable coordinate: every value is an equilibrium) is held at its
    ``near`` value and listed in each result's ``free`` attribute. Inputs are held at their value in
    ``params`` (by name; default 0).

    Returns an empty list when no start converges; raises :class:`~lagrange.errors.AnalysisError` for rough
    or moving constraints and :class:`~lagrange.errors.LagrangeError` for missing parameter values.

    Examples
    --------
    >>> import sympy as sp
    >>> from lagrange import Particle, System, coordinates, parameters
    >>> th = coordinates("theta"); m, g, l = parameters("m g l")
    >>> pendulum = System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th))
    >>> [round(e[th], 6) for e in equilibria_near(pendulum, {"m": 1, "g": 9.81, "l": 1}, {"theta": 0.5})]
    [0.0, 3.141593]
    """
    conds, unknowns = _conditions(system)
    F, unknowns, x0, fixed = _numeric_problem(system, params, near, conds, unknowns)
    n = system.derived.n
    starts = _starts(x0, n, fixed[0])
    periodic = _periodic(F, starts, n, fixed)
    found: list[np.ndarray] = []
    for x in starts:
        sol, _ = _solve_from(F, x, unknowns, fixed)
        if sol is None:
            continue
        for i in periodic:  # an angle: the representative within π of the starting point
            sol[i] = x0[i] + (sol[i] - x0[i] + np.pi) % (2 * np.pi) - np.pi
        if not any(_same(sol[:n], other[:n], periodic) for other in found):
            found.append(sol)
    for sol in found:  # rounding of the root finder: exact zeros stay zeros
        sol[:n][np.abs(sol[:n]) < 1e-12 * max(1.0, float(np.max(np.abs(sol[:n]))))] = 0.0
    found.sort(key=lambda s: float(np.linalg.norm(s[:n] - x0[:n])))
    return [_as_equilibrium(system, unknowns, s, fixed) for s in found]


def _starts(x0: np.ndarray, n: int, fixed: dict) -> list[np.ndarray]:
    """x0; x0 ± 1 and ± π (times max(1, |x0ᵢ|)) along each coordinate not fixed; then seeded random points."""
    starts = [x0]
    for i in range(n):
        if i in fixed:
            continue
        for d in (1.0, -1.0, np.pi, -np.pi):
            x = x0.copy()
            x[i] += d * max(1.0, abs(x0[i]))
            starts.append(x)
    rng = np.random.default_rng(0)
    while len(starts) < MAX_STARTS:
        x = x0.copy()
        x[:n] += rng.normal(0.0, 2.0, n) * np.maximum(1.0, np.abs(x0[:n]))
        for i in fixed:
            x[i] = x0[i]
        starts.append(x)
    return starts[:MAX_STARTS]


def _same(a: np.ndarray, b: np.ndarray, periodic: list[int]) -> bool:
    d = a - b
    d[periodic] = (d[periodic] + np.pi) % (2 * np.pi) - np.pi
    return bool(np.all(np.abs(d) <= 1e-6 * (1.0 + np.abs(a))))


def _periodic(F, starts, n: int, fixed) -> list[int]:
    """The coordinates in which the conditions are 2π-periodic (angles), tested at three of the starts."""
    fixed_at, keep = fixed
    out = []
    for i in range(n):
        if i in fixed_at:
            continue
        same = True
        for x in starts[1:4] or starts:
            y = x.copy()
            y[i] += 2 * np.pi
            a, b = F(x[keep]), F(y[keep])
            if not (np.all(np.isfinite(a)) and np.allclose(a, b, rtol=1e-9, atol=1e-12)):
                same = False
                break
        if same:
            out.append(i)
    return out
