"""A step-by-step driver over scipy's ``OdeSolver`` classes with a post-step hook.

``solve_ivp`` offers no way to change the state between steps. Constraint stabilization by projection
needs exactly that: after every accepted step the state is projected back onto the constraint manifold
and the solver continues from the projected state. This driver does the stepping, the sampling at
``t_eval`` (from the step's dense output, then passed through the same hook) and event location (sign
change of ``event(t, y)`` over a step, root found with Brent's method on the dense output), and returns
an object shaped like ``solve_ivp``'s result.

Only one-step methods can continue from a modified state: RK23, RK45, DOP853 and Radau (their last
derivative is refreshed after the hook). BDF and LSODA keep a history and are not allowed here.

Partial results
---------------
:func:`recording` wraps any scipy ``OdeSolver`` class so that every accepted step is logged in a
:class:`StepLog`: the states at the requested output times (from the step's dense output) and the last
accepted state. When a run fails — an exception from the right-hand side (a singular mass matrix, a
non-finite value, a math domain error) or a collapsed step size — the log still holds everything computed
up to the last accepted step, which :mod:`lagrange.integrate.run` returns as the ``partial`` trajectory of
the error. Both ``solve_ivp`` (which accepts a solver class as ``method``) and :func:`step_loop` use it.
Ctrl-C during such a run (a KeyboardInterrupt raised in the right-hand side or in scipy's Python code) is
turned by :func:`interrupted_run` into :class:`~lagrange.errors.IntegrationInterrupted` carrying the same
partial trajectory.
"""

from __future__ import annotations

from dataclasses import field

import numpy as np
from scipy.integrate import BDF, DOP853, LSODA, RK23, RK45, OdeSolver, Radau
from scipy.optimize import brentq

from ..errors import IntegrationError
from ..records import record

__all__ = ["step_loop", "STEPPABLE", "StepResult", "StepLog", "recording", "interrupt_of", "interrupted_run"]

STEPPABLE = {"RK23": RK23, "RK45": RK45, "DOP853": DOP853, "Radau": Radau}


@record
class StepResult:
    t: np.ndarray
    y: np.ndarray  # (n_state, n_times), like solve_ivp
    nfev: int
    status: int
    message: str
    success: bool
    t_events: list = field(default_factory=list)
    y_events: list = field(default_factory=list)


SOLVERS = {**STEPPABLE, "LSODA": LSODA, "BDF": BDF}


class StepLog:
    """What a run has computed so far: states at the output times ``t_eval`` reached by accepted steps,
    and the last accepted ``(t, y)``.

    ``t_eval`` must be ordered in the direction of integration (as ``solve_ivp`` requires).
    """

    def __init__(self, t_eval, max_steps: int | None = None):
        self.t_eval = np.asarray(t_eval, dtype=float)
        self.max_steps = max_steps
        self.t: list[float] = []
        self.y: list[np.ndarray] = []
        self.last: tuple[float, np.ndarray] | None = None
        self.steps = 0
        self._k = 0
        #: the last ``(t, z)`` since the last accepted step at which the model's solve failed (a trial stage the
        #: right-hand side answered with NaN, so the step was rejected and shrunk), and how many in all
        self.trial_fault: tuple[float, np.ndarray] | None = None
        self.trial_faults = 0

    def fault(self, t: float, z: np.ndarray) -> None:
        """Note a failed solve in a trial stage at ``(t, z)`` (see :attr:`trial_fault`)."""
        self.trial_fault = (float(t), np.array(z, dtype=float))
        self.trial_faults += 1

    def start(self, t0: float, y0: np.ndarray, direction: float) -> None:
        self._dir = direction if direction != 0 else 1.0
        self.last = (float(t0), np.array(y0, dtype=float))
        while self._k < len(self.t_eval) and (self.t_eval[self._k] - t0) * self._dir <= 0:
            if self.t_eval[self._k] == t0 and not self.t:
                self.t.append(float(t0))
                self.y.append(np.array(y0, dtype=float))
            self._k += 1

    def accept(self, solver: OdeSolver) -> None:
        """Log the step just accepted by ``solver`` (from ``solver.t_old`` to ``solver.t``)."""
        t_new = solver.t
        self.steps += 1
        self.trial_fault = None
        dense = None
        while self._k < len(self.t_eval) and (self.t_eval[self._k] - t_new) * self._dir <= 0:
            te = self.t_eval[self._k]
            if te == t_new:
                self.y.append(np.array(solver.y, dtype=float))
            else:
                dense = dense or solver.dense_output()
                self.y.append(np.asarray(dense(te), dtype=float))
            self.t.append(float(te))
            self._k += 1
        self.last = (float(t_new), np.array(solver.y, dtype=float))
        if self.max_steps is not None and self.steps >= self.max_steps and solver.status == "running":
            raise IntegrationError(f"the run took max_steps={self.max_steps:,} steps and stopped at t={t_new:.9g}, "
                                   "before the end of its span: raise max_steps, loosen rtol/atol, shorten the span, "
                                   "or try a stiff method (method='Radau' or 'LSODA') if the steps are tiny",
                                   t=float(t_new))

    def arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """``(t, Y)`` with Y of shape (m, n_state): the output times reached, then the last accepted state
        when it lies beyond them (the time where the run stopped)."""
        k = min(len(self.t), len(self.y))  # equal, unless Ctrl-C came between the two appends of accept()
        ts, ys = list(self.t[:k]), list(self.y[:k])
        if self.last is not None and (not ts or (self.last[0] - ts[-1]) * self._dir > 0):
            ts.append(self.last[0])
            ys.append(self.last[1])
        n = len(self.last[1]) if self.last is not None else 0
        return np.array(ts, dtype=float), np.array(ys, dtype=float).reshape(len(ts), n)


