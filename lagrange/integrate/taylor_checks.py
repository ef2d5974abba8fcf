r"""The Taylor method's check of its own run (:mod:`lagrange.results.verdict`), from states it reached.

The Taylor method takes no rejected steps: its step follows the last two series coefficients (Jorba & Zou
2005), which is right when the coefficients decay as the series' radius of convergence says. At up to
:data:`SAMPLES` output states (evenly spaced) the run is restarted with the same engine, order and tolerance:

- **Taylor local error** (the decay of the series over the step actually taken): the step the rule takes from
  the state, against two steps of half its length. Their difference estimates the truncation error of the
  step; divided by the local tolerance ``max(rtol·‖z‖∞, atol)`` it must stay below :data:`LOCAL_FACTOR` (the
  step rule keeps it near 1e-2 on resolved runs, stiff ones included). A step that reaches past the series'
  radius of convergence fails it by orders of magnitude: a nearly non-analytic right-hand side
  (``sqrt(x² + ε²)`` near x = 0, a regularized friction ``tanh(v/ε)`` where the velocity turns).

Not a check: the growth per step :math:`|R_p(h\lambda)| = |\sum_{k \le p} (h\lambda)^k/k!|` of the Jacobian's modes. A
Taylor step beyond the stability limit of a stiff mode at rest is routine and harmless (the step rule holds the
mode at the tolerance: a linear damped oscillator grows such a mode 10–2,000× per step and stays accurate to
its tolerance), so a limit on it would flag good runs; the local error is what separates the runs that go
wrong.

Cost: per sampled state two short restarts of the tape (one step, then two half steps): a fixed amount per
sampled state, whatever the length of the run (measured in benchmarks/results/verdict_cost.md).
"""

from __future__ import annotations

import math

import numpy as np

from ..results.verdict import Check

__all__ = ["taylor_checks", "SAMPLES", "LOCAL_FACTOR"]

#: output states at which the Taylor run is restarted for its checks
SAMPLES = 24
#: allowed ratio of the step-halving error estimate of a step to the local tolerance (the step rule aims at
#: about 1; a step past the radius of convergence is off by orders of magnitude)
LOCAL_FACTOR = 1e3
_ADVICE_LOCAL = "method='DOP853' or 'Radau' (the right-hand side is not analytic enough for a Taylor series here)"


def taylor_checks(traj, restart, order: int, rtol: float, atol: float) -> tuple[Check, ...]:
    """The local-error check of a Taylor run (module docstring).

    ``restart(t, z, t_end, max_step, max_steps) -> (t reached, z reached)`` runs the run's engine from a
    state ``z`` (the state and, for a non-conservative system, the work integral); ``order`` is the run's.
    """
    T, Y, W = traj.t, traj.y, traj.work
    t_end = T[-1]
    idx = np.unique(np.linspace(0, len(T) - 1, min(SAMPLES, len(T))).round().astype(int))
    worst, where = 0.0, ""
    for i in idx:
        t_i = float(T[i])
        z = np.ascontiguousarray(Y[i] if W is None else np.append(Y[i], W[i]))
        if t_i == t_end or not np.all(np.isfinite(z)):
            continue
        t_a, z_a = restart(t_i, z, t_end, math.inf, 1)
        h = t_a - t_i
        if not h > 0:
            continue
        t_b, z_b = restart(t_i, z, t_a, h / 2, 1000)
        tol = max(rtol * float(np.max(np.abs(z))), atol)
        err = float(np.max(np.abs(z_a - z_b))) / tol if t_b == t_a else math.inf
        err = err if math.isfinite(err) else math.inf
        if err > worst:
            worst, where = err, f"; worst at t={t_i:.6g}, step {h:.3g} (order {order})"
    return (Check.of("Taylor local error", worst, LOCAL_FACTOR, _ADVICE_LOCAL,
                     "step-halving estimate / local tolerance" + where),)
