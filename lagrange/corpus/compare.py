"""Deciding whether two symbolic results agree: structurally, by bounded simplify, or numerically.

Numeric comparison evaluates both sides with mpmath at 30 significant digits at several random points
(parameters and coordinates drawn from ranges that keep square roots real), and requires agreement to
``rtol`` relative to the size of the values. A point where either side is not a finite real number is
redrawn.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence

import mpmath
import sympy as sp

__all__ = ["numeric_points", "agree", "Mismatch"]

DEFAULT_RANGE = (0.15, 0.85)
PARAMETER_RANGE = (1.1, 2.3)


class Mismatch(Exception):
    """Raised with a message when two results disagree."""


def numeric_points(symbols: Sequence[sp.Symbol], count: int, *, seed: int = 1234,
                   ranges: Mapping | None = None, parameters: Sequence = ()) -> list[dict]:
    """Random substitution dicts: parameters from PARAMETER_RANGE, everything else from DEFAULT_RANGE."""
    rng = random.Random(seed)
    ranges = dict(ranges or {})
    by_name = {getattr(k, "name", str(k)): v for k, v in ranges.items()}
    params = set(parameters)
    pts = []
    for _ in range(count):
        pt = {}
        for s in symbols:
            lo, hi = by_name.get(s.name, PARAMETER_RANGE if s in params else DEFAULT_RANGE)
            pt[s] = sp.Float(rng.uniform(lo, hi), 30)
        pts.append(pt)
    return pts


def _quadrature(expr, point):
    """``expr`` at ``point`` with every definite integral done by 30-digit mpmath quadrature (a book answer
    written as an integral over a body, Wells ch. 6); sympy's own ``Integral.evalf`` takes seconds each."""
    expr = sp.sympify(expr).xreplace(point)

    def one(integral):
        inner = integral.function.replace(lambda e: isinstance(e, sp.Integral), one)
        if len(integral.limits) != 1 or len(integral.limits[0]) != 3:
            return integral.func(inner, *integral.limits)
        var, lo, hi = integral.limits[0]
        if inner.free_symbols - {var} or sp.sympify(lo).free_symbols or sp.sympify(hi).free_symbols:
            return integral.func(inner, *integral.limits)
        f = sp.lambdify(var, inner, "mpmath")
        with mpmath.workdps(30):
            a, b = (mpmath.mpf(str(sp.N(e, 35))) for e in (lo, hi))
            return sp.Float(mpmath.quad(f, mpmath.linspace(a, b, 9)), 30)  # 8 panels: sharp but smooth integrands

    return expr.replace(lambda e: isinstance(e, sp.Integral), one)


def _value(expr, point):
    expr = sp.sympify(expr)
    if expr.has(sp.Integral):
        expr = _quadrature(expr, point)
    v = expr.evalf(30, subs=point)
    if v.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        return None
    try:
        c = complex(v)
    except TypeError:
        return None
    if abs(c.imag) > 1e-20 * max(1.0, abs(c.real)):
        return None
    return mpmath.mpf(c.real)


def agree(a, b, symbols: Sequence[sp.Symbol], *, rtol: float = 1e-10, count: int = 6,
          ranges: Mapping | None = None, parameters: Sequence = (), what: str = "expression") -> None:
    """Raise :class:`Mismatch` unless scalar expressions ``a`` and ``b`` agree.

    First a structural/expand test; then ``count`` random points (30-digit evaluation).
    """
    diff = sp.sympify(a) - sp.sympify(b)
    if diff == 0:
        return
    try:
        if sp.count_ops(diff) < 200 and sp.expand(diff) == 0:
            return
    except Exception:  # noqa: BLE001 - expand may fail on odd input; fall back to numbers
        pass
    symbols = sorted(set(symbols) | (sp.sympify(a).free_symbols | sp.sympify(b).free_symbols), key=lambda s: s.name)
    done = 0
    tries = 0
    seed = 1234
    while done < count:
        tries += 1
        if tries > 20 * count:
            raise Mismatch(f"{what}: could not find points where both sides are finite and real")
        pt = numeric_points(symbols, 1, seed=seed + tries, ranges=ranges, parameters=parameters)[0]
        va, vb = _value(a, pt), _value(b, pt)
        if va is None or vb is None:
            continue
        scale = max(abs(va), abs(vb), mpmath.mpf(1e-30))
        if abs(va - vb) > rtol * scale and abs(va - vb) > 1e-25:
            shown = ", ".join(f"{k}={float(v):.4g}" for k, v in pt.items())
            raise Mismatch(f"{what}: {float(va):.12g} (derived) != {float(vb):.12g} (book) at {shown}")
        done += 1
