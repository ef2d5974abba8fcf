r"""A model's derived equations as a heyoka.py ODE system: what ``method="heyoka"`` integrates.

From the same CSE as every backend (:func:`lagrange.codegen.cse.fuse`: M's upper triangle, f and, for
non-conservative systems, the power dh/dt of the work integral), each expression is converted node by node
into a heyoka expression (numbers as floats, parameters as heyoka runtime parameters ``par[k]`` in the order
of ``equations.numeric_parameters``, ``t`` as heyoka's ``time``), and the linear solve ``M q̈ = f`` is written
as heyoka expressions too (LDLᵀ without pivoting, structural zeros of M skipped; M is symmetric positive
definite). The first-order system is

.. math:: \dot q = v, \quad \dot v = M(q, v, t)^{-1} f(q, v, t), \quad \dot w = P(q, v, t)

(``w``, the work of the non-conservative forces, only when the system is not conservative), the state
``z = [q, v(, w)]`` as in :mod:`lagrange.codegen.tape`. Because parameters are runtime parameters, a re-run
with other values reuses heyoka's compiled code (its in-memory and on-disk JIT caches).

Scope, as the Taylor tape's: unconstrained systems (no multipliers) with analytic equations
(``+ − × ÷``, powers, ``exp log sin cos tan sinh cosh tanh``); anything else raises
:class:`~lagrange.codegen.tape.TapeError` naming the function and where it is.
"""

from __future__ import annotations

import importlib.util
import weakref

import sympy as sp

from ..derive.equations import Equations
from ..errors import BackendError
from ..records import record
from .cse import fuse
from .tape import TapeError, _check_analytic

__all__ = ["HeyokaODEs", "HeyokaShape", "heyoka_odes", "heyoka_shape", "heyoka_available", "convert_expression",
           "COMPACT_OPS"]

#: systems whose fused expressions have more operations than this get heyoka's ``compact_mode`` (its LLVM
#: compile time explodes otherwise: measured on the 5-link pendulum, 25 s default vs 1.7 s compact)
COMPACT_OPS = 400
_ODES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SHAPES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def heyoka_available() -> bool:
    """Whether ``import heyoka`` would succeed."""
    return importlib.util.find_spec("heyoka") is not None


@record(frozen=True, eq=False)
class HeyokaODEs:
    """``system``: heyoka's ``[(var, rhs), ...]`` over the state ``z = [q, v(, w)]``; ``n`` coordinates,
    ``nz`` state size (2n, or 2n + 1 with the work integral), ``n_params`` runtime parameters; ``compact``:
    use heyoka's compact mode (large systems)."""

    system: list
    n: int
    nz: int
    n_params: int
    compact: bool


@record(frozen=True, eq=False)
class HeyokaShape:
    """What a run needs to know of the heyoka system without building it: ``n`` coordinates, ``nz`` state
    size (2n, or 2n + 1 with the work integral), ``n_params`` runtime parameters."""

    n: int
    nz: int
    n_params: int


def heyoka_shape(eqs: Equations) -> HeyokaShape:
    """The shape of :func:`heyoka_odes` of ``eqs``, after the same refusals, without the CSE and the conversion
    (an integrator loaded from the on-disk cache needs no more; one per Equations).

    Raises
    ------
    BackendError, TapeError
        As :func:`heyoka_odes`.
    """
    if eqs in _SHAPES:
        return _SHAPES[eqs]
    if not heyoka_available():
        raise BackendError('method="heyoka" needs heyoka.py: pip install "lagrange-dynamics[heyoka]"')
    if eqs.m or eqs.is_rough:
        raise TapeError(f"method='heyoka' integrates unconstrained systems (this one has {eqs.m} constraint(s) "
                        "whose multipliers it cannot solve for): use method='DOP853' or another scipy method")
    _check_analytic(eqs)
    out = _SHAPES[eqs] = HeyokaShape(eqs.n, 2 * eqs.n + (0 if eqs.is_conservative else 1),
                                     len(eqs.numeric_parameters))
    return out


