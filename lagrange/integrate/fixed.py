"""Driver of the fixed-step geometric integrators: (q, q̇) → (q, p), stepping, back to a Trajectory.

``simulate(..., method=name, step=h)`` with ``name`` in :data:`GEOMETRIC` dispatches here.
"""

from __future__ import annotations

import math

import numpy as np

from ..conventions import VELOCITY_SUFFIX
from ..errors import IntegrationError
from ..model.coordinates import coordinate_name
from ..results.trajectory import Trajectory
from .discrete_gradient import DiscreteGradient
from .gauss_legendre import GaussLegendre4, GaussLegendre6, ImplicitMidpoint
from .hamiltonian_model import hamiltonian_model
from .stormer_verlet import StormerVerlet

__all__ = ["GEOMETRIC", "integrate_fixed"]

#: name → scheme
GEOMETRIC = {cls.name: cls for cls in (ImplicitMidpoint, GaussLegendre4, GaussLegendre6, StormerVerlet,
                                       DiscreteGradient)}


def integrate_fixed(system, t_span, y0, params, *, method: str, step: float, n_points: int = 1001,
                    model=None, tol: float = 1e-13) -> Trajectory:
    """Integrate from ``y0 = [q, q̇]`` over ``t_span`` with ``steps = round((t1 − t0)/step)`` fixed steps,
    recording about ``n_points`` states (every ``stride``-th step).

    Raises
    ------
    IntegrationError
        A step failed: Newton did not converge (the last residual is given), the Jacobian was singular, a
        non-finite state or an arithmetic error appeared. The message names the method, the step number,
        its time and the state before it; ``t``/``state`` are that time and state and ``partial`` is the
        trajectory up to it (the recorded states plus the last good one).
    """
    t0, t1 = t_span
    if not (step and step > 0 and math.isfinite(step)):
        raise TypeError(f"method {method!r} is a fixed-step integrator: give step=h > 0")
    steps = max(1, int(round((t1 - t0) / step)))
    h = (t1 - t0) / steps
    hm = hamiltonian_model(system, params)
    scheme = GEOMETRIC[method](hm, tol=tol)
    n = hm.n
    z = np.concatenate([y0[:n], hm.to_momenta(t0, y0[:n], y0[n:])])
    stride = max(1, steps // max(1, n_points - 1))
    ts, zs = [t0], [z.copy()]
    iters = 0
    if model is None:
        model = system.compile(params)
    label = f"{method} (fixed step h={h:.3g}, order {scheme.order}" + (", symplectic" if scheme.symplectic else "") \
        + (", energy-conserving" if scheme.energy_conserving else "") + ")"
    for k in range(steps):
        tk = t0 + k * h
        try:
            z_new, it = scheme.step(tk, z, h)
            if not np.all(np.isfinite(z_new)):
                raise IntegrationError(f"{method}: non-finite state after the step from t={tk:.9g}; a blow-up, "
                                       "or a step too large: reduce the step")
        except (IntegrationError, ZeroDivisionError, OverflowError, ValueError, FloatingPointError,
                np.linalg.LinAlgError) as exc:
            raise _step_fault(exc, k, steps, tk, z, (ts, zs), hm, model, label, t0, y0) from None
        z = z_new
        iters += it
        if (k + 1) % stride == 0 or k + 1 == steps:
            ts.append(t0 + (k + 1) * h)
            zs.append(z.copy())
    Y = _velocities(hm, ts, zs)
    return Trajectory(t=np.array(ts), y=Y, model=model, method=label, success=True,
                      message=f"{steps} steps, {iters} Newton iterations", nfev=steps, work=None,
                      initial=(t0, np.asarray(y0, dtype=float).copy()))


def _velocities(hm, ts, zs) -> np.ndarray:
    """``[q, q̇]`` rows from canonical ``(q, p)``: ``q̇ = ∂H/∂p``."""
    n = hm.n
    return np.array([np.concatenate([zi[:n], hm.grad(ti, zi)[n:]]) for ti, zi in zip(ts, zs)]).reshape(len(ts), 2 * n)


def _step_fault(exc, k, steps, tk, z, recorded, hm, model, label, t0, y0) -> IntegrationError:
    """The failed step ``k`` as an IntegrationError: where, why, and the trajectory up to the state before it."""
    ts, zs = list(recorded[0]), list(recorded[1])
    if ts[-1] != tk:
        ts.append(tk)
        zs.append(z.copy())
    Y = _velocities(hm, ts, zs)
    names = [coordinate_name(c) for c in model.equations.coordinates]
    n = len(names)
    state = ", ".join([f"{nm}={Y[-1, i]:.6g}" for i, nm in enumerate(names)]
                      + [f"{nm}{VELOCITY_SUFFIX}={Y[-1, n + i]:.6g}" for i, nm in enumerate(names)])
    cause = str(exc) if isinstance(exc, IntegrationError) else f"{type(exc).__name__}: {exc}"
    partial = Trajectory(t=np.array(ts), y=Y, model=model, method=f"{label} (stopped early)", success=False,
                         message=cause, nfev=k, work=None, initial=(t0, np.asarray(y0, dtype=float).copy()))
    return IntegrationError(
        f"step {k + 1} of {steps} failed at t={tk:.9g} ({state}): {cause}. The trajectory up to "
        f"t={tk:.9g} is in the error's `partial` attribute.",
        t=tk, state=dict(zip(model.equations.coordinates, Y[-1, :n])), partial=partial)
