r"""``method="heyoka"``: the model's derived equations integrated by heyoka.py's adaptive Taylor method.

heyoka (Biscani & Izzo, *MNRAS* 504 (2021) 2614) compiles the Taylor recurrences of an ODE system with LLVM
and steps with Jorba & Zou's rule, as :mod:`lagrange.integrate.taylor` does. The system handed to it is the
project's own — ``M q̈ = f`` from the derivation, converted by :mod:`lagrange.codegen.heyoka_expr` and reached
through the compiled model (:meth:`~lagrange.codegen.numeric.NumericModel.heyoka_taylor`) — not a
re-derivation by heyoka. Parameters are heyoka runtime parameters, so a run with other values (a sweep)
reuses heyoka's compiled code: the ``taylor_adaptive`` integrator is built (JIT-compiled) once per system and
tolerance and kept (:func:`compilations` counts the builds); later runs reset its time, state and parameters.
Optional: ``pip install "lagrange-dynamics[heyoka]"``.

Tolerance: heyoka takes one ε with a mixed absolute/relative criterion (like ``atol = rtol``); the stricter of
``rtol`` and ``atol`` is used. Outputs at ``t_eval`` come from heyoka's dense output (``propagate_grid``).

Scope: unconstrained analytic systems (as ``method="taylor"``); time-varying inputs, constraints needing
multipliers and friction switches are refused.

Interrupts: heyoka's loop does not check for signals, so in the main thread a trivial Python step callback is
passed (about 0.3 µs per step), where Python acts on a pending Ctrl-C within one step. While the run lasts,
Python's default SIGINT handler is replaced by one that only notes the interrupt (:class:`_Interrupt`); the
callback then returns False, heyoka stops after the step with the output points it has reached, and
:class:`~lagrange.errors.IntegrationInterrupted` carries them in ``partial``, followed by the state reached.
(Under another SIGINT handler, or a KeyboardInterrupt raised by other means, the exception propagates out of
heyoka: the grid is propagated in chunks of :data:`CHUNK` points, and the outputs of the finished chunks and
the state reached are kept.)
"""

from __future__ import annotations

import math
import signal
import threading
import weakref
from contextlib import contextmanager

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import InputError, IntegrationError, IntegrationInterrupted
from ..results.trajectory import Trajectory
from .compiled import MAX_STEPS, check_output_times

__all__ = ["integrate_heyoka", "compilations", "disk_loads"]

#: output points per ``propagate_grid`` call (the outputs of finished chunks survive a Ctrl-C)
CHUNK = 256

#: the integrators in use: HeyokaODEs -> {(tolerance, events): (taylor_adaptive, lock, order)}
_INTEGRATORS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_GUARD = threading.Lock()
_BUILDS = [0]
_LOADS = [0]


def compilations() -> int:
    """How many heyoka integrators this process has built (JIT-compiled with LLVM); a re-run of the same
    system at the same tolerance and events, with other parameter values or initial state, builds none, and
    neither does one whose integrator came from the on-disk cache (:func:`disk_loads`)."""
    return _BUILDS[0]


def disk_loads() -> int:
    """How many heyoka integrators this process has loaded from the on-disk cache instead of compiling
    (:mod:`lagrange.codegen.heyoka_jit`)."""
    return _LOADS[0]


def _integrator(model: NumericModel, odes, tol: float, events: tuple):
    """``(taylor_adaptive, lock, order, origin)`` for ``odes`` at ``tol`` with ``events``: kept in memory per
    process, else from the on-disk cache, else compiled (``origin`` says which)."""
    with _GUARD:
        per_system = _INTEGRATORS.setdefault(odes, {})
        entry = per_system.get((tol, events))
        origin = "memory"
        if entry is None:
            ta, origin, order = model.heyoka_integrator(tol, events)
            (_BUILDS if origin == "compiled" else _LOADS)[0] += 1
            entry = per_system[tol, events] = (ta, threading.Lock(), order)
    return (*entry, origin)


_ORIGIN_TEXT = {"compiled": "integrator compiled by LLVM", "disk": "integrator loaded from the on-disk cache",
                "memory": "integrator reused"}


