r"""Values of a system's time-varying inputs (:mod:`lagrange.model.inputs`) at simulate time.

Generated code takes the inputs as the last entries of its parameter vector ``p``
(:attr:`~lagrange.derive.equations.Equations.numeric_parameters`, from
:attr:`~lagrange.derive.equations.Equations.input_offset` on). A **constant** input is bound there once, like a
parameter, so every route runs it — the compiled loops and the Taylor tape included. A **time-varying** input
is an :class:`InputSchedule` attached to the :class:`~lagrange.codegen.numeric.NumericModel`
(:meth:`~lagrange.codegen.numeric.NumericModel.with_schedule`), whose right-hand side then refills those
slots with ``u(t, y)`` at every evaluation; only the routes that call the model from Python per step accept
it (the scipy methods, friction events, constraints with projection or Baumgarte).

Accepted values, for each input ``u`` (keys: the :class:`~lagrange.model.inputs.Input` or its name):

``number``
    a constant (int, float, NumPy or sympy number).
``u(t)``
    a callable of one positional argument, the time (e.g. ``lambda t: F0*np.cos(w*t)``, or a
    :class:`scipy.interpolate.CubicSpline` for cubic interpolation of samples).
``u(t, y)``
    a callable of two positional arguments: a feedback law of the time and the state
    ``y = [q, q̇]`` (ndarray, shape (2n,), the coordinates in the system's order then their velocities).
``(t_samples, values)``
    sampled data, interpolated **linearly** (``scipy.interpolate.make_interp_spline`` with ``k=1``: exact at
    the samples, no overshoot); ``t_samples`` strictly increasing and covering ``t_span`` (no extrapolation).
``expression of t``
    a sympy expression in :data:`lagrange.t` alone (the form spec files give).

A callable must return one finite real number; it is called once at the initial state when the run is
prepared, so a wrong signature or shape fails before integrating. It must be a pure function of its
arguments: adaptive solvers call it at trial stages, rejected steps and out of time order, and
:attr:`Trajectory.input_values <lagrange.results.trajectory.Trajectory.input_values>` (``sol[u]``) calls it
again at the output times (a controller with internal state is a coordinate of the system, not an input).
"""

from __future__ import annotations

import inspect
import math
import numbers
from collections.abc import Callable, Mapping

import numpy as np
import sympy as sp

from ..conventions import t as time_symbol
from ..errors import InputError, IntegrationError, ParameterError
from ..model.coordinates import canonical_key
from ..records import record
from ..safe_sympify import lambdify as _lambdify

__all__ = ["InputSchedule", "resolve_inputs", "VARYING_ROUTES", "input_help"]

#: the routes that accept time-varying (callable or sampled) inputs, for refusal messages
VARYING_ROUTES = ("the scipy methods (DOP853, RK45, RK23, LSODA, Radau, BDF) run by solve_ivp (loop='scipy', "
                  "the default for python models), with friction events, constraints and events")


def input_help(name: str = "u") -> str:
    """The accepted value forms, for error messages."""
    return (f"inputs={{'{name}': value}} with a number, a function {name}(t), a feedback law {name}(t, y) of the "
            "state y = [q, q_dot], or samples (t_samples, values)")


@record(frozen=True)
class InputSchedule:
    """The values of a system's inputs along a run: ``schedule(t, y)`` → list of floats, one per input in the
    order of ``Equations.inputs``.

    Attributes
    ----------
    inputs : tuple of Input symbols (``Equations.inputs``)
    kinds : tuple of ``"constant"``, ``"time"``, ``"state"`` or ``"samples"``, one per input
    functions : tuple — the float for a constant, else a callable (``f(t)``, or ``f(t, y)`` for ``"state"``)
    """

    inputs: tuple
    kinds: tuple
    functions: tuple

    @property
    def varying(self) -> bool:
        """True when some input is not constant."""
        return any(k != "constant" for k in self.kinds)

    @property
    def feedback(self) -> bool:
        """True when some input depends on the state."""
        return "state" in self.kinds

    def __call__(self, t: float, y) -> list:
        """The input values at ``(t, y)``, ``y = [q, q̇]`` (shape (2n,))."""
        out = []
        for u, kind, fn in zip(self.inputs, self.kinds, self.functions):
            if kind == "constant":
                out.append(fn)
                continue
            try:
                v = fn(t, np.array(y, dtype=float)) if kind == "state" else fn(t)
                v = float(v)
            except Exception as exc:  # a user's function: report which input failed where
                raise IntegrationError(f"the value of the input {u} failed at t={t:.9g}: {type(exc).__name__}: "
                                       f"{exc}", t=float(t)) from exc
            if not math.isfinite(v):
                raise IntegrationError(f"the input {u} is {v} at t={t:.9g}: its value must be finite", t=float(t))
            out.append(v)
        return out

    def many(self, t, Y) -> np.ndarray:
        """Input values at many points: ``t`` shape (m,), ``Y`` shape (m, 2n) → shape (m, k)."""
        t = np.asarray(t, dtype=float)
        return np.array([self(ti, yi) for ti, yi in zip(t, np.asarray(Y, dtype=float))],
                        dtype=float).reshape(len(t), len(self.inputs))

    def describe(self) -> str:
        return ", ".join(f"{u}: {k}" for u, k in zip(self.inputs, self.kinds))


