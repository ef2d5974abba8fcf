"""Faults during a run, as errors that say when, where and why, with the trajectory computed so far.

Each cause is derived from the actual failure (the exception raised while evaluating the model, the solver's
status); the options that could cause such symptoms (tolerances, output times) are validated before a run
(:mod:`lagrange.integrate.options`).
"""

from __future__ import annotations

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import IntegrationError, LagrangeError
from ..model.coordinates import state_text
from ..results.trajectory import Trajectory
from .stepper import StepLog

__all__ = ["state_text_of", "collapse_error", "collapse_cause", "model_fault", "FAULT_CAUSES", "with_partial"]


def state_text_of(model: NumericModel, y) -> str:
    return state_text(model.equations.coordinates, y)


def collapse_error(model: NumericModel, res, t0: float, y0, log: StepLog | None = None) -> IntegrationError:
    """The step size collapsed: say when (the last accepted step, from ``log`` when given), where, and the cause
    computed at that state (:func:`collapse_cause`)."""
    n2 = 2 * model.n
    ys = np.asarray(res.y, dtype=float)
    last_t = float(res.t[-1]) if len(res.t) else t0
    last_y = ys[:n2, -1] if ys.size else np.asarray(y0, dtype=float)[:n2]
    if log is not None and log.last is not None:
        last_t, last_y = log.last[0], log.last[1][:n2]
    return IntegrationError(
        f"integration stopped at t={last_t:.9g} ({state_text_of(model, last_y)}): {res.message} The step size "
        f"collapsed near this state: {collapse_cause(model, last_t, last_y, start=y0)}. The trajectory up to this "
        "time is in the error's `partial` attribute; shorten t_span or use a terminal event to stop before it.",
        t=last_t,
        state=dict(zip(model.equations.coordinates, last_y)),
    )


#: a state or right-hand side beyond this magnitude is reported as an overflow, not as a singularity
HUGE = 1e100
#: the mass matrix's condition number beyond which it is reported as (nearly) singular at a state
SINGULAR_CONDITION = 1e12
#: growth of the state's largest value since the start beyond which the collapse is reported as a blow-up
BLOWUP_GROWTH = 1e6


def _conditioning(model: NumericModel, t_: float, y, start) -> tuple[float, float]:
    """The mass matrix's condition number at ``(t_, y)`` and its smallest eigenvalue relative to that at the
    state ``start`` (1 without one); ``(inf, 0)`` when it cannot be evaluated."""
    def smallest_largest(state):
        with np.errstate(all="ignore"):
            w = np.abs(np.linalg.eigvalsh(np.asarray(model.mass_matrix(t_, state), dtype=float)))
        return (float(w.min()), float(w.max())) if w.size else (1.0, 1.0)

    try:
        lo, hi = smallest_largest(y)
        lo0 = smallest_largest(np.asarray(start, dtype=float)[:y.size])[0] if start is not None else lo
    except (np.linalg.LinAlgError, ArithmeticError, ValueError, LagrangeError):
        return np.inf, 0.0
    cond = hi / lo if lo > 0 else np.inf
    return cond, (lo / lo0 if lo0 > 0 else 1.0)


