r"""Source of the batched right-hand side: many states at once, states as columns, one compiled loop.

The kernel evaluates the same fused expressions as ``rhs`` (:func:`lagrange.codegen.cse.fuse`, then the
unrolled LDLᵀ solve of :mod:`lagrange.codegen.source`) for ``k`` members at once, in the layout that lets
the compiler use SIMD registers across members: every variable is a contiguous row of ``k`` values::

    def rhs_columns(t, Y, P, out, S):   # t (k,), Y (2n, k), P (n_params, k), out (2n, k), S (n_calls, k)
        for c in range(k):              # phase 1: calls of sin, cos, exp, ... (libm, one member at a time)
            S0[c] = math.sin(Y0[c]) ...
        for c in range(k):              # phase 2: straight-line arithmetic, vectorized by LLVM over c
            y0 = Y0[c] ... a0_0 = ... ; <LDLᵀ> ; O0[c] = ...
        return bad                      # members whose mass matrix failed the pivot test

Transcendental functions have no vector form in numba without Intel's SVML, and one scalar call in a loop
keeps LLVM from vectorizing the whole loop: so every function call (with the arithmetic its arguments
need) is hoisted into phase 1 and stored in ``S``; phase 2 is then pure arithmetic (``+ − × ÷``, ``sqrt``,
``abs``, comparisons). It is compiled with ``error_model='numpy'`` (a division by zero gives inf or NaN
instead of raising, which a vector loop cannot do) and fastmath off (IEEE results, the same numbers as the
per-member ``rhs``). A mass matrix that is not positive definite counts in ``bad`` instead of raising; the
caller (:meth:`NumericModel.rhs_many <lagrange.codegen.numeric.NumericModel.rhs_many>`) then, and for any
non-finite result, re-runs the members one by one so that the error names the member's state exactly as the
per-member path does.

Scope: unconstrained systems (constrained models keep the per-member compiled loop, which carries their
Baumgarte terms).
"""

from __future__ import annotations

import re

import sympy as sp

from .cse import FusedExpressions
from .source import _ldl_factor, _ldl_solve, print_expr

__all__ = ["columns_source", "KERNEL"]

#: name of the generated kernel
KERNEL = "rhs_columns"
_VECTOR_FUNCTIONS = (sp.Abs,)


def _is_call(e) -> bool:
    """A node that compiles to a scalar libm call (no vector form): functions other than ``abs``, and
    powers with a non-integer exponent other than 1/2 (``sqrt`` is an LLVM intrinsic)."""
    if isinstance(e, sp.Function):
        return not isinstance(e, _VECTOR_FUNCTIONS)
    if isinstance(e, sp.Pow):
        return not (e.exp.is_Integer or e.exp == sp.Rational(1, 2) or e.exp == -sp.Rational(1, 2))
    return False


def _calls_in(e, found: dict) -> None:
    """Add every call node of ``e`` to ``found`` (insertion order: innermost first)."""
    for arg in e.args:
        _calls_in(arg, found)
    if _is_call(e):
        found.setdefault(e, None)


class _Calls:
    """The call nodes of a set of expressions, each named ``s{j}``, and the printed text of an expression
    with its calls replaced by their names: the text of ``print_expr`` of the original expression is kept
    character for character (only the call's own text becomes its name), so the arithmetic, and its
    rounding, is exactly that of the per-member ``rhs``."""

    def __init__(self, exprs):
        found: dict = {}
        for e in exprs:
            _calls_in(e, found)
        self.order = [(sp.Symbol(f"s{j}", real=True), e) for j, e in enumerate(found)]
        self.name = {e: s for s, e in self.order}
        self._names = {print_expr(e): s.name for s, e in self.order}

    def text(self, e, *, inner_only: bool = False) -> str:
        """``print_expr(e)`` with every call replaced by its name (``inner_only``: all but ``e`` itself)."""
        printed = print_expr(e)
        names = {t: n for t, n in self._names.items() if not (inner_only and t == printed)}
        if not names:
            return printed
        # longest first, never inside a longer name or number (`y1` in `y10`, `p0**1.5` in `p0**1.53`)
        pattern = "|".join(rf"(?<![\w.]){re.escape(t)}(?![\w.])" for t in sorted(names, key=len, reverse=True))
        return re.sub(pattern, lambda m: names[m.group(0)], printed)

    def deps(self, e, *, inner_only: bool = False) -> set:
        """Symbols (temporaries, state, parameters) and call names ``e`` needs."""
        found: dict = {}
        _calls_in(e, found)
        if inner_only:
            found.pop(e, None)
        return set(e.free_symbols) | {self.name[c] for c in found}


