"""Driver of the fixed-step geometric integrators: (q, q̇) → (q, p), stepping, back to a Trajectory.

``simulate(..., method=name, step=h)`` with ``name`` in :data:`GEOMETRIC` dispatches here. The steps run
either in Python (the schemes of :mod:`~lagrange.integrate.gauss_legendre`,
:mod:`~lagrange.integrate.stormer_verlet`, :mod:`~lagrange.integrate.discrete_gradient`) or, with
``loop="compiled"`` (the default for numba models, see :func:`fixed_loop`), in the compiled loop of
:mod:`lagrange.integrate._geometric_loops` — the same schemes transcribed, nothing in Python per step.
"""

from __future__ import annotations

import math

import numpy as np

from ..conventions import VELOCITY_SUFFIX
from ..errors import IntegrationError, IntegrationInterrupted
from ..model.coordinates import coordinate_name
from ..results.trajectory import Trajectory
from ..results.verdict import Check
from .base import diverged, non_finite_state, not_converged, singular_jacobian, step_prefix
from .composition import KahanLi6, McLachlan8, _Composition
from .discrete_gradient import DiscreteGradient
from .gauss_legendre import TABLEAUX, GaussLegendre4, GaussLegendre6, ImplicitMidpoint, _Gauss
from .stormer_verlet import StormerVerlet

__all__ = ["GEOMETRIC", "integrate_fixed", "fixed_loop", "run", "step_doubling_check", "FIXED_RTOL", "FIXED_ATOL"]

#: the accuracy a fixed-step run is checked against when ``rtol``/``atol`` are not given (its verdict,
#: :func:`step_doubling_check`): 1 % of each component's range (the user chose a step, not a tolerance: the
#: verdict flags answers off by more), absolute below 1e-6
FIXED_RTOL, FIXED_ATOL = 1e-2, 1e-6

#: why a step failed when M is not positive definite at one of its points (both loops)
SINGULAR_MASS = ("the mass matrix is singular (or not positive definite) at a point of the step: a singular "
                 "configuration (a coordinate reaching a singular value, a vanishing inertia), or a step too large")

#: name → scheme
GEOMETRIC = {cls.name: cls for cls in (ImplicitMidpoint, GaussLegendre4, GaussLegendre6, StormerVerlet,
                                       DiscreteGradient, KahanLi6, McLachlan8)}


def fixed_loop(loop: str, *, backend: str, model=None) -> bool:
    """Whether a fixed-step run uses the compiled loop (:mod:`lagrange.integrate._geometric_loops`).

    ``loop="compiled"`` always (needs numba), ``"scipy"`` never (the step loop in Python; scipy has no such
    methods), ``"auto"`` when the model's backend (or the requested one) is numba — as for the adaptive
    methods. Raises :class:`TypeError` for an unknown ``loop`` and :class:`BackendError` when numba is missing.
    """
    from .compiled import loop_backend

    effective = loop_backend(loop, backend=backend, model=model)
    return loop == "compiled" or (loop == "auto" and effective == "numba")


def run(req) -> Trajectory:
    """The run function of the fixed-step entries of :mod:`lagrange.integrate.registry` (the registry has
    refused events, constraints, inputs and non-conservative systems, and required ``step``)."""
    from .prepare import model_for

    compiled = fixed_loop(req.loop, backend=req.backend, model=req.model)
    model = model_for(req.equations, req.params, req.model, "python")
    return integrate_fixed(req.system, req.t_span, req.y0, req.params, method=req.method, step=req.step.h,
                           n_points=req.n_points, model=model, compiled=compiled)


