"""One joint common-subexpression elimination over (upper triangle of M, f), and the symbol renaming
used by every generated-code backend.

Generated code sees the state as ``y0 .. y{2n-1}`` (positions then velocities), parameters as
``p0 .. p{k-1}`` and temporaries as ``c0, c1, …`` — unique names, so sympy's CSE/assumption pitfalls
(sympy#25043) cannot bite.
"""

from __future__ import annotations

import weakref

import sympy as sp
from sympy.simplify import cse_opts

from ..budget import check
from ..conventions import t
from ..derive.equations import Equations
from ..records import record
from ..symengine_bridge import FAILURES, Restorer, carries, symengine

__all__ = ["FusedExpressions", "fuse", "rename_map", "numeric_arguments",
           "FACTOR_TERMS_LIMIT"]

#: expression-tree size (nodes of M, f and the constraint blocks, shared subtrees counted each time) above
#: which CSE skips sympy's ``factor_terms`` pre-pass: symengine's CSE when installed, else sympy's with its
#: cheap negation pre-pass only. Measured (benchmarks/results/workprecision.md models): ``factor_terms``
#: cost 0.8 s of Greenspan's top (18,765 nodes) for ~20 % fewer operations, and on the 5-link pendulum
#: (1,235 nodes) 70 ms while *adding* operations; below the limit (the textbook systems, < 100 nodes) it
#: takes milliseconds and saves a few.
FACTOR_TERMS_LIMIT = 1000


def rename_map(eqs: Equations) -> dict:
    """Plain symbols of the derivation → generated-code names (``y0..``, ``p0..``, ``t``)."""
    n = eqs.n
    m = {s: sp.Symbol(f"y{i}", real=True) for i, s in enumerate(eqs.q)}
    m.update({s: sp.Symbol(f"y{n + i}", real=True) for i, s in enumerate(eqs.qd)})
    m.update({s: sp.Symbol(f"p{k}", real=True) for k, s in enumerate(eqs.numeric_parameters)})
    m[t] = sp.Symbol("t", real=True)
    return m


def numeric_arguments(eqs: Equations) -> tuple[sp.Symbol, tuple, list]:
    """``(t, y, p)`` in generated-code names — the argument symbols of every numeric function built from
    ``eqs`` (``y`` has 2n entries, positions first; ``p`` follows ``eqs.numeric_parameters``)."""
    ren = rename_map(eqs)
    y = tuple(ren[s] for s in (*eqs.q, *eqs.qd))
    return ren[t], y, [ren[s] for s in eqs.numeric_parameters]


@record(frozen=True)
class FusedExpressions:
    """CSE'd ``M`` (upper triangle, row-major) and ``f`` in generated-code names."""

    n: int
    temporaries: tuple  # ((Symbol, expr), ...)
    mass_upper: dict  # {(i, j): expr} for i <= j, structural zeros omitted
    forcing: tuple  # n expressions
    constraint_matrix: dict = None  # {(r, j): expr} structural zeros omitted
    constraint_rhs: tuple = ()  # c_r with A q̈ = c (Baumgarte terms included when requested)
    reaction: dict | None = None  # {(j, r): expr} of B when it differs from Aᵀ (rough constraints)
    quadratures: tuple = ()  # QuadratureGroups computing the placeholders qs{k} of remaining integrals

    @property
    def m(self) -> int:
        return len(self.constraint_rhs)


