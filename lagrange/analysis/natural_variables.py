r"""Integrals in a field's natural variables, and the zero checks that verify their results.

A force written with a distance ``d = B^{1/2}`` (or any power ``B^p`` of an expression) is most easily integrated
in ``u = B``: a term ``g(B) ∂B/∂s`` has the antiderivative ``G(B)`` with ``G' = g``, whatever coordinates ``s``
stands for. Expanding such a term first (``B^{3/2} → B·√B``, the base multiplied out) hides ``B`` from sympy's
``integrate``; :func:`expand_keeping_powers` expands everything else and :func:`integrate_by_substitution`
integrates the groups of terms that have that form. :func:`numerically_zero` evaluates at random points in
30-digit arithmetic (fixed precision: an expression that vanishes by cancellation costs no more than any other),
and :func:`zero_in_bases` proves an identity with each such power written as a power of one symbol.
"""

from __future__ import annotations

import random

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef

from ..errors import SymbolicTimeoutError
from ..simplification import _probe, _sample, is_zero, run_bounded

__all__ = ["expand_keeping_powers", "integrate_by_substitution", "numerically_zero", "vanishes", "zero_in_bases"]


def vanishes(e) -> bool:
    """Zero after expansion, at random points, or proven zero: good enough to move on while building a result
    that is verified as a whole afterwards (as :func:`lagrange.potential_of` does)."""
    if e == 0 or expand_keeping_powers(e) == 0:
        return True
    numeric = numerically_zero(e, sp.Add.make_args(e))
    return numeric if numeric is not None else is_zero(e)


def numerically_zero(e, parts) -> bool | None:
    """True when ``|e| ≤ 1e-20·(1 + Σ|parts|)`` at six random exact points (30-digit arithmetic), False when
    it is larger at one, None when it cannot be evaluated (undefined functions, or undefined everywhere tried)."""
    parts = list(parts)
    if any(x.atoms(AppliedUndef, sp.Derivative) for x in (e, *parts)):  # given functions: values of their own
        probe = _probe(e)
        return None if probe is None else not probe
    symbols = sorted(set().union(e.free_symbols, *(p.free_symbols for p in parts)), key=sp.default_sort_key)
    try:
        f = sp.lambdify(symbols, [e, *parts], modules="mpmath")
    except (TypeError, ValueError, NameError, SyntaxError):  # a function mpmath lacks: the exact probe
        probe = _probe(e)
        return None if probe is None else not probe
    rnd = random.Random(1729)
    good = 0
    with mpmath.workdps(30):
        for _ in range(24):
            point = [_sample(v, rnd) for v in symbols]
            try:
                values = f(*(mpmath.mpf(v.p) / v.q for v in point))
            except NameError:  # a function mpmath lacks (DiracDelta, …): the exact probe
                probe = _probe(e)
                return None if probe is None else not probe
            except (ZeroDivisionError, ValueError, TypeError, OverflowError, AttributeError):
                continue
            if not all(mpmath.isfinite(v) for v in values):
                continue
            if abs(values[0]) > mpmath.mpf("1e-20") * (1 + sum(abs(v) for v in values[1:])):
                return False
            good += 1
            if good == 6:
                return True
    return None


def expand_keeping_powers(e):
    """``expand``, keeping powers with non-integer or negative exponents, exponentials and logarithms of sums
    whole (``B^{3/2}`` is not split into ``B·√B``, ``exp(−B)`` not into a product, and ``B`` is not multiplied
    out, so the natural variable ``B`` stays visible)."""
    kept = {p: sp.Dummy() for p in e.atoms(sp.Pow) if p.base.is_Add and not (p.exp.is_Integer and p.exp > 0)}
    kept.update({f: sp.Dummy() for f in e.atoms(sp.exp, sp.log) if f.args[0].is_Add})  # exp(a + b) stays whole
    return sp.expand(e.xreplace(kept)).xreplace({v: k for k, v in kept.items()}) if kept else sp.expand(e)


def _bases(e, s) -> list:
    """The bases ``B(s)`` of the powers in ``e`` with a non-integer or negative exponent, and the arguments of
    its exponentials and logarithms, largest first."""
    bases = {p.base for p in e.atoms(sp.Pow)
             if p.base.has(s) and not p.base.is_Symbol and not (p.exp.is_Integer and p.exp > 0)}
    bases |= {f.args[0] for f in e.atoms(sp.exp, sp.log) if f.args[0].has(s) and not f.args[0].is_Symbol}
    return sorted(bases, key=lambda b: (-sp.count_ops(b), sp.default_sort_key(b)))


def integrate_by_substitution(e, s, seconds: float = 4.0):
    r"""(∫ of the terms of ``e`` that are ``g(B) ∂B/∂s`` for a base ``B`` of theirs (or the argument of an
    exponential or a logarithm), the other terms).

    Each group of terms holding ``B`` is divided by ``∂B/∂s`` with ``B`` replaced by a symbol ``u``; when the
    quotient ``g`` does not depend on ``s`` (checked at random points), ``∫ g(u) du`` is taken and ``u = B``
    put back. A quotient that only reduces to a function of ``u`` through identities such as
    ``sin² + cos² = 1`` is evaluated at a value of ``s`` instead of being simplified."""
    terms = list(sp.Add.make_args(expand_keeping_powers(e)))
    part = sp.S.Zero
    for B in _bases(e, s):
        group = [term for term in terms if term.has(B)]
        dB = sp.diff(B, s)
        if not group or vanishes(dB):
            continue
        exps = [p.exp for p in e.atoms(sp.Pow) if p.base == B]
        radicand = bool(exps) and not any(x.is_Integer for x in exps)  # B ≥ 0 where e is real
        u = sp.Dummy("u", positive=True) if radicand else sp.Dummy("u", real=True)
        g = sp.cancel(sp.Add(*group).xreplace({B: u}) / dB)
        if g.has(s):
            if not numerically_zero(sp.diff(g, s), [g]):
                continue
            g = _at_some_value(g, s)
            if g is None:
                continue
        try:
            G = run_bounded(sp.integrate, g, u, what=f"an integral in {B}", seconds=seconds)
        except SymbolicTimeoutError:
            continue
        if G.has(sp.Integral):
            continue
        part += sp.unpolarify(G).xreplace({u: B})
        terms = [term for term in terms if term not in group]
    return part, sp.Add(*terms)


def _at_some_value(g, s):
    """``g`` (independent of ``s``) at a value of ``s`` where it is defined, or None."""
    for v in (sp.Rational(3, 7), sp.Rational(11, 13), sp.Rational(-5, 9), sp.S.Zero, sp.S.One):
        out = g.xreplace({s: v})
        if not out.has(sp.zoo, sp.nan, sp.oo, -sp.oo) and numerically_zero(sp.S.Zero, [out]) is not None:
            return out
    return None


def zero_in_bases(e) -> bool:
    """Proven zero with every power ``B^p`` (non-integer or negative p) written ``u_B^p`` for a positive symbol
    ``u_B``: an identity in more variables, hence also at ``u_B = B`` (sufficient, not necessary)."""
    kept = {}
    for p in e.atoms(sp.Pow):
        if p.base.is_Add and not (p.exp.is_Integer and p.exp > 0) and p.base.free_symbols:
            kept.setdefault(p.base, sp.Dummy("u", positive=True))
    if not kept:
        return False
    e = e.xreplace(kept)
    return expand_keeping_powers(e) == 0 or is_zero(e)