def resolve_inputs(eqs, values: Mapping | None, t_span, y0) -> tuple[dict, InputSchedule | None]:
    """Check the input values of a run and split them: ``(constants, schedule)``.

    Parameters
    ----------
    eqs : Equations — its ``inputs`` each need a value
    values : mapping ``{input or name: value}`` (forms in the module docstring)
    t_span : (t0, t1) — sampled inputs must cover it
    y0 : ndarray, shape (2n,) — callables are probed at ``(t0, y0)``

    Returns
    -------
    constants : dict ``{name: float}`` for every input: a constant's value, a varying input's value at
        ``(t0, y0)`` (bound in ``p`` before the schedule takes over; used for the method choice)
    schedule : InputSchedule, or None when every input is constant

    Raises
    ------
    ParameterError
        Missing, unknown or non-finite values, samples that do not cover ``t_span`` or are not increasing,
        a callable whose value at the initial state is not one finite number (all listed).
    InputError
        A callable that is neither ``u(t)`` nor ``u(t, y)``.
    """
    values = dict(values or {})
    by_name: dict = {}
    problems: list[str] = []
    wanted = [u.name for u in eqs.inputs]
    for key, value in values.items():
        key = canonical_key(key, (), eqs.inputs)  # sympy's specifieds u(t) name inputs too
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        if name not in wanted:
            problems.append(f"{name} is not an input of this system (its inputs: {', '.join(wanted) or 'none'})")
            continue
        by_name[name] = value
    missing = [n for n in wanted if n not in by_name]
    if missing:
        problems.append(f"missing value(s) for input(s) {', '.join(missing)}: give each at simulate time, "
                        + input_help(missing[0]))
    t0, t1 = float(t_span[0]), float(t_span[1])
    kinds, functions, constants = [], [], {}
    for u in eqs.inputs:
        if u.name not in by_name:
            continue
        kind, fn = _classify(u, by_name[u.name], (t0, t1), problems)
        if kind is None:
            continue
        if kind == "constant":
            v = fn
        else:
            v = _probe(u, kind, fn, t0, y0, problems)
            if v is None:
                continue
        kinds.append(kind)
        functions.append(fn)
        constants[u.name] = v
    if problems:
        raise ParameterError("; ".join(problems))
    schedule = InputSchedule(tuple(eqs.inputs), tuple(kinds), tuple(functions))
    return constants, (schedule if schedule.varying else None)


def _number(value) -> float | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, numbers.Real) or (isinstance(value, np.ndarray) and value.ndim == 0):
        return float(value)
    if isinstance(value, sp.Basic) and value.is_number:
        try:
            return float(value.evalf())
        except TypeError:
            return None
    return None


