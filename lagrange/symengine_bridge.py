"""The optional symengine fast path: which sympy expressions symengine carries exactly, and the round trip.

symengine (``pip install "lagrange-dynamics[fast]"``) differentiates and eliminates common subexpressions tens of
times faster than sympy. lagrange uses it only where the result is provably the same expression:
:func:`carries` admits Add, Mul, Pow, integers, rationals, π, e, the elementary functions of
:data:`FUNCTIONS` and plain symbols with distinct names — no floats (their precision could change), no
``Abs``/``sign``/``Piecewise`` or user functions (not converted back unchanged), no ``Dummy`` and no two
symbols of one name (the round trip keys symbols by name and restores their assumptions). Anything else
takes the sympy path, as does everything when symengine is not installed.
"""

from __future__ import annotations

from collections.abc import Iterable
from types import ModuleType

import sympy as sp

__all__ = ["FUNCTIONS", "FAILURES", "symengine", "carries", "Restorer", "to_symengine"]

#: elementary functions symengine represents exactly and converts back to the same sympy class
FUNCTIONS = (sp.sin, sp.cos, sp.tan, sp.exp, sp.log, sp.sinh, sp.cosh, sp.tanh, sp.asin, sp.acos, sp.atan)
_NODES = (sp.Add, sp.Mul, sp.Pow, sp.Integer, sp.Rational, type(sp.pi), type(sp.E), *FUNCTIONS)
#: what a failed symengine call or conversion raises; the caller then takes the sympy path
FAILURES = (RuntimeError, TypeError, ValueError, NotImplementedError, AttributeError, sp.SympifyError)


def symengine() -> ModuleType | None:
    """The symengine module, or None when it is not installed."""
    try:
        import symengine as se
    except ImportError:
        return None
    return se


def carries(exprs: Iterable, symbols: Iterable = ()) -> bool:
    """Whether every node of ``exprs`` is one symengine carries back unchanged and the free symbols of
    ``exprs`` together with ``symbols`` have distinct names (and none is a ``Dummy``).

    Each distinct subexpression is visited once (a bicycle's kinetic energy repeats the same products of sines
    hundreds of times; a plain tree walk visited every copy)."""
    seen: dict[str, sp.Symbol] = {}
    for s in symbols:
        if type(s) is not sp.Symbol or seen.setdefault(s.name, s) != s:
            return False
    visited: set = set()  # each distinct subtree once: linear in the size of the expression graph
    stack = list(exprs)
    while stack:
        node = stack.pop()
        if node in visited:
            continue
        visited.add(node)
        if type(node) is sp.Symbol:
            if seen.setdefault(node.name, node) != node:
                return False
        elif not isinstance(node, _NODES):
            return False
        else:
            stack.extend(node.args)
    return True


def to_symengine(exprs: Iterable, symbols: Iterable[sp.Symbol]) -> list:
    """``exprs`` in symengine, each of ``symbols`` as a symbol that symengine converts back to that very
    sympy symbol (with its assumptions): results then come back by ``sympy.sympify`` alone, without
    :class:`Restorer`'s second pass over the tree. Precondition: :func:`carries` holds for ``exprs`` and
    ``symbols``."""
    se = symengine()
    carrier = _carrier_class(se)
    names = {se.Symbol(s.name): carrier(s) for s in symbols}
    if len(names) != len(set(symbols)):
        raise ValueError("to_symengine: two symbols share a name")
    return [se.sympify(e).xreplace(names) for e in exprs]


_CARRIER: list = []


def _carrier_class(se: ModuleType) -> type:
    """A symengine symbol holding its sympy original (a subclass of ``symengine.Symbol`` is stored as a
    Python object by symengine, and ``_sympy_`` converts it back).

    Its symengine name holds the original's assumptions: symengine compares symbols by name, and sympy's
    cache, keyed by the symengine arguments of a conversion, would otherwise hand back a result built from an
    earlier same-named symbol with other assumptions (found by tests/test_derive.py: a positive ``r`` of one
    problem in the equations of the next)."""
    if not _CARRIER:

        class Carried(se.Symbol):
            def __init__(self, original: sp.Symbol):
                super().__init__(f"{original.name}{sorted(original.assumptions0.items())}")
                self.original = original

            def _sympy_(self) -> sp.Symbol:
                return self.original

        _CARRIER.append(Carried)
    return _CARRIER[0]


