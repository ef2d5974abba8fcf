r"""Ensemble integration: many initial states and parameter sets in one process, each with its own error control.

Every member runs exactly the step-size control of scipy's explicit Runge–Kutta solvers (``RK23``,
``RK45``, ``DOP853``; their tableaus are taken from :mod:`scipy.integrate`): its own initial step
(Hairer, Nørsett & Wanner, *Solving ODEs I*, II.4), its own error norm

.. math:: \|e\| = \sqrt{\tfrac{1}{N}\sum_i \big(e_i / (\mathrm{atol} + \mathrm{rtol}\,\max(|y_i|, |y_i^{new}|))\big)^2}

(DOP853: the 5th/3rd-order blend of Hairer's DOP853), its own accept/reject decision and step factor
``0.9‖e‖^{-1/(p+1)}`` clipped to [0.2, 10]. This is *not* one stacked ODE with a shared step: a fast member
never forces small steps on the others, and each member reproduces, up to rounding, the steps and the
result of ``solve_ivp`` run on it alone. Only the right-hand side is batched: each Runge–Kutta stage
evaluates all members still stepping with one call of :meth:`NumericModel.rhs_many
<lagrange.codegen.numeric.NumericModel.rhs_many>` (a compiled loop with the numba backend), so the Python
overhead per step is paid once for the whole ensemble instead of once per member.

Outputs at ``t_eval`` use each method's dense output (as ``solve_ivp`` does). Unconstrained models only
(no projection of constraint drift here; use :func:`lagrange.sweep` for constrained ones); no events.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import DOP853, RK23, RK45

from ..errors import IntegrationError, LagrangeError, MethodError
from ..integrate.options import DEFAULT_MAX_OUTPUT_BYTES, DEFAULT_MAX_STEPS, check_output_size, check_step_count
from ..records import record

__all__ = ["integrate_ensemble", "EnsembleResult", "METHODS"]

METHODS = {"RK23": RK23, "RK45": RK45, "DOP853": DOP853}
_SAFETY, _MIN_FACTOR, _MAX_FACTOR = 0.9, 0.2, 10.0


@record(frozen=True)
class EnsembleResult:
    """States of every member at the output times.

    Attributes
    ----------
    t : ndarray, shape (m,)
    y : ndarray, shape (k, m, 2n) — member i's ``[q, q̇]`` at ``t``; NaN after a member failed
    nfev, nsteps : ndarray, shape (k,) — right-hand-side evaluations and accepted steps per member
    status : ndarray, shape (k,) — 0 reached the end, -1 failed (see ``messages``)
    messages : tuple of str, one per member
    method : str
    """

    t: np.ndarray
    y: np.ndarray
    nfev: np.ndarray
    nsteps: np.ndarray
    status: np.ndarray
    messages: tuple
    method: str

    @property
    def success(self) -> np.ndarray:
        return self.status == 0

    def _repr_html_(self) -> str:
        from ..display import ensemble_html

        return ensemble_html(self)


def _rms(x: np.ndarray) -> np.ndarray:
    return np.sqrt(np.einsum("ij,ij->i", x, x) / x.shape[1])


class _Members:
    """Per-member state of the ensemble and the batched right-hand side."""

    def __init__(self, model, Y0: np.ndarray, P: np.ndarray, t0: float):
        k = Y0.shape[0]
        self.model, self.P = model, P
        self.t = np.full(k, t0)
        self.y = Y0.copy()
        self.nfev = np.zeros(k, dtype=int)
        self.nsteps = np.zeros(k, dtype=int)
        self.status = np.ones(k, dtype=int)  # 1 running, 0 done, -1 failed
        self.messages = ["running"] * k

    def fail(self, rows: np.ndarray, message: str) -> None:
        for i in rows:
            if self.status[i] == 1:
                self.status[i] = -1
                self.messages[i] = message

    def rhs(self, tv: np.ndarray, Yv: np.ndarray, rows: np.ndarray) -> np.ndarray:
        """Derivatives of members ``rows``; a member whose evaluation raises is failed and gets NaN."""
        self.nfev[rows] += 1
        try:
            return self.model.rhs_many(tv, Yv, self.P[rows])
        except (LagrangeError, ZeroDivisionError, ValueError, OverflowError):
            out = np.full(Yv.shape, np.nan)
            for j, i in enumerate(rows):
                try:
                    out[j] = self.model.rhs_many(tv[j:j + 1], Yv[j:j + 1], self.P[i:i + 1])[0]
                except (LagrangeError, ZeroDivisionError, ValueError, OverflowError) as exc:
                    self.fail(np.array([i]), f"failed at t={tv[j]:.9g}: {exc}")
            return out


def _initial_step(mem: _Members, f0, t0, t1, direction, order, rtol, atol, max_step) -> np.ndarray:
    """scipy's ``select_initial_step``, member by member."""
    y0 = mem.y
    rows = np.arange(len(y0))
    interval = abs(t1 - t0)
    scale = atol + np.abs(y0) * rtol
    d0, d1 = _rms(y0 / scale), _rms(f0 / scale)
    h0 = np.where((d0 < 1e-5) | (d1 < 1e-5), 1e-6, 0.01 * d0 / np.where(d1 == 0, 1.0, d1))
    h0 = np.minimum(h0, interval)
    f1 = mem.rhs(t0 + h0 * direction, y0 + (h0 * direction)[:, None] * f0, rows)
    d2 = _rms((f1 - f0) / scale) / h0
    dmax = np.maximum(d1, d2)
    with np.errstate(divide="ignore"):
        h1 = np.where((d1 <= 1e-15) & (d2 <= 1e-15), np.maximum(1e-6, h0 * 1e-3),
                      (0.01 / dmax) ** (1.0 / (order + 1)))
    return np.minimum(np.minimum(100 * h0, h1), min(interval, max_step))


