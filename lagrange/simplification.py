"""Bounded, reproducible symbolic simplification and zero testing.

sympy's multivariate factorization (Wang's algorithm, used by ``factor``, ``trigsimp`` and ``simplify``)
draws random evaluation points from sympy's global, unseeded random generator. For a few of those draws it
runs for minutes instead of a fraction of a second (sympy issue #20456); which runs are unlucky changes from
process to process. lagrange therefore never calls these functions directly. It calls them through
:func:`run_bounded`, which

1. seeds sympy's generator with a fixed seed for the call (the caller's generator state is restored
   afterwards), so a given expression takes the same path every time, and
2. in the main thread of a POSIX process, limits each attempt to :data:`SECONDS` of wall time
   (``$LAGRANGE_SYMPY_SECONDS``, default 10) and retries with the next seed, up to :data:`ATTEMPTS` seeds.

Before any of this, the size budget of :mod:`lagrange.budget` applies: a simplification or a zero test whose
expansion would exceed it is skipped (unproven), the numeric probe skips points where an exponential or a
power would take a number of unbounded size, and a solve of too large an equation raises
:class:`~lagrange.errors.ExpressionTooLarge`.

Inside a symbolic stage (a derivation, an analysis: :mod:`lagrange.limits`) each clean-up also has at most a
share of the stage's CPU time, and the stage's deadline bounds every call here.

A simplification that does not finish is skipped (the expression is used as it is); a zero test that
cannot be proven answers ``False`` (not known to vanish); a solve that does not finish raises
:class:`~lagrange.errors.SymbolicTimeoutError`. Nothing is ever silently wrong, at worst less tidy.

:func:`is_zero` decides most cases without ``simplify``: evaluation at random exact points (at 30 and 50
digits) proves an expression nonzero, and a canonical reduction proves trigonometric polynomials zero.
"""

from __future__ import annotations

import os
import random
import signal
import threading
from collections.abc import Callable
from typing import TypeVar

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.core.random import rng as _sympy_rng

from . import limits
from .budget import fits
from .errors import SymbolicTimeoutError
from .safe_sympify import sympify as _sympify

__all__ = ["SECONDS", "ATTEMPTS", "run_bounded", "simplify", "trigsimp", "factor", "solve", "is_zero"]

SECONDS = float(os.environ.get("LAGRANGE_SYMPY_SECONDS", "10"))
"""Wall-time limit of one attempt (seconds); ``$LAGRANGE_SYMPY_SECONDS`` overrides, ``0`` disables it."""
ATTEMPTS = 4
"""Seeds tried before giving up."""

_R = TypeVar("_R")


class _Timeout(BaseException):
    """Raised inside sympy by the alarm; a BaseException so that sympy's ``except Exception`` cannot eat it."""


def _alarm(signum, frame):
    raise _Timeout


def _can_time(seconds: float) -> bool:
    return (seconds > 0 and hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
            and signal.getitimer(signal.ITIMER_REAL)[0] == 0.0)  # never disturb a caller's own timer


_depth = 0  # > 0 while a bounded call runs: nested calls inherit its seed stream and its time limit


def run_bounded(fn: Callable[..., _R], *args, what: str, seconds: float | None = None, **kwargs) -> _R:
    """``fn(*args, **kwargs)`` with sympy's random generator seeded, time-limited and retried.

    ``seconds`` per attempt (default :data:`SECONDS`). A call made inside another bounded call runs
    plainly: the outer call's seed stream and time limit cover it, so the outer retry changes every draw.
    Raises :class:`SymbolicTimeoutError` (naming ``what``) when every attempt ran out of time.
    """
    global _depth
    if _depth:
        return fn(*args, **kwargs)
    seconds = SECONDS if seconds is None else seconds
    timed = _can_time(seconds)
    state = _sympy_rng.getstate()
    _depth += 1
    try:
        for seed in range(ATTEMPTS if timed else 1):
            _sympy_rng.seed(seed)
            if not timed:
                return fn(*args, **kwargs)
            previous = signal.signal(signal.SIGALRM, _alarm)
            try:
                signal.setitimer(signal.ITIMER_REAL, seconds)
                try:
                    return fn(*args, **kwargs)
                finally:
                    signal.setitimer(signal.ITIMER_REAL, 0)
            except _Timeout:
                continue
            finally:
                signal.signal(signal.SIGALRM, previous)
    finally:
        _depth -= 1
        _sympy_rng.setstate(state)
    raise SymbolicTimeoutError(f"sympy did not finish {what} within {seconds:g} s in {ATTEMPTS} attempts "
                               "(set LAGRANGE_SYMPY_SECONDS to allow more time)")