def _classify(u, value, t_span, problems) -> tuple[str | None, object]:
    """``(kind, function or float)`` of one input's value, or ``(None, None)`` after recording a problem."""
    v = _number(value)
    if v is not None:
        if not math.isfinite(v):
            problems.append(f"input {u} = {v} is not finite")
            return None, None
        return "constant", v
    if isinstance(value, sp.Basic):
        extra = value.free_symbols - {time_symbol}
        if extra:
            problems.append(f"input {u} = {value} contains {', '.join(sorted(map(str, extra)))}: an expression "
                            "value may contain lagrange.t only (substitute the parameters' values)")
            return None, None
        return "time", _lambdify(time_symbol, value, modules="math", where=f"the value of input {u}")
    if isinstance(value, (str, bytes)):
        problems.append(f"input {u} = {value!r} is a string: strings are never evaluated; "
                        + input_help(u.name))
        return None, None
    if callable(value):
        return _callable_kind(u, value), value
    if isinstance(value, (tuple, list)) and len(value) == 2:
        fn = _samples(u, value, t_span, problems)
        return ("samples", fn) if fn is not None else (None, None)
    problems.append(f"input {u} = {value!r} is not a value: " + input_help(u.name))
    return None, None


def _callable_kind(u, fn: Callable) -> str:
    """``"time"`` for ``u(t)``, ``"state"`` for ``u(t, y)``; :class:`InputError` otherwise."""
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # a NumPy ufunc or a builtin: its number of inputs, if it says
        nin = getattr(fn, "nin", None)
        if nin in (1, 2):
            return "time" if nin == 1 else "state"
        raise InputError(f"the input {u}'s function {fn!r} has no inspectable signature: wrap it, "
                         f"lambda t: ... for {u}(t) or lambda t, y: ... for a feedback law {u}(t, y)") from None
    positional = [p for p in sig.parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    required = [p for p in positional if p.default is p.empty]
    required_kw = [p for p in sig.parameters.values() if p.kind == p.KEYWORD_ONLY and p.default is p.empty]
    if required_kw or len(required) not in (1, 2):
        raise InputError(f"the input {u}'s function must take (t) or (t, y) — y = [q, q_dot] the state — but its "
                         f"signature is {sig}: write {u}(t) for a function of time or {u}(t, y) for feedback")
    return "time" if len(required) == 1 else "state"


def _probe(u, kind, fn, t0, y0, problems) -> float | None:
    """The value at the initial state, checked to be one finite real number."""
    try:
        raw = fn(t0, np.array(y0, dtype=float)) if kind == "state" else fn(t0)
    except Exception as exc:  # a user's function: name the input and the call
        call = f"{u}(t0, y0)" if kind == "state" else f"{u}(t0)"
        problems.append(f"the input {u} failed at the initial state: {call} raised {type(exc).__name__}: {exc}")
        return None
    if np.ndim(raw) != 0 or isinstance(raw, (complex, np.complexfloating)):
        problems.append(f"the input {u} must give one real number, but its value at t={t0:g} is {raw!r} "
                        f"(shape {np.shape(raw)})")
        return None
    try:
        v = float(raw)
    except (TypeError, ValueError):
        problems.append(f"the input {u}'s value at t={t0:g} is {raw!r}, not a number")
        return None
    if not math.isfinite(v):
        problems.append(f"the input {u} is {v} at t={t0:g}: its value must be finite")
        return None
    return v


def _samples(u, value, t_span, problems) -> Callable | None:
    """Linear interpolation of ``(t_samples, values)`` (scipy's ``make_interp_spline``, ``k=1``)."""
    from scipy.interpolate import make_interp_spline

    try:
        ts = np.asarray(value[0], dtype=float)
        vs = np.asarray(value[1], dtype=float)
    except (TypeError, ValueError):
        problems.append(f"input {u}: samples must be two arrays of numbers (t_samples, values)")
        return None
    if ts.ndim != 1 or vs.shape != ts.shape or len(ts) < 2:
        problems.append(f"input {u}: t_samples and values must be 1-D arrays of the same length >= 2, got shapes "
                        f"{ts.shape} and {vs.shape}")
        return None
    if not (np.all(np.isfinite(ts)) and np.all(np.isfinite(vs))):
        problems.append(f"input {u}: the samples contain non-finite numbers")
        return None
    if np.any(np.diff(ts) <= 0):
        problems.append(f"input {u}: t_samples must be strictly increasing")
        return None
    lo, hi = min(t_span), max(t_span)
    if lo < ts[0] or hi > ts[-1]:
        problems.append(f"input {u}: the samples cover t in [{ts[0]:g}, {ts[-1]:g}] but t_span is "
                        f"[{t_span[0]:g}, {t_span[1]:g}]; inputs are not extrapolated: extend the samples")
        return None
    spline = make_interp_spline(ts, vs, k=1)

    def sampled(t_):
        return float(spline(t_))

    return sampled