def integrate_heyoka(model: NumericModel, t_span, y0, t_eval, *, rtol: float, atol: float,
                     max_step: float = np.inf, max_steps: int = MAX_STEPS, label: str | None = None,
                     events=()) -> Trajectory:
    """Integrate ``model`` from ``y0 = [q, q̇]`` at ``t_span[0]`` with heyoka (module docstring); outputs at
    ``t_eval`` (sorted in the direction of integration). Same signature as
    :func:`lagrange.integrate.taylor.integrate_taylor`, plus ``events``: scipy-style callables
    ``event(t, y)`` (``terminal``, ``direction`` attributes), traced into heyoka events
    (:mod:`lagrange.codegen.heyoka_events`); ``t_events`` / ``y_events`` of the result as scipy's.

    Raises
    ------
    BackendError
        heyoka is not installed (the message names the extra).
    TapeError
        Constraints or a non-analytic function in the equations (named).
    MethodError
        An event that cannot be traced into a heyoka expression (named, with the cause).
    InputError
        The model has time-varying inputs (a schedule), which heyoka cannot call.
    ValueError
        Bad tolerances or ``t_eval`` (as scipy words them).
    IntegrationError
        heyoka stopped early (non-finite state, step limit); ``partial`` holds the outputs reached.
    """
    if model.schedule is not None:
        raise InputError("method='heyoka' cannot follow time-varying inputs (the model has a schedule; constant "
                         "inputs are parameters): use method='DOP853' or another scipy method")
    odes = model.heyoka_shape()  # the system itself is built only when it must be compiled
    t0, t1 = float(t_span[0]), float(t_span[1])
    rtol, atol, max_step = float(rtol), float(atol), float(max_step)
    if not (rtol > 0 and math.isfinite(rtol)) or not (atol > 0 and math.isfinite(atol)):
        raise ValueError(f"method='heyoka' needs finite rtol > 0 and atol > 0, got rtol={rtol}, atol={atol}")
    if not max_step > 0:
        raise ValueError("max_step must be positive")
    t_eval = check_output_times(t_eval, t0, t1)
    y0 = np.asarray(y0, dtype=float)
    z0 = y0 if odes.nz == y0.size else np.append(y0, 0.0)
    traced = model.heyoka_events(list(events), t0, z0) if events else ()
    import heyoka as hy

    ta, lock, order, origin = _integrator(model, odes, max(min(rtol, atol), 2.0**-52), traced)
    with lock:  # one run at a time on a shared integrator (threads of a sweep take turns)
        ta.time = t0
        ta.state[:] = z0
        if odes.n_params:
            ta.pars[:] = np.asarray(model.params, dtype=float)
        recorders = [(ta.t_events if kind == "t" else ta.nt_events)[i].callback for kind, i in order]
        for rec in recorders:
            rec.records.clear()
        if recorders:
            ta.reset_cooldowns()
        return _propagate(ta, hy, odes, model, t0, t1, y0, t_eval, max_step, max_steps, label, recorders,
                          _ORIGIN_TEXT[origin])


def _event_results(recorders, n2: int, direction: float) -> tuple[list, list]:
    """scipy's ``t_events`` and ``y_events`` (states ``[q, q̇]``) from the recorders, in the order of time."""
    t_events, y_events = [], []
    for rec in recorders:
        rows = sorted(rec.records, key=lambda r: direction * r[0])
        t_events.append(np.array([r[0] for r in rows], dtype=float))
        y_events.append(np.array([r[1][:n2] for r in rows], dtype=float).reshape(len(rows), n2))
    return t_events, y_events


def _tick(ta) -> bool:
    """heyoka's step callback without a SIGINT handler of ours: a Python frame per step, where a pending Ctrl-C
    is raised (see the module docstring); never stops the run itself."""
    return True


class _Interrupt:
    """Ctrl-C noted during a heyoka run: :meth:`handler` is the SIGINT handler, :meth:`tick` the step callback,
    which stops heyoka (returns False) once the signal came."""

    def __init__(self):
        self.caught = False

    def handler(self, signum, frame) -> None:
        self.caught = True

    def tick(self, ta) -> bool:
        return not self.caught


@contextmanager
def _noting_sigint(kw: dict):
    """In the main thread: the step callback in ``kw``, and — when Python's default SIGINT handler is in force —
    a handler that only notes Ctrl-C for the run's duration (restored after); yields the :class:`_Interrupt`,
    or None when the callback is the plain :func:`_tick`."""
    if threading.current_thread() is not threading.main_thread():
        yield None
        return
    if signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        kw["callback"] = _tick
        yield None
        return
    note = _Interrupt()
    kw["callback"] = note.tick
    signal.signal(signal.SIGINT, note.handler)
    try:
        yield note
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def _terminal_stop(outcome) -> bool:
    """Whether heyoka's ``outcome`` is a terminal event (its value is the event's index ``i`` or ``-i-1``;
    the other outcomes are the values below ``-2**32``)."""
    return int(outcome.value) > -(2**32)