class Restorer:
    """symengine → sympy with the original symbols (and their assumptions) restored by name.

    Converted node by node, each distinct symengine subexpression once, with the original symbols put in
    as the leaves are reached: the same sympy expression as ``sympify`` followed by ``xreplace`` of the
    symbols, without rebuilding the whole tree a second time (on a bicycle's convective terms, 77,000
    operations, 0.3 s instead of 1.8 s). Nodes outside :func:`carries`' set go through ``sympify`` and
    ``xreplace``, as before.
    """

    def __init__(self, symbols: Iterable[sp.Symbol]):
        self._back = {sp.Symbol(s.name): s for s in symbols if sp.Symbol(s.name) != s}
        self._by_name = {plain.name: s for plain, s in self._back.items()}

    def __call__(self, expr) -> sp.Expr:
        se = symengine()
        if se is None or not isinstance(expr, se.Basic):
            out = sp.sympify(expr)
            return out.xreplace(self._back) if self._back else out
        return self._convert(expr, {}, se)

    def _convert(self, e, memo: dict, se):
        done = memo.get(e)
        if done is not None:
            return done
        if isinstance(e, se.Symbol):
            out = self._by_name.get(e.name) or sp.Symbol(e.name)
        elif isinstance(e, (se.Add, se.Mul, se.Pow)):
            cls = sp.Add if isinstance(e, se.Add) else sp.Mul if isinstance(e, se.Mul) else sp.Pow
            out = cls(*[self._convert(a, memo, se) for a in e.args])
        elif type(e).__name__ in _FUNCTION_NAMES and len(e.args) == 1:
            out = _FUNCTION_NAMES[type(e).__name__](self._convert(e.args[0], memo, se))
        else:  # numbers, constants, anything else: symengine's own conversion, then the symbols
            out = sp.sympify(e)
            if self._back and out.free_symbols:
                out = out.xreplace(self._back)
        memo[e] = out
        return out


_FUNCTION_NAMES = {f.__name__: f for f in FUNCTIONS}


#: expressions smaller than this (nodes, all of them together) are differentiated by sympy in :func:`jacobian`:
#: there symengine's import and the round trip cost more than they save (the same threshold as
#: ``lagrange.derive.lagrange.SYMENGINE_MIN_NODES``, decided by size alone so a result never depends on what a
#: process imported before)
JACOBIAN_MIN_NODES = 75


def _nodes_at_least(exprs: Iterable, bound: int) -> bool:
    count = 0
    for e in exprs:
        for _ in sp.preorder_traversal(e):
            count += 1
            if count >= bound:
                return True
    return False


def jacobian(exprs: list, variables: list) -> list[list] | None:
    """``[[∂e/∂v for v in variables] for e in exprs]`` by symengine, converted back exactly (:class:`Restorer`),
    or None when sympy should do it: symengine not installed, the expressions below
    :data:`JACOBIAN_MIN_NODES` nodes or holding something :func:`carries` refuses, or symengine failed.

    ``variables`` are plain symbols. The derivatives equal sympy's (exact differentiation; only the order of
    terms in the printed form may differ)."""
    if not exprs or not _nodes_at_least(exprs, JACOBIAN_MIN_NODES):
        return None
    se = symengine()
    if se is None or not carries(exprs, variables):
        return None
    free = set(variables).union(*(_free(e) for e in exprs))
    restore = Restorer(free)
    try:
        ses = [se.sympify(e) for e in exprs]
        svs = [se.Symbol(v.name) for v in variables]
        return [[restore(e.diff(v)) if e.has(v) else sp.S.Zero for v in svs] for e in ses]
    except FAILURES:
        return None


def _free(e) -> set:
    return sp.sympify(e).free_symbols