def _convert(e, table: dict, hy):
    """``e`` (sympy, over the fused symbols) as a heyoka expression; ``table`` maps symbols and memoizes."""
    hit = table.get(e)
    if hit is not None:
        return hit
    if e.is_Number or e.is_NumberSymbol:
        out = hy.expression(float(e))
    elif e.is_Symbol:
        raise TapeError(f"heyoka: the symbol {e} is not a state, parameter or time")  # pragma: no cover
    elif e.is_Add or e.is_Mul:
        args = [_convert(a, table, hy) for a in e.args]
        out = hy.sum(args) if e.is_Add else hy.prod(args)
    elif e.is_Pow:
        base, ex = e.args
        b = _convert(base, table, hy)
        if ex.is_Integer and int(ex) == -1:
            out = hy.expression(1.0) / b
        elif ex.is_Number:
            out = hy.sqrt(b) if ex == sp.S.Half else b ** float(ex)
        else:
            out = hy.exp(_convert(ex * sp.log(base), table, hy))
    else:
        f = e.func
        funcs = {sp.sin: hy.sin, sp.cos: hy.cos, sp.tan: hy.tan, sp.exp: hy.exp, sp.log: hy.log, sp.sinh: hy.sinh,
                 sp.cosh: hy.cosh, sp.tanh: hy.tanh}
        if f not in funcs or len(e.args) != 1:  # _check_analytic has named it already; a safety net
            raise TapeError(f"heyoka: cannot convert {e.func}(...)")  # pragma: no cover
        out = funcs[f](_convert(e.args[0], table, hy))
    table[e] = out
    return out


def _solve(mass: dict, force: list, n: int, hy) -> list:
    """``a = M⁻¹ f`` in heyoka expressions: LDLᵀ of the symmetric M (``mass[(i, j)]``, i ≤ j, absent =
    structural zero), forward and back substitution."""
    zero = None

    def m(i, j):
        return mass.get((min(i, j), max(i, j)), zero)

    L: dict = {}
    d: list = []
    for j in range(n):
        dj = m(j, j)
        for k in range(j):
            if (j, k) in L:
                dj = dj - L[j, k] * L[j, k] * d[k]
        d.append(dj)
        for i in range(j + 1, n):
            s = m(i, j)
            for k in range(j):
                if (i, k) in L and (j, k) in L:
                    s = -(L[i, k] * L[j, k] * d[k]) if s is None else s - L[i, k] * L[j, k] * d[k]
            if s is not None:
                L[i, j] = s / dj
    r = list(force)
    for i in range(n):
        for j in range(i):
            if (i, j) in L:
                r[i] = r[i] - L[i, j] * r[j]
    a: list = [None] * n
    for i in range(n - 1, -1, -1):
        s = r[i] / d[i]
        for j in range(i + 1, n):
            if (j, i) in L:
                s = s - L[j, i] * a[j]
        a[i] = s
    return a


def convert_expression(e: sp.Expr):
    """``e``, a sympy expression over ``t`` and the state symbols ``y0 … y{nz-1}`` (``y{2n}`` the work
    integral), as a heyoka expression over the variables of :func:`heyoka_odes`' system (an event)."""
    import heyoka as hy

    table: dict = {}
    for s in e.free_symbols:
        if s.name == "t":
            table[s] = hy.time
        elif s.name.startswith("y") and s.name[1:].isdigit():
            table[s] = hy.make_vars(f"z{s.name[1:]}")
        else:
            raise TapeError(f"heyoka: the symbol {s} is not a state or time")
    return _convert(e, table, hy)


def heyoka_odes(eqs: Equations) -> HeyokaODEs:
    """The heyoka ODE system of ``eqs`` (module docstring), built once per Equations.

    Raises
    ------
    BackendError
        heyoka is not installed (``pip install "lagrange-dynamics[heyoka]"``).
    TapeError
        The system has constraints (multipliers) or rough constraints, or a non-analytic function (named).
    """
    if eqs in _ODES:
        return _ODES[eqs]
    heyoka_shape(eqs)  # the refusals
    import heyoka as hy

    n = eqs.n
    conservative = eqs.is_conservative
    fused, red_extra = fuse(eqs, extra=() if conservative else (eqs.jacobi_rate,))
    nz = 2 * n + (0 if conservative else 1)
    z = list(hy.make_vars(*[f"z{i}" for i in range(nz)]))
    table: dict = {sp.Symbol(f"y{i}", real=True): z[i] for i in range(2 * n)}
    table[sp.Symbol("t", real=True)] = hy.time
    n_params = len(eqs.numeric_parameters)
    table.update({sp.Symbol(f"p{k}", real=True): hy.par[k] for k in range(n_params)})
    ops = 0
    for sym, e in fused.temporaries:
        table[sym] = _convert(e, table, hy)
        ops += sp.count_ops(e)
    mass = {ij: _convert(e, table, hy) for ij, e in fused.mass_upper.items()}
    force = [_convert(e, table, hy) for e in fused.forcing]
    ops += sum(sp.count_ops(e) for e in [*fused.mass_upper.values(), *fused.forcing])
    acc = _solve(mass, force, n, hy)
    system = [(z[i], z[n + i]) for i in range(n)] + [(z[n + i], acc[i]) for i in range(n)]
    if not conservative:
        system.append((z[2 * n], _convert(red_extra[0], table, hy)))
    out = HeyokaODEs(system=system, n=n, nz=nz, n_params=n_params, compact=int(ops) > COMPACT_OPS)
    _ODES[eqs] = out
    return out