def _propagate(ta, hy, odes, model, t0, t1, y0, t_eval, max_step, max_steps, label, recorders=(),
               origin: str = "") -> Trajectory:
    """The run itself on the reset integrator ``ta``; ``recorders``: the user events' callbacks, in order."""
    grid = t_eval if t_eval.size and t_eval[0] == t0 else np.concatenate([[t0], t_eval])
    skip = grid.size - t_eval.size
    kw = {"max_steps": int(max_steps)}
    if math.isfinite(max_step):
        kw["max_delta_t"] = max_step
    rows, steps = [], 0
    try:
        with _noting_sigint(kw) as note:
            for i0 in range(0, max(grid.size - 1, 1), CHUNK):  # chunks share their end points
                res = ta.propagate_grid(np.ascontiguousarray(grid[i0:i0 + CHUNK + 1]), **kw)
                outcome, steps = res[0], steps + int(res[3])
                got = np.asarray(res[-1], dtype=float).reshape(-1, odes.nz)
                rows.append(got if i0 == 0 else got[1:])
                if outcome != hy.taylor_outcome.time_limit:
                    break
        if note is not None and note.caught:
            raise _interrupted(ta, odes, model, t0, y0, t_eval, rows, skip, steps, label, None)
    except IntegrationInterrupted:
        raise
    except KeyboardInterrupt as exc:
        raise _interrupted(ta, odes, model, t0, y0, t_eval, rows, skip, steps, label, exc) from exc
    Y = np.concatenate(rows)[skip:]
    direction = 1.0 if t1 >= t0 else -1.0
    if outcome == hy.taylor_outcome.time_limit and ta.time != t1:  # t_eval ends before t1
        res = ta.propagate_until(t1, **kw)
        outcome, steps = res[0], steps + int(res[3])
    Y = Y.reshape(-1, odes.nz)  # after a failure heyoka returns only the rows it reached
    reached = (direction * (t_eval[: Y.shape[0]] - ta.time) <= 0) & np.all(np.isfinite(Y), axis=1)
    n_out = int(np.argmin(reached)) if not reached.all() else Y.shape[0]
    Y = Y[:n_out]
    n2 = 2 * odes.n
    stopped = _terminal_stop(outcome) and bool(np.all(np.isfinite(np.asarray(ta.state))))
    ok = stopped or (outcome == hy.taylor_outcome.time_limit and ta.time == t1 and n_out == t_eval.size)
    order = int(ta.order)
    message = ("A termination event occurred." if stopped else
               "The solver successfully reached the end of the integration interval." if ok else
               f"heyoka stopped at t={ta.time:.9g}: {outcome.name}")
    message += f" ({steps} heyoka Taylor steps of order {order}{'; ' + origin if origin else ''})"
    t_events, y_events = _event_results(recorders, n2, direction)
    traj = Trajectory(t=t_eval[:n_out].copy(), y=Y[:, :n2].copy(), model=model,
                      method=label or f"heyoka (taylor_adaptive, order {order})", success=ok, message=message,
                      nfev=int(steps) * order, work=None if odes.nz == n2 else Y[:, n2].copy(),
                      initial=(t0, y0.copy()), t_events=t_events, y_events=y_events)
    if ok:
        return traj
    coords = model.equations.coordinates
    state = np.asarray(ta.state, dtype=float)
    raise IntegrationError(f"{message}: a blow-up, a singular configuration or too many steps (raise max_steps). "
                           f"The trajectory up to there ({n_out} output points) is in the exception's `partial` "
                           "attribute.", t=float(ta.time), state=dict(zip(coords, state[:n2])), partial=traj)


def _interrupted(ta, odes, model, t0, y0, t_eval, rows, skip, steps, label, exc) -> IntegrationInterrupted:
    """The IntegrationInterrupted of a heyoka run stopped by Ctrl-C: ``partial`` holds the output points
    reached (``rows``, finite ones before ``ta.time``; the initial state when no chunk finished), then the state
    reached at ``ta.time`` (after a whole step)."""
    if rows:
        Y = np.concatenate(rows)[skip:].reshape(-1, odes.nz)
    else:  # no chunk finished: the initial state, when it is an output point
        z0 = np.asarray(y0, dtype=float) if odes.nz == np.size(y0) else np.append(y0, 0.0)
        Y = z0[None, :] if t_eval.size and t_eval[0] == t0 else np.empty((0, odes.nz))
    T = t_eval[:Y.shape[0]]
    direction = 1.0 if t_eval.size == 0 or t_eval[-1] >= t0 else -1.0
    keep = int(np.sum((direction * (T - ta.time) <= 0) & np.all(np.isfinite(Y), axis=1)))
    T, Y = T[:keep], Y[:keep]
    state = np.asarray(ta.state, dtype=float)
    t_reached = float(ta.time)
    if (not T.size or T[-1] != t_reached) and direction * (t_reached - t0) > 0 and np.isfinite(state).all():
        T, Y = np.append(T, t_reached), np.vstack([Y, state[None, :]])
    n2 = 2 * odes.n
    partial = None
    if T.size:
        partial = Trajectory(t=T.copy(), y=Y[:, :n2].copy(), model=model,
                             method=(label or "heyoka") + " (interrupted)", success=False,
                             message=f"interrupted by Ctrl-C at t={t_reached:.9g}", nfev=steps * int(ta.order),
                             work=None if odes.nz == n2 else Y[:, n2].copy(), initial=(t0, y0.copy()))
    coords = model.equations.coordinates
    return IntegrationInterrupted(
        f"the heyoka run was interrupted (Ctrl-C) at t={t_reached:.9g}; the trajectory up to there "
        f"({T.size} points: the output times reached, then the state reached) is in the exception's `partial` "
        "attribute.", t=t_reached, state=dict(zip(coords, state[:n2])), partial=partial)
