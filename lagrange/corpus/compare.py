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
import numpy as np
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


#: Gauss–Legendre nodes per variable of a multiple integral in :func:`_quadrature` (double precision)
MULTIPLE_NODES = 64


def _quadrature(expr, point):
    """``expr`` at ``point`` with every definite integral done numerically (a book answer written as an integral
    over a body, Wells ch. 6); sympy's own ``Integral.evalf`` takes seconds each. A single integral: 30-digit
    mpmath quadrature on 8 panels (sharp but smooth integrands). A multiple integral (a plate): a
    :data:`MULTIPLE_NODES`-point Gauss–Legendre rule per variable in double precision (inner limits at the outer
    nodes), accurate to round-off for the analytic integrands the problems' ranges give (nested 30-digit
    quadrature took minutes per point)."""
    expr = sp.sympify(expr).xreplace(point)

    def one(integral):
        inner = integral.function.replace(lambda e: isinstance(e, sp.Integral), one)
        limits = integral.limits
        if any(len(lim) != 3 for lim in limits):
            return integral.func(inner, *limits)
        variables = [lim[0] for lim in limits]
        if inner.free_symbols - set(variables) or any(
                sp.sympify(e).free_symbols - set(variables[k + 1:]) for k, lim in enumerate(limits) for e in lim[1:]):
            return integral.func(inner, *limits)
        if len(limits) > 1:
            return sp.Float(_tensor_gauss(inner, limits), 17)
        var, lo, hi = limits[0]
        f = sp.lambdify(var, inner, "mpmath")
        with mpmath.workdps(30):
            a, b = (mpmath.mpf(str(sp.N(e, 35))) for e in (lo, hi))
            return sp.Float(mpmath.quad(f, mpmath.linspace(a, b, 9)), 30)  # 8 panels: sharp but smooth integrands

    return expr.replace(lambda e: isinstance(e, sp.Integral), one)


def _tensor_gauss(inner, limits) -> float:
    """The multiple integral of ``inner`` over ``limits`` (innermost first) by a tensor Gauss–Legendre rule."""
    x, w = np.polynomial.legendre.leggauss(MULTIPLE_NODES)
    variables = [lim[0] for lim in limits]
    f = sp.lambdify(variables, inner, "numpy")
    ends = [sp.lambdify(variables[k + 1:], sp.Tuple(*lim[1:]), "numpy") for k, lim in enumerate(limits)]

    def integrate(k, outer):
        shape = np.broadcast_shapes(*(np.shape(o) for o in outer))
        a, b = (np.broadcast_to(np.asarray(e, dtype=float), shape) for e in ends[k](*outer))
        half, mid = (b - a) / 2, (b + a) / 2
        v = mid[..., None] + half[..., None] * x
        args = [np.asarray(o)[..., None] for o in outer]
        vals = f(v, *args) if k == 0 else integrate(k - 1, (v, *args))
        return (np.broadcast_to(vals, v.shape) * w).sum(axis=-1) * half

    with np.errstate(all="ignore"):
        return float(integrate(len(limits) - 1, ()))


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
