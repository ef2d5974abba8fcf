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

__all__ = ["state_text_of", "collapse_error", "model_fault", "FAULT_CAUSES", "with_partial"]


def state_text_of(model: NumericModel, y) -> str:
    return state_text(model.equations.coordinates, y)


def collapse_error(model: NumericModel, res, t0: float, y0, log: StepLog | None = None) -> IntegrationError:
    """The step size collapsed: say when (the last accepted step, from ``log`` when given), where, and what
    usually causes it."""
    n2 = 2 * model.n
    last_t = float(res.t[-1]) if len(res.t) else t0
    last_y = res.y[:n2, -1] if res.y.size else y0
    if log is not None and log.last is not None:
        last_t, last_y = log.last[0], log.last[1][:n2]
    return IntegrationError(
        f"integration stopped at t={last_t:.9g} ({state_text_of(model, last_y)}): {res.message} The step size "
        "collapsed near this state: a singularity of the model (a coordinate reaching a division by zero), "
        "a blow-up, stiffness (try method='LSODA' or 'Radau'), or Euler angles passing through gimbal lock "
        "(θ = 0 or π: use a Quaternion orientation). The trajectory up to this time is in the error's "
        "`partial` attribute; shorten t_span or use a terminal event to stop before it.",
        t=last_t,
        state=dict(zip(model.equations.coordinates, last_y)),
    )


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