def recording(method: str | type, log: StepLog) -> type:
    """A subclass of the scipy solver ``method`` (name or class) that logs every accepted step in ``log``."""
    base = SOLVERS[method] if isinstance(method, str) else method

    class Recording(base):
        def __init__(self, fun, t0, y0, t_bound, **kwargs):
            super().__init__(fun, t0, y0, t_bound, **kwargs)
            log.start(t0, self.y, np.sign(t_bound - t0))

        def step(self):
            message = super().step()
            if self.status != "failed":
                log.accept(self)
            return message

        def dense_output(self):
            # one interpolant per step, shared by the log and solve_ivp (DOP853's costs 3 evaluations)
            if getattr(self, "_dense_at", None) != (self.t_old, self.t):
                self._dense_at, self._dense = (self.t_old, self.t), super().dense_output()
            return self._dense

    Recording.__name__ = Recording.__qualname__ = f"Recording{base.__name__}"
    return Recording


def _solver_class(method: str | type) -> type:
    if isinstance(method, str):
        if method not in STEPPABLE:
            raise ValueError(f"method {method!r} cannot continue from a projected state; use one of "
                             f"{sorted(STEPPABLE)}")
        return STEPPABLE[method]
    if not (isinstance(method, type) and issubclass(method, tuple(STEPPABLE.values()))):
        raise ValueError(f"method {method!r} cannot continue from a projected state; use one of {sorted(STEPPABLE)}")
    return method


def _event_sign_change(g0: float, g1: float, direction: float) -> bool:
    """A zero crossing from g0 to g1 in the requested direction; a start exactly on zero is not one."""
    if g0 == 0 or g0 == g1 or (np.sign(g0) == np.sign(g1) and g1 != 0):
        return False
    up = g1 > g0
    return direction == 0 or (direction > 0 and up) or (direction < 0 and not up)


