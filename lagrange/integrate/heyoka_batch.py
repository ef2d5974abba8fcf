r"""``integrate_ensemble(..., method="heyoka")``: the members of an ensemble through heyoka's batch mode.

heyoka's ``taylor_adaptive_batch`` integrates ``B`` copies of the ODE system at once, one per SIMD lane
(``B = heyoka.recommended_simd_size()``: 4 doubles with AVX2, 8 with AVX-512), each lane with its own state,
parameters, step size and error control (Biscani & Izzo, *MNRAS* 504 (2021) 2614, §5): per member the same
Taylor method as ``method="heyoka"``, vectorized across members. The members are taken ``B`` at a time; the
last group is padded by repeating its last member (the padding is discarded). Parameters are heyoka runtime
parameters, one column per member (``P[i]`` in the order of ``model.equations.numeric_parameters``), so one
compiled batch integrator serves every group and every later ensemble of the same model (kept in memory, and on
disk: :mod:`lagrange.codegen.heyoka_jit`). Outputs at ``t_eval`` come from heyoka's dense output.

heyoka stops a whole batch when one lane fails (a non-finite state, the step limit); such a group is re-run
member by member with the scalar integrator (:func:`lagrange.integrate.heyoka_backend.integrate_heyoka`), so a
failing member gets ``status = -1``, NaN after its failure and its own message, and the others their results.

Scope, as ``method="heyoka"``: unconstrained analytic systems, constant inputs (parameters); refused otherwise.
Tolerance: the stricter of ``rtol`` and ``atol`` (heyoka's one mixed criterion).
"""

from __future__ import annotations

import math
import threading
import weakref

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import InputError, LagrangeError, MethodError

__all__ = ["integrate_ensemble_heyoka", "batch_size"]

#: built batch integrators: HeyokaODEs -> {(tol, B): (taylor_adaptive_batch, lock)}
_BATCH: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_GUARD = threading.Lock()


def batch_size() -> int:
    """heyoka's recommended SIMD width for doubles on this CPU (the lanes of one batch)."""
    import heyoka as hy

    return max(1, int(hy.recommended_simd_size()))


def _batch_integrator(model: NumericModel, odes, tol: float, B: int):
    with _GUARD:
        per = _BATCH.setdefault(odes, {})
        entry = per.get((tol, B))
        if entry is None:
            ta, _origin, _ = model.heyoka_integrator(tol, (), batch=B)
            entry = per[tol, B] = (ta, threading.Lock())
    return entry


def integrate_ensemble_heyoka(model: NumericModel, t0: float, t1: float, Y0: np.ndarray, P: np.ndarray,
                              t_eval: np.ndarray, *, rtol: float, atol: float, max_step: float = np.inf,
                              max_steps: int = 10_000_000):
    """The states of the members ``Y0`` (shape (k, 2n)) with parameter rows ``P`` (shape (k, n_params)) at
    ``t_eval`` (checked by the caller: within ``[t0, t1]``, sorted in the direction of integration).

    Returns
    -------
    (out, nfev, nsteps, status, messages, method)
        ``out`` shape (k, len(t_eval), 2n), NaN after a member failed; the rest as
        :class:`lagrange.sweep.ensemble.EnsembleResult`'s fields.

    Raises
    ------
    BackendError
        heyoka is not installed (the message names the extra).
    TapeError
        Constraints or a non-analytic function (dry friction) in the equations (named).
    InputError
        Time-varying inputs (a schedule).
    """
    if model.schedule is not None:
        raise InputError("integrate_ensemble(method='heyoka') cannot follow time-varying inputs (the model has a "
                         "schedule); constant inputs are parameters: give them in P")
    if model.m:
        raise MethodError("integrate_ensemble(method='heyoka') takes unconstrained models; use lagrange.sweep "
                          "for constrained systems")
    odes = model.heyoka_shape()  # the system itself is built only when it must be compiled
    rtol, atol = float(rtol), float(atol)
    if not (rtol > 0 and math.isfinite(rtol)) or not (atol > 0 and math.isfinite(atol)):
        raise ValueError(f"method='heyoka' needs finite rtol > 0 and atol > 0, got rtol={rtol}, atol={atol}")
    tol = max(min(rtol, atol), 2.0**-52)
    import heyoka as hy

    B = batch_size()
    ta, lock = _batch_integrator(model, odes, tol, B)
    k, n2 = Y0.shape
    grid = t_eval if t_eval.size and t_eval[0] == t0 else np.concatenate([[t0], t_eval])
    skip = grid.size - t_eval.size
    out = np.full((k, t_eval.size, n2), np.nan)
    nsteps, status = np.zeros(k, dtype=int), np.zeros(k, dtype=int)
    messages = ["The solver successfully reached the end of the integration interval."] * k
    kw = {"max_steps": int(max_steps)}
    if math.isfinite(max_step):
        kw["max_delta_t"] = np.full(B, float(max_step))
    Z = Y0 if odes.nz == n2 else np.hstack([Y0, np.zeros((k, 1))])
    bgrid = np.ascontiguousarray(np.repeat(grid[:, None], B, axis=1))
    order = int(ta.order)
    with lock:
        for g0 in range(0, k, B):
            rows = np.minimum(np.arange(g0, g0 + B), k - 1)  # the last group padded with its last member
            ta.set_time(np.full(B, t0))
            ta.state[:] = Z[rows].T
            if odes.n_params:
                ta.pars[:] = P[rows].T
            res = ta.propagate_grid(bgrid, **kw)
            outcomes = ta.propagate_res
            ok = all(o[0] == hy.taylor_outcome.time_limit for o in outcomes) and np.all(ta.time == grid[-1])
            real = np.arange(g0, min(g0 + B, k))
            if ok:
                Y = np.asarray(res[-1], dtype=float)[skip:]  # (n_times, nz, B)
                out[real] = np.transpose(Y[:, :n2, : real.size], (2, 0, 1))
                nsteps[real] = [int(o[3]) for o in outcomes[: real.size]]
                continue
            for i in real:  # heyoka stopped the whole batch: each member alone, with its own fate
                _one(model, i, t0, t1, Y0, P, t_eval, rtol, atol, max_step, out, nsteps, status, messages, order)
    return out, nsteps * order, nsteps, status, tuple(messages), f"heyoka (taylor_adaptive_batch, {B} lanes)"


def _one(model, i, t0, t1, Y0, P, t_eval, rtol, atol, max_step, out, nsteps, status, messages, order) -> None:
    """Member ``i`` with the scalar heyoka integrator (after its batch failed)."""
    from .heyoka_backend import integrate_heyoka

    member = model.with_params(dict(zip(model.equations.numeric_parameters, P[i])))
    try:
        sol = integrate_heyoka(member, (t0, t1), Y0[i], t_eval, rtol=rtol, atol=atol, max_step=max_step)
    except LagrangeError as exc:
        part = getattr(exc, "partial", None)
        if part is not None and len(part.t):
            out[i, : len(part.t)] = part.y
            nsteps[i] = part.nfev // max(order, 1)
        status[i], messages[i] = -1, str(exc)
        return
    out[i] = sol.y
    nsteps[i] = sol.nfev // max(order, 1)