def collapse_cause(model: NumericModel, t_: float, y, start=None) -> str:
    """Why the step size collapsed at ``(t_, y)``, computed there: values overflowing (the state or its rate
    beyond :data:`HUGE` or not finite), a blow-up (the state's largest value grown :data:`BLOWUP_GROWTH`-fold
    since the state ``start``), a nearly singular mass matrix (condition number above
    :data:`SINGULAR_CONDITION`, or its smallest eigenvalue that much below the one at ``start``: a singular
    configuration, e.g. Euler angles at gimbal lock), or else a singularity of the forces or stiffness."""
    y = np.asarray(y, dtype=float)
    try:
        with np.errstate(all="ignore"):
            rate = np.asarray(model.fun(t_, y), dtype=float)
    except (ArithmeticError, ValueError, LagrangeError):
        rate = np.array([np.inf])
    if not (np.all(np.isfinite(y)) and np.max(np.abs(y), initial=0.0) < HUGE):
        return (f"the state overflows (largest value {np.max(np.abs(y)):.3g}): a blow-up (the motion escapes to "
                "infinity in finite time) or initial values, parameters or inputs too large for the model")
    if not (np.all(np.isfinite(rate)) and np.max(np.abs(rate), initial=0.0) < HUGE):
        return ("the accelerations overflow there (not finite or beyond 1e100): a blow-up, or initial values, "
                "parameters or inputs too large for the model")
    cond, shrink = _conditioning(model, t_, y, start)
    if cond > SINGULAR_CONDITION or shrink < 1 / SINGULAR_CONDITION:
        what = f"condition number {cond:.2g}" if cond > SINGULAR_CONDITION else \
            f"its smallest eigenvalue {shrink:.2g} times the initial one"
        return (f"the mass matrix is nearly singular there ({what}): a singularity of the model — a singular "
                "configuration (for Wells' Euler angles, gimbal lock at θ = 0 or π: use a Quaternion "
                "orientation) or a coordinate reaching a division by zero")
    if start is not None:
        before = max(1.0, float(np.max(np.abs(np.asarray(start, dtype=float)[:y.size]), initial=0.0)))
        if np.max(np.abs(y), initial=0.0) > BLOWUP_GROWTH * before:
            return (f"the state grew from {before:.3g} to {np.max(np.abs(y)):.3g}: a blow-up (the motion escapes to "
                    "infinity in finite time), or a step too large for the model's growth")
    return ("the state and the mass matrix are regular there, so the forces change faster than the steps can "
            "follow: a singularity of the forces (a coordinate approaching a division by zero) or stiffness "
            "(try method='LSODA' or 'Radau')")


FAULT_CAUSES = (
    (ValueError, "the model left its domain (a square root or logarithm of a negative number, or asin/acos "
                 "beyond ±1): a coordinate passed a limit of the model, or a parameter is out of range"),
    (OverflowError, "a value overflowed: a blow-up (the motion escapes to infinity in finite time) or a step "
                    "too large for the model's growth"),
    (ZeroDivisionError, "a division by zero in the model: a singular configuration (a coordinate reaching a "
                        "singular value)"),
)


def model_fault(model: NumericModel, t_: float, z, exc: Exception) -> IntegrationError:
    """An arithmetic error raised while evaluating the model, as an IntegrationError with time, state and
    the likely cause."""
    cause = next(text for kind, text in FAULT_CAUSES if isinstance(exc, kind))
    return IntegrationError(
        f"evaluating the model failed at t={t_:.9g} ({state_text_of(model, z)}): {type(exc).__name__}: {exc}. "
        f"Likely cause: {cause}.",
        t=float(t_), state=dict(zip(model.equations.coordinates, z)),
    )


def with_partial(exc: LagrangeError, model: NumericModel, log: StepLog, conservative: bool, t0: float, y0,
                  method: str) -> LagrangeError:
    """``exc`` (an IntegrationError or a mid-run SingularMassMatrixError) again, carrying ``partial``: the
    trajectory up to the last accepted step, from ``log``; ``t``/``state`` default to where that ended."""
    n2 = 2 * model.n
    T, Z = log.arrays()
    partial = None
    if len(T):
        partial = Trajectory(t=T, y=Z[:, :n2].copy(), model=model, method=f"{method} (stopped early)",
                             success=False, message=str(exc), nfev=log.steps,
                             work=None if conservative else Z[:, n2].copy(), initial=(t0, np.array(y0).copy()))
    t_fault = exc.t if getattr(exc, "t", None) is not None else (float(T[-1]) if len(T) else t0)
    state = exc.state if getattr(exc, "state", None) is not None else (
        dict(zip(model.equations.coordinates, Z[-1, :n2])) if len(T) else None)
    note = (f" The trajectory up to t={T[-1]:.9g} ({len(T)} points) is in the error's `partial` attribute."
            if partial is not None and "`partial`" not in str(exc) else "")
    out = type(exc)(str(exc) + note, t=t_fault, state=state, partial=partial)
    out.__cause__ = exc.__cause__
    return out