def _error_norm(scheme, K, h, scale) -> np.ndarray:
    """scipy's error norm of ``scheme`` per member; K shape (stages + 1, members, d)."""
    if scheme is DOP853:
        e5 = np.einsum("s,smd->md", scheme.E5, K) / scale
        e3 = np.einsum("s,smd->md", scheme.E3, K) / scale
        n5, n3 = np.einsum("md,md->m", e5, e5), np.einsum("md,md->m", e3, e3)
        denom = np.sqrt((n5 + 0.01 * n3) * scale.shape[1])
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where((n5 == 0) & (n3 == 0), 0.0, np.abs(h) * n5 / denom)
    err = np.einsum("s,smd->md", scheme.E, K) * h[:, None]
    return _rms(err / scale)


def _stages(mem: _Members, scheme, t, y, f, h, rows) -> tuple[np.ndarray, np.ndarray]:
    """One Runge–Kutta step of members ``rows``: (y_new, K with K[-1] = f(t + h, y_new))."""
    ns = scheme.n_stages
    K = np.empty((ns + 1, *y.shape))
    K[0] = f
    for s in range(1, ns):
        dy = np.einsum("s,smd->md", scheme.A[s, :s], K[:s]) * h[:, None]
        K[s] = mem.rhs(t + scheme.C[s] * h, y + dy, rows)
    y_new = y + h[:, None] * np.einsum("s,smd->md", scheme.B, K[:ns])
    K[ns] = mem.rhs(t + h, y_new, rows)
    return y_new, K


def _dense(mem: _Members, scheme, t_old, h, y_old, y_new, K, rows):
    """Interpolant ``ip(x)`` of each member over its step (x = (t − t_old)/h in [0, 1], shape (members,))."""
    if scheme is not DOP853:
        Q = np.einsum("smd,sq->mdq", K, scheme.P)

        def ip(x):
            p = np.cumprod(np.repeat(x[:, None], Q.shape[2], axis=1), axis=1)
            return y_old + h[:, None] * np.einsum("mdq,mq->md", Q, p)

        return ip
    Kx = np.concatenate([K, np.empty((len(scheme.A_EXTRA), *y_old.shape))])
    for j, (a, c) in enumerate(zip(scheme.A_EXTRA, scheme.C_EXTRA)):
        s = K.shape[0] + j
        dy = np.einsum("s,smd->md", a[:s], Kx[:s]) * h[:, None]
        Kx[s] = mem.rhs(t_old + c * h, y_old + dy, rows)
    dyy = y_new - y_old
    F = [dyy, h[:, None] * Kx[0] - dyy, 2 * dyy - h[:, None] * (K[-1] + Kx[0])]
    F += list(h[None, :, None] * np.einsum("ps,smd->pmd", scheme.D, Kx))

    def ip(x):
        out = np.zeros_like(y_old)
        for i, fi in enumerate(reversed(F)):
            out += fi
            out *= x[:, None] if i % 2 == 0 else (1 - x)[:, None]
        return out + y_old

    return ip