def _phase_one(temps: list, calls: _Calls) -> list[tuple[sp.Symbol, str]]:
    """The lines ``(symbol, text)`` that compute every call: each after the temporaries and calls it needs,
    in dependency order."""
    defs = {s: (e, False) for s, e in temps} | {s: (e, True) for s, e in calls.order}
    done: set = set()
    lines: list = []

    def emit(sym):
        if sym in done or sym not in defs:
            return
        done.add(sym)
        e, is_call = defs[sym]
        for dep in sorted(calls.deps(e, inner_only=is_call), key=str):
            emit(dep)
        lines.append((sym, calls.text(e, inner_only=is_call)))

    for sym, _ in calls.order:
        emit(sym)
    return lines


_FAIL = "<fail>"


def _branch_free(lines: list[str]) -> list[str]:
    """The factorization's ``if not (cond): <fail>`` pairs as ``ok = ok & (cond)``: one predicate per
    member instead of a branch per pivot (a vector loop cannot branch per member)."""
    out: list[str] = []
    for line in lines:
        if line.strip() == _FAIL:
            cond = out.pop()
            if not (cond.startswith("if not (") and cond.endswith("):")):
                raise AssertionError(f"unexpected pivot test {cond!r}")
            out.append(f"ok = ok & ({cond[len('if not ('):-2]})")
        else:
            out.append(line)
    return out


def columns_source(fused: FusedExpressions, *, n_params: int) -> tuple[str, int]:
    """``(source, n_calls)``: the text of ``rhs_columns(T, Y, P, out, S) -> bad`` (module docstring; ``T``
    the members' times) for an unconstrained system, and the rows of the scratch array ``S`` it needs (one
    per distinct hoisted call). Raises ValueError for a system with constraints."""
    if fused.m:
        raise ValueError("the column kernel is for unconstrained systems (no multipliers)")
    n = fused.n
    temps = list(fused.temporaries)
    mass, forcing = fused.mass_upper, list(fused.forcing)
    calls = _Calls([e for _, e in temps] + list(mass.values()) + forcing)
    head = ["k = Y.shape[1]", "bad = 0"] + [f"O{i} = O[{i}]" for i in range(2 * n)]

    def loads(symbols) -> list[str]:
        names = {s.name for s in symbols}
        out = [f"y{i} = Y[{i}, c]" for i in range(2 * n) if f"y{i}" in names]
        out += [f"p{j} = P[{j}, c]" for j in range(n_params) if f"p{j}" in names]
        return out + (["t = T[c]"] if "t" in names else [])

    loop1: list[str] = []
    if calls.order:
        first = _phase_one(temps, calls)
        defs = dict(temps) | dict(calls.order)
        one = loads(set().union(*(defs[s].free_symbols for s, _ in first))) + [f"{s} = {text}" for s, text in first]
        one += [f"S[{s.name[1:]}, c] = {s}" for s, _ in calls.order]
        loop1 = ["for c in range(k):"] + ["    " + line for line in one]
    every = [e for _, e in temps] + list(mass.values()) + forcing
    used = set().union(*(e.free_symbols for e in every)) | {sp.Symbol(f"y{n + i}") for i in range(n)}
    two = loads(used) + [f"{s} = S[{s.name[1:]}, c]" for s, _ in calls.order]
    two += [f"{s} = {calls.text(e)}" for s, e in temps]
    two += [f"a{i}_{j} = {calls.text(e)}" for (i, j), e in mass.items()]
    two += [f"b{i} = {calls.text(e)}" for i, e in enumerate(forcing)]
    lines, nz, d = _ldl_factor(n, lambda i, j: f"a{i}_{j}" if (i, j) in mass else None, "", "mass matrix",
                               _FAIL)
    two += ["ok = True"] + _branch_free(lines)
    two += _ldl_solve(n, nz, d, [f"b{i}" for i in range(n)], [f"x{i}" for i in range(n)], "")
    two += [f"O{i}[c] = y{n + i}" for i in range(n)] + [f"O{n + i}[c] = x{i}" for i in range(n)]
    two.append("bad += 1 - ok")
    loop2 = ["for c in range(k):"] + ["    " + line for line in two]
    body = head + loop1 + loop2 + ["return bad"]
    return f"def {KERNEL}(T, Y, P, O, S):\n" + "".join(f"    {line}\n" for line in body), len(calls.order)