_FUSED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def fuse(eqs: Equations, *, extra: tuple = (), constraint_rhs=None,
         printable: bool = False) -> tuple[FusedExpressions, tuple]:
    """Run one CSE over M's upper triangle, f, the constraint blocks A and c (``constraint_rhs``
    overrides c, e.g. with Baumgarte terms) and ``extra`` expressions.

    ``printable=True`` (code printing only, no ``extra``): the same CSE, but on the symengine path
    (symengine installed, the expressions above :data:`FACTOR_TERMS_LIMIT` nodes and carried exactly) the
    renaming, the CSE and the result stay in symengine, and the expressions of the result are symengine
    objects that :func:`lagrange.codegen.source.print_expr` prints directly — no conversion back to sympy,
    which took most of the code generation of a 10-link pendulum. Elsewhere, and for the Taylor tape and
    heyoka (which need sympy), the result is sympy. The two give the same expressions up to the order of
    terms in sums (tests/test_codegen_symengine.py).

    Floats are introduced here only: exact rationals stay exact until printed.
    Returns the fused expressions and the CSE'd ``extra`` expressions (treat both as read-only: the result
    is remembered per equations and arguments, so the code generator and the Taylor tape of one model share
    one CSE — 0.14 s of a 10-link pendulum's first result).
    """
    if printable and not extra and not eqs.has_quadrature:
        fast = _symengine_fuse(eqs, constraint_rhs)
        if fast is not None:
            return fast, ()
    key = (tuple(extra), None if constraint_rhs is None else tuple(constraint_rhs))
    memo = _FUSED.setdefault(eqs, {})
    if key not in memo:
        memo[key] = _fuse(eqs, extra, constraint_rhs)
    return memo[key]


def _fuse_inputs(eqs: Equations, extra: tuple, constraint_rhs) -> tuple[list, tuple]:
    """The expressions one CSE runs over, in the plain symbols of the derivation, and their index sets
    ``(idx of M's upper triangle, idx of A, idx of B)``."""
    n = eqs.n
    A = eqs.constraint_matrix
    crhs = list(constraint_rhs) if constraint_rhs is not None else list(eqs.constraint_rhs)
    M, f = sp.Matrix(eqs.mass_matrix), sp.Matrix(eqs.forcing)
    if eqs.m:
        # exact augmented form: adding Aᵀ(A q̈ − c) = 0 gives (M + AᵀA) q̈ = f + Aᵀc + Bλ, whose matrix is
        # positive definite whenever the constrained problem is well posed — also when M itself is
        # singular (superfluous coordinates that carry no inertia of their own)
        M = M + A.T * A
        f = f + A.T * sp.Matrix(crhs)
    idx = [(i, j) for i in range(n) for j in range(i, n) if M[i, j] != 0]
    exprs = [M[i, j] for i, j in idx] + list(f)
    aidx = [(r, j) for r in range(eqs.m) for j in range(n) if A[r, j] != 0]
    exprs += [A[r, j] for r, j in aidx] + [sp.sympify(e) for e in crhs]
    B = eqs.reaction_matrix
    bidx = [(j, r) for r in range(eqs.m) for j in range(n) if B[j, r] != 0] if eqs.is_rough else []
    exprs += [B[j, r] for j, r in bidx] + [sp.sympify(e) for e in extra]
    return exprs, (idx, aidx, bidx)


def _assemble(eqs: Equations, indices: tuple, repl: list, red: list, quadratures: tuple = ()
              ) -> tuple[FusedExpressions, tuple]:
    n = eqs.n
    idx, aidx, bidx = indices
    k = len(idx)
    ka = k + n + len(aidx)
    fused = FusedExpressions(
        n=n,
        temporaries=tuple(repl),
        mass_upper={ij: e for ij, e in zip(idx, red[:k])},
        forcing=tuple(red[k : k + n]),
        constraint_matrix={rj: e for rj, e in zip(aidx, red[k + n : ka])},
        constraint_rhs=tuple(red[ka : ka + eqs.m]),
        reaction={jr: e for jr, e in zip(bidx, red[ka + eqs.m : ka + eqs.m + len(bidx)])} if bidx else None,
        quadratures=quadratures,
    )
    return fused, tuple(red[ka + eqs.m + len(bidx) :])