def _or_input(fn, expr, what):
    """A clean-up: ``fn(expr)`` bounded by :func:`run_bounded` and by a share of the symbolic stage's CPU budget
    (:func:`lagrange.limits.tidy`); ``expr`` itself when either runs out."""

    def attempt(e):
        try:
            return run_bounded(fn, e, what=what)
        except SymbolicTimeoutError:
            return e

    return limits.tidy(attempt, expr, what=what)


def simplify(expr, *, limit: int | None = None):
    """``sympy.simplify``, bounded: the input is returned unchanged above ``limit`` operations, when expanding
    it would exceed the size budget (:func:`lagrange.budget.fits`), or on timeout."""
    expr = _sympify(expr)
    if limit is not None and sp.count_ops(expr) > limit:
        return expr
    if not fits(expr):
        return expr
    return _or_input(sp.simplify, expr, "simplify")


def trigsimp(expr):
    """``sympy.trigsimp``, bounded (the input unchanged above the size budget or on timeout)."""
    expr = _sympify(expr)
    return _or_input(sp.trigsimp, expr, "trigsimp") if fits(expr) else expr


def factor(expr):
    """``sympy.factor``, bounded (the input unchanged above the size budget or on timeout)."""
    expr = _sympify(expr)
    return _or_input(sp.factor, expr, "factor") if fits(expr) else expr


def solve(*args, what: str = "solve", **kwargs):
    """``sympy.solve``, bounded; raises :class:`SymbolicTimeoutError` naming ``what`` on timeout (of an attempt,
    or of the symbolic stage it runs in: :mod:`lagrange.limits`) and :class:`~lagrange.errors.ExpressionTooLarge`
    when an equation has more nodes than the stage's budget."""
    for a in args[:1]:
        for e in (a if isinstance(a, (list, tuple, sp.MatrixBase)) else [a]):
            limits.measure(e, what=f"an equation of {what}")
    return run_bounded(sp.solve, *args, what=what, **kwargs)


# ---------------------------------------------------------------------------------------------- zero test

_PROBES = 3
_DIGITS = 30


def _sample(s, rnd: random.Random):
    """An exact rational value for ``s`` respecting its sign assumptions (exact, so evaluation at higher
    precision is really more precise)."""
    if s.is_integer:
        return sp.Integer(rnd.randint(1, 5) * (-1 if s.is_negative else 1))
    x = sp.Rational(rnd.randint(3000, 17000), 10000)
    if s.is_positive or s.is_nonnegative:
        return x
    if s.is_negative or s.is_nonpositive:
        return -x
    return x if rnd.random() < 0.5 else -x


def _probe(expr) -> bool | None:
    """True if ``expr`` is nonzero at some random point (a proof that it does not vanish identically),
    False if it vanishes at every probe, None if it could not be evaluated.

    Each point is evaluated at 30 and at 50 digits: a value that is really there agrees between the two;
    rounding noise left by cancellation does not. Undefined functions and derivatives are probed as
    independent values (sound: at one instant a function and its derivatives can take any values)."""
    atoms = sorted(expr.atoms(AppliedUndef, sp.Derivative), key=sp.default_sort_key)
    stand_in = {a: sp.Dummy(f"v{i}", real=True) for i, a in enumerate(atoms)}
    e = expr.xreplace(stand_in) if stand_in else expr
    symbols = sorted(e.free_symbols, key=sp.default_sort_key)
    rnd = random.Random(20456)
    zero_points = 0
    hazards = _hazards(e)
    for _ in range(6 * _PROBES):
        point = {s: _sample(s, rnd) for s in symbols}
        if not _safe_at(hazards, point):
            continue
        at = e.xreplace(point)
        try:
            lo, hi = complex(at.evalf(_DIGITS)), complex(at.evalf(_DIGITS + 20))
        except (TypeError, ValueError, ZeroDivisionError, OverflowError):
            continue
        if not all(abs(v) < float("inf") for v in (lo, hi)):  # also rejects NaN
            continue
        if hi != 0 and abs(lo - hi) <= 1e-8 * abs(hi):
            return True
        zero_points += 1
        if zero_points == _PROBES:
            return False
    return None