def integrate_ensemble(model, t_span, Y0, P=None, *, method: str = "DOP853", rtol: float = 1e-9,
                       atol: float = 1e-11, t_eval=None, n_points: int = 1001,
                       max_step: float = np.inf, max_steps: int = DEFAULT_MAX_STEPS,
                       max_output_bytes: int = DEFAULT_MAX_OUTPUT_BYTES) -> EnsembleResult:
    """Integrate ``model`` from every row of ``Y0`` (with the parameter row ``P[i]``), each member with its
    own adaptive step (see the module docstring).

    Parameters
    ----------
    model : NumericModel (unconstrained), e.g. ``system.compile(params, backend="numba")``
    t_span : (t0, t1) or t1
    Y0 : ndarray, shape (k, 2n) or (2n,) — initial states ``[q, q̇]``
    P : None (the model's parameters for all) or ndarray, shape (k, len(model.params)) in the order of
        ``model.equations.numeric_parameters``
    method : ``"DOP853"`` (default), ``"RK45"`` or ``"RK23"``; or ``"heyoka"``: heyoka's Taylor method in
        batch mode, the members in SIMD lanes (:mod:`lagrange.integrate.heyoka_batch`; analytic models,
        ``pip install "lagrange-dynamics[heyoka]"``)
    rtol, atol, max_step : as in :func:`scipy.integrate.solve_ivp`
    t_eval : output times (monotone in the direction of integration); default ``n_points`` equally spaced
    max_steps, max_output_bytes : as in :func:`lagrange.integrate.run.simulate`: a ``max_step`` that would need
        more steps over the span, or output (members × times × 2n × 8 bytes) beyond the limit, is refused up
        front (:class:`~lagrange.errors.OptionError`)

    Returns
    -------
    EnsembleResult

    Examples
    --------
    >>> import numpy as np, lagrange as lg
    >>> x = lg.coordinates("x"); k = lg.parameters("k")
    >>> osc = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2).compile({"k": 1.0})
    >>> res = integrate_ensemble(osc, np.pi, [[1.0, 0.0], [2.0, 0.0]], P=[[1.0], [4.0]], t_eval=[np.pi])
    >>> np.round(res.y[:, -1, 0], 8).tolist()       # x(π) = cos(√k π)·x0
    [-1.0, 2.0]
    """
    if method not in METHODS and method != "heyoka":
        raise MethodError(f"integrate_ensemble: method must be one of {', '.join(METHODS)} or heyoka, got {method!r}")
    if model.m:
        raise MethodError("integrate_ensemble takes unconstrained models (constraint drift needs projection): "
                         "use lagrange.sweep for constrained systems")
    scheme = METHODS.get(method)
    t0, t1 = (0.0, float(t_span)) if np.ndim(t_span) == 0 else (float(t_span[0]), float(t_span[1]))
    if t1 == t0:
        raise IntegrationError(f"t_span must be two different times, got {t_span}")
    direction = 1.0 if t1 > t0 else -1.0
    Y0 = np.atleast_2d(np.asarray(Y0, dtype=float))
    k = Y0.shape[0] if P is None else max(Y0.shape[0], np.atleast_2d(P).shape[0])
    Y0 = np.ascontiguousarray(np.broadcast_to(Y0, (k, Y0.shape[1])))
    P = np.broadcast_to(model.params, (k, len(model.params))) if P is None else np.atleast_2d(np.asarray(P, float))
    P = np.ascontiguousarray(np.broadcast_to(P, (k, P.shape[1])))
    model.rhs_many(t0, Y0[:1], P[:1])  # shape checks with the model's messages
    t_eval = np.linspace(t0, t1, n_points) if t_eval is None else np.asarray(t_eval, dtype=float)
    if np.any(direction * np.diff(t_eval) < 0) or np.any(direction * (t_eval - t0) < 0) or \
            np.any(direction * (t_eval - t1) > 0):
        raise IntegrationError("t_eval must be sorted in the direction of integration and lie within t_span")
    if np.isfinite(max_step) and max_step > 0:
        check_step_count(abs(t1 - t0), float(max_step), "max_step", max_steps)
    check_output_size(k * len(t_eval), Y0.shape[1], max_output_bytes)
    if method == "heyoka":  # heyoka's batch mode: lagrange/integrate/heyoka_batch.py
        from ..integrate.heyoka_batch import integrate_ensemble_heyoka

        *fields, label = integrate_ensemble_heyoka(model, t0, t1, Y0, P, t_eval, rtol=rtol, atol=atol,
                                                   max_step=max_step)
        return EnsembleResult(t_eval, *fields, label)
    mem = _Members(model, Y0, P, t0)
    out = np.full((k, len(t_eval), Y0.shape[1]), np.nan)
    try:
        _run(mem, scheme, t0, t1, direction, rtol, atol, max_step, t_eval, out)
    except SystemError as exc:  # Ctrl-C while numba boxed rhs_many's result: the interrupt it is
        from ..integrate.stepper import interrupt_of

        if interrupt_of(exc) is None:
            raise
        raise KeyboardInterrupt("integrate_ensemble was interrupted (Ctrl-C)") from None
    return EnsembleResult(t_eval, out, mem.nfev, mem.nsteps, mem.status, tuple(mem.messages), method)


