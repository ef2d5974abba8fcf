r"""The user's events (scipy-style callables ``event(t, y)``) as heyoka events: what ``method="heyoka"`` compiles.

heyoka detects events inside its compiled loop, from the Taylor expansion of an event *expression*; it cannot
call a Python function per step. So each event callable is **traced**: called once with symbolic arguments
(``t`` and ``y = [q, q̇(, w)]``, the state scipy's path passes, ``w`` the work integral of a non-conservative
system), on which arithmetic, powers, indexing and the numpy functions ``sin cos tan exp log sqrt sinh cosh
tanh`` (and ``math``-free code in general) build a sympy expression; that expression is converted to heyoka
exactly as the equations are (:mod:`lagrange.codegen.heyoka_expr`). The trace is then **checked**: the
expression and the callable are evaluated at the initial state and at perturbed states, and must agree to
1e-9 (relative). A callable that cannot be traced (it calls ``math.sin`` or ``float``, branches on the state
with ``if``, or uses a function heyoka lacks) or whose trace disagrees is refused with a
:class:`~lagrange.errors.MethodError` naming the event and the cause; never integrated as something else.

The attributes are scipy's: ``terminal`` (False, True, or an int k: stop at the k-th occurrence) and
``direction`` (> 0: rising through zero only, < 0: falling only, 0: both). Each event gets a callback object
(:class:`NonTerminalRecorder`, :class:`TerminalRecorder`, picklable, so an integrator with its events can be
stored in the on-disk cache) that records ``(t, state)`` of every occurrence in ``records``.
"""

from __future__ import annotations

import math
import numbers

import numpy as np
import sympy as sp

from ..errors import MethodError
from ..records import record
from ..safe_sympify import lambdify as _lambdify

__all__ = ["HeyokaEvent", "trace_event", "heyoka_events", "NonTerminalRecorder", "TerminalRecorder"]

_T = sp.Symbol("t", real=True)
_UNARY = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt,
          "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "negative": lambda a: -a, "positive": lambda a: a,
          "square": lambda a: a**2}
_BINARY = {"add": lambda a, b: a + b, "subtract": lambda a, b: a - b, "multiply": lambda a, b: a * b,
           "true_divide": lambda a, b: a / b, "divide": lambda a, b: a / b, "power": lambda a, b: a**b}


class _Untraceable(Exception):
    """The callable did something a symbolic trace cannot follow (the message says what)."""


def _sym(v):
    """A traced operand as sympy: a traced value's expression, a real number exactly (floats keep their bits)."""
    if isinstance(v, _Traced):
        return v.e
    if isinstance(v, bool | np.bool_):
        raise _Untraceable("a boolean in arithmetic")
    if isinstance(v, numbers.Integral):
        return sp.Integer(int(v))
    if isinstance(v, numbers.Real):
        if not math.isfinite(float(v)):
            raise _Untraceable(f"a non-finite constant {v}")
        return sp.Float(float(v))
    raise _Untraceable(f"an operand of type {type(v).__name__}")


