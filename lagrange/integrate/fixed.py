"""Driver of the fixed-step geometric integrators: (q, q̇) → (q, p), stepping, back to a Trajectory.

``simulate(..., method=name, step=h)`` with ``name`` in :data:`GEOMETRIC` dispatches here.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import IntegrationError
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
    recording about ``n_points`` states (every ``stride``-th step)."""
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
    for k in range(steps):
        tk = t0 + k * h
        z, it = scheme.step(tk, z, h)
        iters += it
        if not np.all(np.isfinite(z)):
            raise IntegrationError(f"{method}: non-finite state at t={tk + h:.9g}; reduce the step", t=tk + h)
        if (k + 1) % stride == 0 or k + 1 == steps:
            ts.append(t0 + (k + 1) * h)
            zs.append(z.copy())
    Z = np.array(zs)
    # back to velocities: q̇ = ∂H/∂p
    Y = np.array([np.concatenate([zi[:n], hm.grad(ti, zi)[n:]]) for ti, zi in zip(ts, Z)])
    if model is None:
        model = system.compile(params)
    label = f"{method} (fixed step h={h:.3g}, order {scheme.order}" + (", symplectic" if scheme.symplectic else "") \
        + (", energy-conserving" if scheme.energy_conserving else "") + ")"
    return Trajectory(t=np.array(ts), y=Y, model=model, method=label, success=True,
                      message=f"{steps} steps, {iters} Newton iterations", nfev=steps, work=None,
                      initial=(t0, np.asarray(y0, dtype=float).copy()))
