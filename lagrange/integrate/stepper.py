"""A step-by-step driver over scipy's ``OdeSolver`` classes with a post-step hook.

``solve_ivp`` offers no way to change the state between steps. Constraint stabilization by projection
needs exactly that: after every accepted step the state is projected back onto the constraint manifold
and the solver continues from the projected state. This driver does the stepping, the sampling at
``t_eval`` (from the step's dense output, then passed through the same hook) and event location (sign
change of ``event(t, y)`` over a step, root found with Brent's method on the dense output), and returns
an object shaped like ``solve_ivp``'s result.

Only one-step methods can continue from a modified state: RK23, RK45, DOP853 and Radau (their last
derivative is refreshed after the hook). BDF and LSODA keep a history and are not allowed here.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import DOP853, RK23, RK45, Radau
from scipy.optimize import brentq

__all__ = ["step_loop", "STEPPABLE", "StepResult"]

STEPPABLE = {"RK23": RK23, "RK45": RK45, "DOP853": DOP853, "Radau": Radau}


@dataclass
class StepResult:
    t: np.ndarray
    y: np.ndarray  # (n_state, n_times), like solve_ivp
    nfev: int
    status: int
    message: str
    success: bool
    t_events: list = field(default_factory=list)
    y_events: list = field(default_factory=list)


def _event_sign_change(g0: float, g1: float, direction: float) -> bool:
    """A zero crossing from g0 to g1 in the requested direction; a start exactly on zero is not one."""
    if g0 == 0 or g0 == g1 or (np.sign(g0) == np.sign(g1) and g1 != 0):
        return False
    up = g1 > g0
    return direction == 0 or (direction > 0 and up) or (direction < 0 and not up)


def step_loop(fun, t_span, y0, *, method: str, t_eval, events=None, post_step=None, rtol=1e-9, atol=1e-11,
              max_step=np.inf, jac=None) -> StepResult:
    """Integrate ``y' = fun(t, y)`` step by step; ``post_step(t, y) -> y`` may modify each accepted state."""
    if method not in STEPPABLE:
        raise ValueError(f"method {method!r} cannot continue from a projected state; use one of {sorted(STEPPABLE)}")
    t0, t1 = t_span
    kwargs = dict(rtol=rtol, atol=atol, max_step=max_step)
    if jac is not None and method == "Radau":
        kwargs["jac"] = jac
    solver = STEPPABLE[method](fun, t0, np.array(y0, dtype=float), t1, **kwargs)
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