#: an exponential whose argument, or a power whose exponent, exceeds this in magnitude at a point is not
#: evaluated there: arbitrary-precision arithmetic would work with numbers of unbounded size (exp(exp(x))
#: at x = 10 has 10⁹⁵¹⁰ digits before the decimal point; x**(10**30) at x = 13/10 is exact)
_EVALUATION_LIMIT = 10_000


def _hazards(e) -> list:
    """The exponentials and the powers of ``e`` whose size depends on a value, inner ones first."""
    from .budget import _EXPONENTIAL, _postorder

    out = []
    for node in _postorder(e):
        if isinstance(node, _EXPONENTIAL) or (node.is_Pow and not (node.exp.is_Number
                                                                   and abs(node.exp) <= _EVALUATION_LIMIT)):
            out.append(node)
    return out


def _safe_at(hazards: list, point: dict) -> bool:
    """True when every argument of an exponential and every exponent of ``hazards`` stays within
    :data:`_EVALUATION_LIMIT` at ``point`` (checked inner first, so each check is itself bounded)."""
    for node in hazards:
        arg = node.args[0] if not node.is_Pow else node.exp
        if arg.is_Number:
            if abs(arg) > _EVALUATION_LIMIT:
                return False
            continue
        try:
            v = complex(arg.xreplace(point).evalf(15))
        except (TypeError, ValueError, ZeroDivisionError, OverflowError):
            return False
        if not abs(v) <= _EVALUATION_LIMIT:  # also NaN
            return False
    return True


def _trig_polynomial_zero(expr) -> bool:
    """True if ``expr``'s numerator, as a polynomial in sin u, cos u, reduces to 0 modulo sin²u + cos²u − 1.

    The relations for distinct arguments form a Gröbner basis, so the remainder is a canonical form: a zero
    remainder proves the expression vanishes identically. (A nonzero one proves nothing when the arguments
    are dependent, e.g. u and u/2.)"""
    e = sp.expand_trig(expr.replace(sp.tan, lambda u: sp.sin(u) / sp.cos(u)))
    num = sp.expand(sp.numer(sp.together(e)))
    if num == 0:
        return True
    args = sorted({f.args[0] for f in num.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    if not args:
        return False
    s = [sp.Dummy(f"s{i}") for i in range(len(args))]
    c = [sp.Dummy(f"c{i}") for i in range(len(args))]
    rep = {}
    for u, si, ci in zip(args, s, c):
        rep[sp.sin(u)] = si
        rep[sp.cos(u)] = ci
    p = num.xreplace(rep)
    if p.has(sp.sin, sp.cos):
        return False
    try:
        _, rem = sp.reduced(p, [si**2 + ci**2 - 1 for si, ci in zip(s, c)], *s, *c)
    except (sp.PolynomialError, sp.polys.polyerrors.PolificationFailed):
        return False
    return sp.expand(rem) == 0


def is_zero(expr, *, limit: int = 300) -> bool:
    """True when ``expr`` is proven to vanish identically; False when it does not, or cannot be proven to.

    Order: structural zero; numeric probe (nonzero somewhere → False); ``expand``; the canonical reduction
    of trigonometric polynomials; bounded ``simplify``. Above ``limit`` operations an expression with symbols
    stops after the probe (unproven → False) and a constant skips only ``simplify``.
    """
    expr = _sympify(expr)
    if expr == 0:
        return True
    if _probe(expr) is True:
        return False
    big = sp.count_ops(expr) > limit
    if big and expr.free_symbols:  # too big to prove anything about within bounded time
        return False
    if not fits(expr):  # expanding would exceed the size budget (lagrange.budget): unproven
        return False
    if sp.expand(expr) == 0:
        return True
    try:
        if run_bounded(_trig_polynomial_zero, expr, what="a trigonometric zero test"):
            return True
    except SymbolicTimeoutError:
        pass
    return not big and simplify(expr) == 0
