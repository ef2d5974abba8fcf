"""The verdict of a finished run (:mod:`lagrange.results.verdict`): which checks apply to which method, computed
once when :func:`~lagrange.integrate.run.simulate` hands back the trajectory.

Every run: the power balance (energy drift; not for a fixed-step run of a system with explicit time, whose
work integral is not integrated) and, with constraints, the constraint drift, against the run's
``rtol``/``atol``. Fixed-step methods: Richardson's step-doubling error estimate
(:func:`lagrange.integrate.fixed.step_doubling_check`; skipped with ``StepOptions(h, estimate=False)``),
against ``rtol``/``atol`` when given, else :data:`~lagrange.integrate.fixed.FIXED_RTOL` and
:data:`~lagrange.integrate.fixed.FIXED_ATOL`. ``method="taylor"``: the local error of its steps
(:mod:`lagrange.integrate.taylor_checks`). A failed check makes ``success`` False and warns once with
:class:`~lagrange.errors.AccuracyWarning`.
"""

from __future__ import annotations

import dataclasses
import warnings

from ..errors import AccuracyWarning
from ..results.trajectory import Trajectory
from ..results.verdict import Verdict, constraint_checks, energy_check

__all__ = ["assess", "accuracy_message"]


def assess(traj: Trajectory, req, entry, *, rtol: float | None, atol: float | None) -> Trajectory:
    """``traj`` with its :class:`~lagrange.results.verdict.Verdict` (``success`` False when a check failed),
    warning with :class:`~lagrange.errors.AccuracyWarning` then. ``rtol``/``atol`` are the user's (None when
    not given); a trajectory that did not reach the end is returned as it is."""
    if not traj.success or len(traj.t) < 2:
        return traj
    if entry.step_required:
        from .fixed import FIXED_ATOL, FIXED_RTOL

        rtol = FIXED_RTOL if rtol is None else rtol
        atol = FIXED_ATOL if atol is None else atol
    else:
        rtol, atol = req.rtol, req.atol
    # the Jacobi integral balances only with its work integral, or when nothing changes it (a fixed-step run of a
    # system with explicit t integrates no work: no energy check there)
    energy = traj.work is not None or traj.model.equations.is_conservative
    checks = [*([energy_check(traj, rtol, atol)] if energy else []), *constraint_checks(traj, rtol, atol)]
    if entry.step_required and req.step.estimate:
        from .fixed import fixed_loop, step_doubling_check

        checks.append(step_doubling_check(traj, method=entry.name, step=req.step.h, t_span=req.t_span, y0=req.y0,
                                          compiled=fixed_loop(req.loop, backend=req.backend, model=req.model),
                                          rtol=rtol, atol=atol))
    if entry.name == "taylor":
        from .taylor import restarter
        from .taylor_checks import taylor_checks

        restart, order = restarter(traj.model, rtol=req.rtol, atol=req.atol)
        checks += taylor_checks(traj, restart, order, req.rtol, req.atol)
    verdict = Verdict(tuple(checks))
    traj = dataclasses.replace(traj, verdict=verdict, success=traj.success and verdict.ok)
    if not verdict.ok:
        warnings.warn(accuracy_message(traj), AccuracyWarning, stacklevel=4)
    return traj


def accuracy_message(traj: Trajectory) -> str:
    """The warning's text: each failed check with its number, its limit and what to try."""
    parts = [f"{c.name} {c.value:.3g} exceeds the {c.allowed:.3g} allowed"
             + (f" ({c.detail})" if c.detail else "") + (f"; try {c.advice}" if c.advice else "")
             for c in traj.verdict.failed]
    return (f"the run ({traj.method}) failed its own accuracy checks: " + " | ".join(parts)
            + ". Its `success` is False; `verdict` lists every check.")