def step_loop(fun, t_span, y0, *, method: str, t_eval, events=None, post_step=None, rtol=1e-9, atol=1e-11,
              max_step=np.inf, jac=None) -> StepResult:
    """Integrate ``y' = fun(t, y)`` step by step; ``post_step(t, y) -> y`` may modify each accepted state.

    ``method`` is a name in :data:`STEPPABLE` or a subclass of one of those solvers (e.g. from
    :func:`recording`).
    """
    cls = _solver_class(method)
    t0, t1 = t_span
    kwargs = dict(rtol=rtol, atol=atol, max_step=max_step)
    if jac is not None and issubclass(cls, Radau):
        kwargs["jac"] = jac
    solver = cls(fun, t0, np.array(y0, dtype=float), t1, **kwargs)
    events = list(events or [])
    g_old = [float(ev(t0, solver.y)) for ev in events]
    t_events = [[] for _ in events]
    y_events = [[] for _ in events]
    t_eval = np.asarray(t_eval, dtype=float)
    out_t, out_y = [], []
    k = 0
    while k < len(t_eval) and t_eval[k] <= t0:
        if t_eval[k] == t0:
            out_t.append(t0)
            out_y.append(solver.y.copy())
        k += 1
    status, message = 0, "The solver successfully reached the end of the integration interval."
    while solver.status == "running":
        msg = solver.step()
        if solver.status == "failed":
            status, message = -1, msg or "step failed"
            break
        t_old, t_new = solver.t_old, solver.t
        dense = solver.dense_output()
        if post_step is not None:
            y_new = post_step(t_new, solver.y)
            if y_new is not solver.y:
                solver.y = np.asarray(y_new, dtype=float)
                solver.f = solver.fun(t_new, solver.y)
        # events over (t_old, t_new]
        stop_at = None
        for i, ev in enumerate(events):
            g_new = float(ev(t_new, solver.y))
            if _event_sign_change(g_old[i], g_new, getattr(ev, "direction", 0)):
                te = brentq(lambda s, ev=ev, dense=dense: float(ev(s, dense(s))), t_old, t_new, xtol=1e-14)
                ye = dense(te)
                if post_step is not None:
                    ye = post_step(te, ye)
                t_events[i].append(te)
                y_events[i].append(ye)
                if getattr(ev, "terminal", False) and (stop_at is None or te < stop_at[0]):
                    stop_at = (te, ye)
            g_old[i] = g_new
        t_hi = t_new if stop_at is None else stop_at[0]
        while k < len(t_eval) and t_eval[k] <= t_hi:
            yk = dense(t_eval[k]) if t_eval[k] != t_new else solver.y.copy()
            if post_step is not None and t_eval[k] != t_new:
                yk = post_step(t_eval[k], yk)
            out_t.append(t_eval[k])
            out_y.append(np.array(yk, dtype=float))
            k += 1
        if stop_at is not None:
            status, message = 1, "A termination event occurred."
            break
    Y = np.array(out_y).T if out_y else np.empty((len(y0), 0))
    return StepResult(np.array(out_t), Y, int(solver.nfev), status, message, status >= 0,
                      [np.array(v) for v in t_events], [np.array(v) for v in y_events])


def interrupt_of(exc: BaseException) -> KeyboardInterrupt | None:
    """The KeyboardInterrupt behind ``exc``: itself, or the cause of a ``SystemError`` raised when Ctrl-C
    arrived while numba boxed a compiled right-hand side's result (boxing calls Python, where the pending
    signal raises; numba then reports "returned a result with an exception set"); else None."""
    seen = 0
    while exc is not None and seen < 8:
        if isinstance(exc, KeyboardInterrupt):
            return exc
        if not isinstance(exc, SystemError):
            return None
        exc, seen = exc.__cause__ or exc.__context__, seen + 1
    return None


def interrupted_run(model, log: StepLog, conservative: bool, t0: float, y0, method: str):
    """Ctrl-C during a scipy-driven run as :class:`~lagrange.errors.IntegrationInterrupted`, whose
    ``partial`` is the trajectory up to the last accepted step (from ``log``; None before the first)."""
    from ..errors import IntegrationInterrupted
    from ..model.coordinates import state_text
    from ..results.trajectory import Trajectory

    n2 = 2 * model.n
    T, Z = log.arrays()
    coords = model.equations.coordinates
    if not len(T):
        return IntegrationInterrupted(f"the {method} run was interrupted (Ctrl-C) before its first step", t=t0)
    partial = Trajectory(t=T, y=Z[:, :n2].copy(), model=model, method=f"{method} (interrupted)", success=False,
                         message=f"interrupted by Ctrl-C at t={T[-1]:.9g}", nfev=log.steps,
                         work=None if conservative else Z[:, n2].copy(), initial=(t0, np.array(y0).copy()))
    return IntegrationInterrupted(
        f"the {method} run was interrupted (Ctrl-C) at t={T[-1]:.9g} ({state_text(coords, Z[-1, :n2])}); the "
        f"trajectory up to there ({len(T)} points) is in the exception's `partial` attribute.",
        t=float(T[-1]), state=dict(zip(coords, Z[-1, :n2])), partial=partial)