class _Traced:
    """A symbolic stand-in for a number inside the user's callable: arithmetic builds sympy; anything that
    would need a concrete value (``float()``, ``math.*``, comparisons, ``if``) raises :class:`_Untraceable`."""

    __slots__ = ("e",)
    __array_priority__ = 1000

    def __init__(self, e):
        self.e = e

    def __add__(self, o): return _Traced(self.e + _sym(o))  # noqa: E704
    def __radd__(self, o): return _Traced(_sym(o) + self.e)  # noqa: E704
    def __sub__(self, o): return _Traced(self.e - _sym(o))  # noqa: E704
    def __rsub__(self, o): return _Traced(_sym(o) - self.e)  # noqa: E704
    def __mul__(self, o): return _Traced(self.e * _sym(o))  # noqa: E704
    def __rmul__(self, o): return _Traced(_sym(o) * self.e)  # noqa: E704
    def __truediv__(self, o): return _Traced(self.e / _sym(o))  # noqa: E704
    def __rtruediv__(self, o): return _Traced(_sym(o) / self.e)  # noqa: E704
    def __pow__(self, o): return _Traced(self.e ** _sym(o))  # noqa: E704
    def __rpow__(self, o): return _Traced(_sym(o) ** self.e)  # noqa: E704
    def __neg__(self): return _Traced(-self.e)  # noqa: E704
    def __pos__(self): return self  # noqa: E704

    def _concrete(self, *_args):
        raise _Untraceable("it needs the state as a number (float(), int(), math.*, a comparison or an `if` on "
                           "the state); write it with arithmetic and numpy functions")

    __float__ = __int__ = __index__ = __bool__ = __lt__ = __le__ = __gt__ = __ge__ = __abs__ = _concrete
    __floordiv__ = __mod__ = __rfloordiv__ = __rmod__ = _concrete

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            raise _Untraceable(f"numpy.{ufunc.__name__}.{method}")
        name = ufunc.__name__
        if name in _UNARY and len(inputs) == 1:
            return _Traced(_UNARY[name](_sym(inputs[0])))
        if name in _BINARY and len(inputs) == 2:
            return _Traced(_BINARY[name](_sym(inputs[0]), _sym(inputs[1])))
        raise _Untraceable(f"numpy.{name}, which heyoka's events do not take here (supported: "
                           f"{', '.join(sorted(_UNARY))}, arithmetic)")


for _name, _f in _UNARY.items():  # numpy calls these methods on the elements of object arrays (np.sin(y[:2]))
    setattr(_Traced, _name, lambda self, _f=_f: _Traced(_f(self.e)))


def _state_symbols(nz: int) -> list:
    return [sp.Symbol(f"y{i}", real=True) for i in range(nz)]


def _describe(event, k: int) -> str:
    return f"event {k} ({getattr(event, '__name__', type(event).__name__)})"


def trace_event(event, nz: int, k: int = 0) -> sp.Expr:
    """The sympy expression of ``event(t, y)`` over ``t`` and ``y0 … y{nz-1}`` (module docstring).

    Raises
    ------
    MethodError
        The callable cannot be traced (the cause is named), or returns a constant or a non-scalar.
    """
    y = np.empty(nz, dtype=object)
    y[:] = [_Traced(s) for s in _state_symbols(nz)]
    what = _describe(event, k)
    try:
        out = event(_Traced(_T), y)
    except _Untraceable as exc:
        raise MethodError(f"method='heyoka' compiles events into its integrator, so it traces them symbolically; "
                          f"{what} could not be traced: {exc}. Use method='DOP853' (it calls the function "
                          "per step) or rewrite the event") from None
    except Exception as exc:  # noqa: BLE001 - whatever the user's code raised on symbolic input
        raise MethodError(f"method='heyoka' traces events symbolically; {what} raised {type(exc).__name__}: "
                          f"{exc} on symbolic input. Use method='DOP853' (it calls the function per step) or "
                          "write the event with arithmetic and numpy functions") from None
    if isinstance(out, np.ndarray) and out.shape == ():
        out = out.item()
    if not isinstance(out, _Traced):
        raise MethodError(f"{what} returned {type(out).__name__} {out!r} on symbolic input, not a scalar "
                          "expression of t and y: method='heyoka' cannot compile it (use method='DOP853')")
    expr = out.e
    if not expr.free_symbols:
        raise MethodError(f"{what} is the constant {expr}: it never crosses zero (method='heyoka')")
    return expr


def _check_trace(event, expr, t0: float, z0: np.ndarray, k: int) -> None:
    """Refuse when the traced ``expr`` and ``event`` disagree at the initial state or at perturbed states."""
    syms = [_T, *_state_symbols(z0.size)]
    f = _lambdify(syms, expr, modules="numpy")
    rng = np.random.default_rng(12345)
    points = [(t0, z0)] + [(t0 + 0.37 * j, z0 + 0.1 * rng.standard_normal(z0.size) * (1 + np.abs(z0)))
                           for j in range(1, 4)]
    checked = 0
    for t, z in points:
        try:
            with np.errstate(all="ignore"):
                want = float(event(t, z.copy()))
                got = float(f(t, *z))
        except (ArithmeticError, ValueError, TypeError):
            continue
        if not (math.isfinite(want) and math.isfinite(got)):
            continue
        checked += 1
        if abs(got - want) > 1e-9 * (1 + abs(want)):
            raise MethodError(f"{_describe(event, k)}: its symbolic trace {expr} gives {got!r} at t={t:g} where the "
                              f"function gives {want!r} (it depends on something besides t and y, e.g. state it "
                              "keeps between calls): method='heyoka' cannot compile it; use method='DOP853'")
    if not checked:
        raise MethodError(f"{_describe(event, k)} is not finite at the initial state: method='heyoka' cannot check "
                          "its trace; use method='DOP853'")