def _symengine_fuse(eqs: Equations, constraint_rhs) -> FusedExpressions | None:
    """The symengine path of :func:`fuse` with ``printable=True``, or None where :func:`_cse` would not take
    it."""
    se = symengine()
    if se is None:
        return None
    exprs, indices = _fuse_inputs(eqs, (), constraint_rhs)
    check(sp.Tuple(*exprs), stage="common-subexpression elimination", what="the equations of motion")
    if _tree_size(exprs) <= FACTOR_TERMS_LIMIT:
        return None
    ren = rename_map(eqs)
    if not carries(exprs, ren):
        return None
    try:
        names = {se.Symbol(old.name): se.Symbol(new.name) for old, new in ren.items()}
        renamed = [se.sympify(e).xreplace(names) for e in exprs]
        allowed = set(names.values())
        if any(not e.free_symbols <= allowed for e in renamed):  # a symbol generated code would not know
            return None
        repl, red = se.cse(renamed)
        temps = {sym: se.Symbol(f"c{k}") for k, (sym, _) in enumerate(repl)}
        repl = [(temps[sym], e.xreplace(temps)) for sym, e in repl]
        red = [e.xreplace(temps) for e in red]
    except FAILURES:
        return None
    return _assemble(eqs, indices, repl, red)[0]


def _tree_size(exprs: list) -> int:
    """Tree size of ``exprs`` (shared subtrees counted each time), counted only up to
    :data:`FACTOR_TERMS_LIMIT` + 1."""
    size = 0
    for e in exprs:
        for _ in sp.preorder_traversal(e):
            size += 1
            if size > FACTOR_TERMS_LIMIT:
                return size
    return size


def _fuse(eqs: Equations, extra: tuple, constraint_rhs) -> tuple[FusedExpressions, tuple]:
    ren = rename_map(eqs)
    exprs, indices = _fuse_inputs(eqs, extra, constraint_rhs)
    exprs = [e.xreplace(ren) for e in exprs]
    groups: tuple = ()
    if eqs.has_quadrature:  # each remaining integral: a placeholder, computed by quadrature before the CSE'd lines
        from .quadrature import split_integrals

        exprs, groups = split_integrals(exprs)
    repl, red = _cse(exprs)
    return _assemble(eqs, indices, repl, red, groups)


def _cse(exprs: list) -> tuple[list, list]:
    """``sympy.cse`` of ``exprs`` with temporaries ``c0, c1, …`` (real); more than
    :data:`lagrange.budget.MAX_NODES` distinct nodes raise :class:`~lagrange.errors.ExpressionTooLarge`.
    Small sets (at most :data:`FACTOR_TERMS_LIMIT` nodes) get sympy's ``factor_terms`` pre-pass;
    larger ones are handed to
    symengine's CSE when installed and ``exprs`` are what it carries back exactly
    (:func:`lagrange.symengine_bridge.carries`), else to sympy's with its negation pre-pass only."""
    check(sp.Tuple(*exprs), stage="common-subexpression elimination", what="the equations of motion")
    if _tree_size(exprs) <= FACTOR_TERMS_LIMIT:
        return sp.cse(exprs, symbols=sp.numbered_symbols("c", real=True), optimizations="basic")
    fast = _symengine_cse(exprs)
    if fast is not None:
        return fast
    return sp.cse(exprs, symbols=sp.numbered_symbols("c", real=True),
                  optimizations=[(cse_opts.sub_pre, cse_opts.sub_post)])


def _symengine_cse(exprs: list) -> tuple[list, list] | None:
    """symengine's CSE of ``exprs`` in sympy form, temporaries renamed ``c0, c1, …`` in order, or None
    (symengine not installed, ``exprs`` not carried exactly, a name clash with symengine's ``x0, x1, …``,
    or a symengine failure). Measured on Greenspan's top: 145 → 60 ms including both conversions, 657 → 674
    operations."""
    se = symengine()
    if se is None or not carries(exprs):
        return None
    free = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    if any(s.name.startswith("x") for s in free):
        return None
    try:
        repl, red = se.cse([se.sympify(e) for e in exprs])
        names = {sym: se.Symbol(f"c{k}") for k, (sym, _) in enumerate(repl)}
        restore = Restorer(free | {sp.Symbol(f"c{k}", real=True) for k in range(len(repl))})
        out_repl = [(restore(names[sym]), restore(e.xreplace(names))) for sym, e in repl]
        out_red = [restore(e.xreplace(names)) for e in red]
    except FAILURES:
        return None
    return out_repl, out_red