def _run(mem: _Members, scheme, t0, t1, direction, rtol, atol, max_step, t_eval, out) -> None:
    """The stepping loop: every round, each running member attempts one step with its own h."""
    k = len(mem.y)
    f = mem.rhs(mem.t.copy(), mem.y, np.arange(k))
    h_abs = _initial_step(mem, f, t0, t1, direction, scheme.error_estimator_order, rtol, atol, max_step)
    rejected = np.zeros(k, dtype=bool)
    nxt = np.zeros(k, dtype=int)  # next output index per member
    exponent = -1.0 / (scheme.error_estimator_order + 1)
    while True:
        rows = np.flatnonzero(mem.status == 1)
        if rows.size == 0:
            return
        t, y = mem.t[rows], mem.y[rows]
        min_step = 10 * np.abs(np.nextafter(t, direction * np.inf) - t)
        hab = h_abs[rows]
        fresh = ~rejected[rows]
        hab = np.where(fresh, np.clip(hab, min_step, max_step) if np.isfinite(max_step) else np.maximum(hab, min_step),
                       hab)
        small = hab < min_step
        if small.any():
            mem.fail(rows[small], "the step size fell below its minimum (10 ulp of t): a singularity or stiffness")
            keep = ~small
            rows, t, y, hab = rows[keep], t[keep], y[keep], hab[keep]
            if rows.size == 0:
                continue
        t_new = t + hab * direction
        t_new = np.where(direction * (t_new - t1) > 0, t1, t_new)
        h = t_new - t
        y_new, K = _stages(mem, scheme, t, y, f[rows], h, rows)
        scale = atol + np.maximum(np.abs(y), np.abs(y_new)) * rtol
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            err = _error_norm(scheme, K, h, scale)
            grow = np.where(err == 0, _MAX_FACTOR, np.minimum(_MAX_FACTOR, _SAFETY * err ** exponent))
            shrink = np.fmax(_MIN_FACTOR, _SAFETY * err ** exponent)
        accept = err < 1
        grow = np.where(rejected[rows], np.minimum(1.0, grow), grow)
        h_abs[rows] = np.abs(h) * np.where(accept, grow, shrink)
        rejected[rows] = ~accept
        acc = np.flatnonzero(accept & (mem.status[rows] == 1))
        if acc.size:
            _accept(mem, scheme, rows[acc], t[acc], t_new[acc], h[acc], y[acc], y_new[acc], K[:, acc], f,
                    t_eval, nxt, out, direction)
            done = rows[acc][t_new[acc] == t1]
            mem.status[done] = 0
            for i in done:
                mem.messages[i] = "reached the end of the interval"


def _accept(mem, scheme, rows, t, t_new, h, y, y_new, K, f, t_eval, nxt, out, direction) -> None:
    """Record an accepted step of members ``rows``: dense output at the t_eval points it covers."""
    mem.t[rows], mem.y[rows], f[rows] = t_new, y_new, K[-1]
    mem.nsteps[rows] += 1
    m = len(t_eval)

    def pending(r, tn):
        return (nxt[r] < m) & (direction * (t_eval[np.minimum(nxt[r], m - 1)] - tn) <= 0)

    cov = np.flatnonzero(pending(rows, t_new))
    if cov.size == 0:
        return
    ip = _dense(mem, scheme, t[cov], h[cov], y[cov], y_new[cov], K[:, cov], rows[cov])
    r = rows[cov]
    need = np.ones(cov.size, dtype=bool)
    while need.any():
        j = np.minimum(nxt[r], m - 1)
        vals = ip(np.where(need, (t_eval[j] - t[cov]) / h[cov], 0.0))
        rr = r[need]
        out[rr, nxt[rr]] = vals[need]
        nxt[rr] += 1
        need &= pending(r, t_new[cov])