def _terminal(event, k: int) -> int:
    """scipy's ``terminal``: 0 (non-terminal), 1 (True) or the number of occurrences that stop the run."""
    raw = getattr(event, "terminal", False)
    if isinstance(raw, bool | np.bool_):
        return int(bool(raw))
    if isinstance(raw, numbers.Integral) and int(raw) >= 0:
        return int(raw)
    raise MethodError(f"{_describe(event, k)}: terminal must be a bool or a non-negative int, got {raw!r}")


@record(frozen=True)
class HeyokaEvent:
    """One user event, compiled form: ``expression`` (sympy over ``t``, ``y0 …``), ``terminal`` (0: record
    only; k ≥ 1: stop at the k-th occurrence), ``direction`` (+1 rising, −1 falling, 0 both); ``key`` (text
    that names it in the integrator caches)."""

    expression: sp.Expr
    terminal: int
    direction: int

    @property
    def key(self) -> str:
        return f"{sp.srepr(self.expression)}|{self.terminal}|{self.direction}"


def heyoka_events(events, nz: int, t0: float, z0) -> tuple[HeyokaEvent, ...]:
    """Trace, check and describe the user's ``events`` (module docstring) for a state of size ``nz``.

    Raises
    ------
    MethodError
        An event that cannot be traced or whose trace disagrees with it, or a bad ``terminal``.
    """
    z0 = np.asarray(z0, dtype=float)
    out = []
    for k, ev in enumerate(events):
        expr = trace_event(ev, nz, k)
        _check_trace(ev, expr, float(t0), z0, k)
        d = float(getattr(ev, "direction", 0.0) or 0.0)
        out.append(HeyokaEvent(expr, _terminal(ev, k), int(np.sign(d))))
    return tuple(out)


class NonTerminalRecorder:
    """heyoka ``nt_event`` callback: records ``(t, state at t)`` from the dense output of the step."""

    def __init__(self):
        self.records: list = []

    def __call__(self, ta, t, d_sgn):
        ta.update_d_output(t)
        self.records.append((float(t), np.array(ta.d_output, dtype=float)))


class TerminalRecorder:
    """heyoka ``t_event`` callback: records ``(t, state)`` (the integrator is at the event) and stops the run at
    the ``count``-th occurrence (returns False)."""

    def __init__(self, count: int):
        self.count = int(count)
        self.records: list = []

    def __call__(self, ta, d_sgn):
        self.records.append((float(ta.time), np.array(ta.state, dtype=float)))
        return len(self.records) < self.count


def to_heyoka(events: tuple[HeyokaEvent, ...], hy) -> tuple[list, list, list]:
    """``(nt_events, t_events, order)``: heyoka event objects with fresh recorders; ``order[k]`` is
    ``("nt" | "t", index)`` of user event k in the integrator's event lists."""
    from .heyoka_expr import convert_expression

    nt, te, order = [], [], []
    directions = {1: hy.event_direction.positive, -1: hy.event_direction.negative, 0: hy.event_direction.any}
    for ev in events:
        expr = convert_expression(ev.expression)
        if ev.terminal:
            order.append(("t", len(te)))
            te.append(hy.t_event(expr, callback=TerminalRecorder(ev.terminal), direction=directions[ev.direction]))
        else:
            order.append(("nt", len(nt)))
            nt.append(hy.nt_event(expr, NonTerminalRecorder(), direction=directions[ev.direction]))
    return nt, te, order
