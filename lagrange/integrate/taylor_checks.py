r"""The Taylor method's checks of its own run (:mod:`lagrange.results.verdict`), from states it reached.

The Taylor method takes no rejected steps: its step follows the last two series coefficients (Jorba & Zou
2005), which is right when the coefficients decay as the series' radius of convergence says, and wrong in two
ways the power balance need not show. At up to :data:`SAMPLES` output states (evenly spaced, the last one
included) the run is restarted for a few steps with the same engine, order and tolerance:

- **Taylor local error** (the decay of the series over the step actually taken): the step the rule takes from
  the state, against two steps of half its length. Their difference estimates the truncation error of the
  step; divided by the local tolerance ``max(rtol·‖z‖∞, atol)`` it must stay below :data:`LOCAL_FACTOR`. A step
  that reaches past the series' radius (a nearly non-analytic right-hand side, ``sqrt(x² + ε²)`` near x = 0)
  fails it.
- **Taylor stability**: the Jacobian ``J`` of the right-hand side at the state (forward differences, 2n + 1
  evaluations) and the step ``h`` the rule takes there. A mode of ``J`` that the state does not excite is
  invisible to the coefficients, yet the step multiplies it by the Taylor polynomial
  :math:`R_p(h\lambda) = \sum_{k \le p} (h\lambda)^k/k!` where the exact flow multiplies it by
  :math:`e^{h\lambda}`. The check is :math:`\max_\lambda |R_p(h\lambda)| / \max(1, |e^{h\lambda}|)` against
  :data:`STABILITY_LIMIT`: above it a decaying mode grows from step to step (a stiff mode at rest, such as the
  regularized friction of a block that sticks), and the run can drift far from the solution with a clean power
  balance.

Cost: per sampled state two short restarts of the tape (one step, then two half steps), 2n + 1 right-hand-side
evaluations and the eigenvalues of a 2n × 2n matrix: a fixed amount per sampled state, whatever the
length of the run (measured in benchmarks/results/verdict_cost.md).
"""

from __future__ import annotations

import math

import numpy as np

from ..results.verdict import Check

__all__ = ["taylor_checks", "SAMPLES", "LOCAL_FACTOR", "STABILITY_LIMIT", "amplification"]

#: output states at which the Taylor run is restarted for its checks
SAMPLES = 24
#: allowed ratio of the step-halving error estimate of a step to the local tolerance (the step rule aims at
#: about 1; a step past the radius of convergence is off by orders of magnitude)
LOCAL_FACTOR = 1e3
#: allowed growth per step of a mode of the Jacobian beyond what the exact flow does
STABILITY_LIMIT = 2.0
_ADVICE_LOCAL = "method='DOP853' or 'Radau' (the right-hand side is not analytic enough for a Taylor series here)"
_ADVICE_STABLE = "method='Radau' or 'LSODA' (a stiff mode at rest: the Taylor steps are not stable)"


def amplification(z: np.ndarray, order: int) -> np.ndarray:
    """``|R_p(z)| / max(1, |e^z|)`` for the order-``order`` Taylor polynomial ``R_p`` of the exponential: the
    factor by which a step of the Taylor method multiplies a mode of eigenvalue ``λ = z/h``, beyond the growth
    of the exact flow when that grows. Where the series resolves the mode it is ``min(|e^z|, 1)`` up to the
    truncation error: at most 1; a decaying mode stepped past the stability limit grows (> 1).

    >>> float(amplification(np.array([-1.0]), 8)[0]).__round__(4), float(amplification(np.array([-8.0]), 8)[0]) > 10
    (0.3679, True)
    """
    z = np.asarray(z, dtype=complex)
    term, total = np.ones_like(z), np.ones_like(z)
    for k in range(1, order + 1):
        term = term * z / k
        total = total + term
    return np.abs(total) / np.maximum(1.0, np.abs(np.exp(np.minimum(z.real, 700.0)) * 1.0))


def taylor_checks(traj, restart, order: int, rtol: float, atol: float) -> tuple[Check, ...]:
    """The local-error and stability checks of a Taylor run (module docstring).

    ``restart(t, z, t_end, max_step, max_steps) -> (t reached, z reached)`` runs the run's engine from a
    state ``z`` (the state and, for a non-conservative system, the work integral) and ``order`` is the run's.
    """
    from .auto import difference_jacobian

    n2 = 2 * traj.model.n
    T, Y = traj.t, traj.y
    W = traj.work
    t_end = T[-1]
    idx = np.unique(np.linspace(0, len(T) - 1, min(SAMPLES, len(T))).round().astype(int))
    local, stable = [0.0, ""], [0.0, ""]
    for i in idx:
        t_i = float(T[i])
        if t_i == t_end:
            continue
        z = np.ascontiguousarray(Y[i] if W is None else np.append(Y[i], W[i]))
        if not np.all(np.isfinite(z)):
            continue
        t_a, z_a = restart(t_i, z, t_end, math.inf, 1)
        h = t_a - t_i
        if not h > 0:
            continue
        t_b, z_b = restart(t_i, z, t_a, h / 2, 1000)
        tol = max(rtol * float(np.max(np.abs(z))), atol)
        err = float(np.max(np.abs(z_a - z_b))) / tol if t_b == t_a else math.inf
        err = err if math.isfinite(err) else math.inf
        if err > local[0]:
            local = [err, f"worst at t={t_i:.6g}, step {h:.3g}"]
        found = difference_jacobian(traj.model.fun, t_i, Y[i][:n2], smooth=True)
        if found is None:
            continue
        lam = np.linalg.eigvals(found[0])
        growth = amplification(h * lam, order)
        amp = float(np.max(growth, initial=0.0))
        amp = amp if math.isfinite(amp) else math.inf
        if amp > stable[0]:
            worst = lam[np.argmax(growth)]
            stable = [amp, f"worst at t={t_i:.6g}: step {h:.3g}, eigenvalue {complex(worst):.3g}"]
    return (Check.of("Taylor local error", local[0], LOCAL_FACTOR, _ADVICE_LOCAL,
                     "step-halving estimate / local tolerance" + (f"; {local[1]}" if local[1] else "")),
            Check.of("Taylor stability", stable[0], STABILITY_LIMIT, _ADVICE_STABLE,
                     "growth per step of the worst mode beyond the exact flow" + (f"; {stable[1]}" if stable[1]
                                                                                 else "")))