def integrate_fixed(system, t_span, y0, params, *, method: str, step: float, n_points: int = 1001,
                    model=None, tol: float = 1e-13, compiled: bool = False) -> Trajectory:
    """Integrate from ``y0 = [q, q̇]`` over ``t_span`` with ``steps = round((t1 − t0)/step)`` fixed steps,
    recording about ``n_points`` states (every ``stride``-th step, and the last).

    ``compiled``: run the steps in the compiled loop (numba; :mod:`lagrange.integrate._geometric_loops`,
    the same schemes transcribed) instead of Python.

    Raises
    ------
    IntegrationError
        A step failed: Newton did not converge (the last residual is given), the Jacobian was singular, a
        non-finite state or an arithmetic error appeared. The message names the method, the step number,
        its time and the state before it; ``t``/``state`` are that time and state and ``partial`` is the
        trajectory up to it (the recorded states plus the last good one).
    IntegrationInterrupted
        Ctrl-C: within about a second in both loops (the compiled one runs in chunks of bounded work,
        bit-identical to one call); ``partial`` holds the recorded states and the state reached.
    """
    t0, t1 = t_span
    if not (step and step > 0 and math.isfinite(step)):
        raise TypeError(f"method {method!r} is a fixed-step integrator: give step=h > 0")
    steps = max(1, int(round((t1 - t0) / step)))
    h = (t1 - t0) / steps
    if model is None:
        model = system.compile(params)
    hm = model.hamiltonian()  # generated by codegen (lagrange.codegen.hamiltonian_model)
    scheme = GEOMETRIC[method](hm, tol=tol)
    stride = max(1, steps // max(1, n_points - 1))
    label = f"{method} (fixed step h={h:.3g}, order {scheme.order}" + (", symplectic" if scheme.symplectic else "") \
        + (", energy-conserving" if scheme.energy_conserving else "") + ("; compiled loop" if compiled else "") + ")"
    where = (t0, y0, model, label, steps)
    if compiled:
        T, Y, iters = _run_compiled(hm, scheme, t0, h, steps, stride, y0, where)
    else:
        T, Y, iters = _run_python(hm, scheme, t0, h, steps, stride, y0, where)
    return Trajectory(t=T, y=Y, model=model, method=label, success=True,
                      message=f"{steps} steps, {iters} Newton iterations", nfev=steps, work=None,
                      initial=(t0, np.asarray(y0, dtype=float).copy()))


def _run_python(hm, scheme, t0, h, steps, stride, y0, where) -> tuple[np.ndarray, np.ndarray, int]:
    """The step loop in Python: ``(T, Y = [q, q̇] rows, Newton iterations)``."""
    n = hm.n
    z = np.concatenate([y0[:n], hm.to_momenta(t0, y0[:n], y0[n:])])
    ts, zs = [t0], [z.copy()]
    iters = 0
    method = scheme.name
    k, t_z = 0, t0
    try:
        for k in range(steps):
            tk = t0 + k * h
            try:
                z_new, it = scheme.step(tk, z, h)
                if not np.all(np.isfinite(z_new)):
                    raise IntegrationError(non_finite_state(method, tk))
            except (IntegrationError, ZeroDivisionError, OverflowError, ValueError, FloatingPointError,
                    np.linalg.LinAlgError) as exc:
                if ts[-1] != tk:
                    ts.append(tk)
                    zs.append(z.copy())
                if isinstance(exc, np.linalg.LinAlgError):  # M singular at a stage point
                    cause = step_prefix(method, tk, h) + SINGULAR_MASS
                else:
                    cause = str(exc) if isinstance(exc, IntegrationError) else f"{type(exc).__name__}: {exc}"
                raise _step_fault(cause, k, tk, np.array(ts), _velocities(hm, ts, zs), where) from None
            z, t_z = z_new, t0 + (k + 1) * h  # the state and its time change together
            iters += it
            if (k + 1) % stride == 0 or k + 1 == steps:
                ts.append(t_z)
                zs.append(z.copy())
    except KeyboardInterrupt:  # Ctrl-C: the records, and the last state reached
        if ts[-1] != t_z:
            ts.append(t_z)
            zs.append(z.copy())
        raise _interrupted(int(round((t_z - t0) / h)), np.array(ts), _velocities(hm, ts, zs), where) from None
    return np.array(ts), _velocities(hm, ts, zs), iters


def _run_compiled(hm, scheme, t0, h, steps, stride, y0, where) -> tuple[np.ndarray, np.ndarray, int]:
    """The compiled step loop: ``(T, Y = [q, q̇] rows, Newton iterations)``; a failed step raises as in
    :func:`_run_python`, with the same wording."""
    from .compiled import first_class, kernel, run_in_chunks

    k = kernel("_geometric_loops.py", "geoloops", f"method={scheme.name!r} with loop='compiled'")
    mod = hm.compiled_module()
    mass, lag, second = (first_class(mod.mass, k.MASS), first_class(mod.lagrangian, k.LAGRANGIAN),
                         first_class(mod.second, k.SECOND))
    n = hm.n
    p = np.ascontiguousarray(hm.params, dtype=float)
    q0, v0 = np.ascontiguousarray(y0[:n], dtype=float), np.ascontiguousarray(y0[n:], dtype=float)
    p0 = np.empty(n)
    k.momenta(mass, float(t0), q0, v0, p, p0)
    z = np.concatenate([q0, p0])  # the loop's state, updated in place chunk by chunk
    if isinstance(scheme, _Gauss):
        code, (A, b, c) = k.GAUSS, TABLEAUX[scheme.stages]
    elif isinstance(scheme, _Composition):  # the coefficients γ_i travel in b
        code, A, b, c = k.COMPOSE, np.zeros((0, 0)), scheme.gammas, np.zeros(0)
    elif isinstance(scheme, StormerVerlet):  # the one-stage composition
        code, A, b, c = k.VERLET, np.zeros((0, 0)), np.ones(1), np.zeros(0)
    else:
        code, A, b, c = k.DG, np.zeros((0, 0)), np.zeros(0), np.zeros(0)
    A, b, c = np.ascontiguousarray(A), np.ascontiguousarray(b), np.ascontiguousarray(c)
    n_rec = steps // stride + 3
    T, Y = np.empty(n_rec), np.empty((n_rec, 2 * n))
    counts, info = np.zeros(4, dtype=np.int64), np.zeros(1)

    def chunk(size: int) -> int:
        return k.run(code, mass, lag, second, A, b, c, float(t0), float(h), int(steps), int(stride), p,
                     float(scheme.tol), int(scheme.max_iter), int(counts[0] + size), z, T, Y, counts, info)

    status = run_in_chunks(chunk)
    kf, n_out, total, its, rnorm = int(counts[0]), int(counts[1]), int(counts[2]), int(counts[3]), float(info[0])
    T, Y = np.array(T[:n_out]), np.array(Y[:n_out])
    if status is None:  # Ctrl-C: the records, and the state reached
        tk = t0 + kf * h
        if T[-1] != tk:
            T, Y = np.append(T, tk), np.vstack([Y, _velocities(hm, [tk], [z])])
        raise _interrupted(kf, T, Y, where)
    if status == k.OK:
        return T, Y, int(total)
    tk = t0 + kf * h
    where_ = "(stage equations)" if code == k.GAUSS else "(discrete gradient)"
    head = step_prefix(scheme.name, tk, h)
    cause = {
        k.NEWTON_MAX_ITER: head + not_converged(scheme.max_iter, where_, rnorm, scheme.tol),
        k.NEWTON_DIVERGED: head + diverged(where_, its),
        k.SINGULAR_JACOBIAN: head + singular_jacobian(where_, its, rnorm),
        k.SINGULAR_MASS: head + SINGULAR_MASS,
        k.NON_FINITE: non_finite_state(scheme.name, tk),
    }[status]
    raise _step_fault(cause, kf, tk, T, Y, where)


def _velocities(hm, ts, zs) -> np.ndarray:
    """``[q, q̇]`` rows from canonical ``(q, p)``: ``q̇ = ∂H/∂p`` (nan where M is singular, as in the
    compiled loop: the state before a failed step may sit on the singularity)."""
    n = hm.n
    rows = []
    for ti, zi in zip(ts, zs):
        try:
            v = hm.grad(ti, zi)[n:]
        except (np.linalg.LinAlgError, ValueError, ZeroDivisionError, OverflowError):
            v = np.full(n, np.nan)
        rows.append(np.concatenate([zi[:n], v]))
    return np.array(rows).reshape(len(ts), 2 * n)


def _interrupted(k: int, T: np.ndarray, Y: np.ndarray, where) -> IntegrationInterrupted:
    """Ctrl-C after ``k`` steps as :class:`~lagrange.errors.IntegrationInterrupted`, ``partial`` holding the
    records ``T, Y`` (the last row the state reached)."""
    t0, y0, model, label, steps = where
    names = [coordinate_name(c) for c in model.equations.coordinates]
    n = len(names)
    partial = Trajectory(t=np.asarray(T, dtype=float), y=Y, model=model, method=f"{label} (interrupted)",
                         success=False, message=f"interrupted by Ctrl-C after {k} of {steps} steps", nfev=k,
                         work=None, initial=(t0, np.asarray(y0, dtype=float).copy()))
    return IntegrationInterrupted(
        f"{label} was interrupted (Ctrl-C) after {k} of {steps} steps, at t={T[-1]:.9g}; the trajectory up to "
        f"there is in the exception's `partial` attribute.",
        t=float(T[-1]), state=dict(zip(model.equations.coordinates, Y[-1, :n])), partial=partial)


def _step_fault(cause: str, k: int, tk: float, T: np.ndarray, Y: np.ndarray, where) -> IntegrationError:
    """The failed step ``k`` (from ``tk``) as an IntegrationError: where, why, and the trajectory ``T, Y`` up
    to the state before it (its last row). A last row whose velocity is undefined (M singular there: q̇ =
    M⁻¹(p − b) does not exist) is named in the message but left out of ``partial``, which stays finite."""
    t0, y0, model, label, steps = where
    names = [coordinate_name(c) for c in model.equations.coordinates]
    n = len(names)
    state = ", ".join([f"{nm}={Y[-1, i]:.6g}" for i, nm in enumerate(names)]
                      + [f"{nm}{VELOCITY_SUFFIX}={Y[-1, n + i]:.6g}" for i, nm in enumerate(names)])
    keep = len(T)
    while keep > 1 and not np.all(np.isfinite(Y[keep - 1])):
        keep -= 1
    partial = Trajectory(t=np.asarray(T[:keep], dtype=float), y=Y[:keep], model=model,
                         method=f"{label} (stopped early)", success=False, message=cause, nfev=k, work=None,
                         initial=(t0, np.asarray(y0, dtype=float).copy()))
    undefined = "" if keep == len(T) else f" (the velocity is undefined at t={tk:.9g})"
    return IntegrationError(
        f"step {k + 1} of {steps} failed at t={tk:.9g} ({state}): {cause}. The trajectory up to "
        f"t={T[keep - 1]:.9g}{undefined} is in the error's `partial` attribute.",
        t=tk, state=dict(zip(model.equations.coordinates, Y[-1, :n])), partial=partial)


def step_doubling_check(traj: Trajectory, *, method: str, step: float, t_span, y0, compiled: bool,
                        rtol: float, atol: float) -> Check:
    r"""Richardson's estimate of the global error of a fixed-step run, from a second run at twice the step.

    The scheme of order :math:`p` runs again with ``round(steps/2)`` steps of :math:`h_2 \approx 2h` (a run of
    one step: two steps of :math:`h/2`); at the times both runs recorded (every common record, always the end)
    the error of the first is :math:`e \approx |y_h - y_{h_2}| / |1 - (h_2/h)^p|`. The value checked is
    :math:`\max_{i,t} e_i(t) / \max(\max_t|y_i|, atol/rtol)` — the relative global error of the worst
    component — against ``rtol``. Cost: the second run, about half of the first. A second run that fails (its
    Newton iteration, a non-finite state) fails the check: the step is near the scheme's limit.
    """
    t0, t1 = t_span
    steps = max(1, int(round((t1 - t0) / step)))
    h = (t1 - t0) / steps
    idx = np.rint((traj.t - t0) / h).astype(np.int64)
    stride = int(idx[1] - idx[0]) if len(idx) > 2 else steps
    if steps == 1:  # nothing to double: halve
        steps2, stride2 = 2, 1
    elif steps % 2 == 0:
        steps2, stride2 = steps // 2, (stride // 2 if stride % 2 == 0 else stride)
    else:  # h2 is not 2h: the runs share their ends only
        steps2 = (steps + 1) // 2
        stride2 = steps2
    h2 = (t1 - t0) / steps2
    hm = traj.model.hamiltonian()
    scheme = GEOMETRIC[method](hm)
    where = (t0, np.asarray(y0, dtype=float), traj.model, f"{method} at step {h2:.3g} (accuracy check)", steps2)
    advice = f"a smaller step than {abs(h):.3g} (or a higher-order method: gl6)"
    try:
        run2 = _run_compiled if compiled else _run_python
        T2, Y2, _ = run2(hm, scheme, t0, h2, steps2, max(1, stride2), np.asarray(y0, dtype=float), where)
    except IntegrationError as exc:
        return Check("step-doubling error", math.inf, float(rtol), False, advice,
                     f"the run at step {h2:.3g} failed: {str(exc).split(': ', 1)[-1][:200]}")
    except KeyboardInterrupt:  # Ctrl-C in the second run: the first is complete
        raise IntegrationInterrupted(f"{traj.method} was interrupted (Ctrl-C) during its accuracy check; the "
                                     "completed trajectory is in the exception's `partial` attribute.",
                                     t=float(traj.t[-1]), partial=traj) from None
    a, b = _common_times(traj.t, T2, 1e-9 * abs(t1 - t0))
    e = np.abs(traj.y[a] - Y2[b]) / abs(1.0 - (h2 / h) ** scheme.order)
    scale = np.maximum(np.max(np.abs(traj.y), axis=0), atol / rtol)
    rel = e / scale
    value = float(np.max(rel)) if rel.size else math.inf
    value = value if math.isfinite(value) else math.inf
    worst = traj.t[a][np.unravel_index(np.argmax(rel), rel.shape)[0]] if math.isfinite(value) else t1
    return Check.of("step-doubling error", value, rtol, advice,
                    f"relative global error estimate of order {scheme.order}, worst at t={worst:.6g}")


def _common_times(T: np.ndarray, T2: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Indices ``(a, b)`` with ``|T[a] − T2[b]| <= tol`` (both records are monotonic in time)."""
    order = np.argsort(T2)
    S = T2[order]
    pos = np.clip(np.searchsorted(S, T), 1, len(S) - 1)
    near = np.where(np.abs(S[pos - 1] - T) <= np.abs(S[pos] - T), pos - 1, pos)
    hit = np.abs(S[near] - T) <= tol
    return np.flatnonzero(hit), order[near[hit]]
