"""What a run could check about itself, and its verdict.

Every trajectory returned by :func:`lagrange.simulate` carries a :class:`Verdict`: a tuple of :class:`Check`
records, each a number the run measured on itself against what its tolerance allows. The checks use data the
run already has, except the fixed-step error estimate (a second run at twice the step). When a check fails the
run is not reported as a plain success: ``Trajectory.success`` is False, ``Trajectory.status`` is
:attr:`RunStatus.INACCURATE`, and :func:`lagrange.simulate` warns with
:class:`~lagrange.errors.AccuracyWarning` naming the check, the number and what to try.

The checks and their limits (docs/guarantees.md, "Accuracy verdict"):

- **power balance** (every run): the relative residual :meth:`~lagrange.results.trajectory.Trajectory.energy_error`
  (the energy drift of a conservative system) must stay below
  ``min(ENERGY_CAP, ENERGY_FACTOR × (rtol + atol / max|y|))``: a thousand times the local tolerance (global
  errors grow with the number of steps), and never more than 1 %.
- **constraint drift** (constrained systems): the largest ``|φ|`` relative to ``max(max|q|, atol/rtol)`` (and
  ``|A q̇ + b|`` relative to ``max|q̇|``) must stay below ``min(CONSTRAINT_CAP, CONSTRAINT_FACTOR × rtol)``.
- **step-doubling error** (fixed-step methods, :mod:`lagrange.integrate.fixed`): Richardson's estimate of the
  global error against the requested ``rtol``/``atol``.
- **Taylor local error** (``method="taylor"``, :mod:`lagrange.integrate.taylor_checks`): one step against two
  half steps from sampled states, against the local tolerance.

The limits are named constants with their reason; the tests in tests/test_verdict.py hold both sides of each
(runs that must pass quietly, runs that must be flagged).
"""

from __future__ import annotations

import enum
import html
import math

import numpy as np

from ..records import record

__all__ = ["Check", "Verdict", "RunStatus", "ENERGY_FACTOR", "ENERGY_CAP", "CONSTRAINT_FACTOR", "CONSTRAINT_CAP",
           "energy_check", "constraint_checks", "tolerance_scale"]

#: power balance: allowed relative residual per unit of local tolerance (global error grows with the steps)
ENERGY_FACTOR = 1e3
#: power balance: the relative residual above which no run is accurate, whatever its tolerance (1 %)
ENERGY_CAP = 1e-2
#: constraint drift: allowed relative violation per unit of rtol (projection holds it near rounding, Baumgarte
#: below rtol; without stabilization it grows with time)
CONSTRAINT_FACTOR = 1e2
#: constraint drift: the relative violation above which no run is accurate, whatever its tolerance (1 %)
CONSTRAINT_CAP = 1e-2


class RunStatus(enum.Enum):
    """How a run ended; each value is the message that says what it means and what to do."""

    SUCCESS = "reached the end and passed its own accuracy checks"
    INACCURATE = ("reached the end but failed its own accuracy checks (see `verdict`): tighten the tolerance, "
                  "shorten the step or change the method")
    STOPPED = "stopped before the end (see `message`)"


@record(frozen=True, slots=True)
class Check:
    """One number a run measured on itself.

    Attributes
    ----------
    name : what was measured (``"power balance"``, ``"step-doubling error"``, ...)
    value : the measured number (relative unless the name says otherwise)
    allowed : the limit the tolerance allows
    passed : ``value <= allowed`` (False as well when the value could not be measured: it is then inf)
    advice : what to try when it fails (a method, a tolerance, a step)
    detail : where or how it was measured (e.g. the worst time)
    """

    name: str
    value: float
    allowed: float
    passed: bool
    advice: str = ""
    detail: str = ""

    @classmethod
    def of(cls, name: str, value: float, allowed: float, advice: str, detail: str = "") -> Check:
        """A check that passes when ``value <= allowed`` (a NaN value fails)."""
        value = float(value)
        return cls(name, value, float(allowed), bool(value <= allowed), advice, detail)

    def __str__(self) -> str:
        mark = "ok" if self.passed else "FAILED"
        text = f"{self.name}: {self.value:.3g} (allowed {self.allowed:.3g}) {mark}"
        if self.detail:
            text += f" [{self.detail}]"
        if not self.passed and self.advice:
            text += f"; try {self.advice}"
        return text


@record(frozen=True, slots=True)
class Verdict:
    """The checks of one run. ``ok`` when every check passed (also when there was nothing to check)."""

    checks: tuple = ()

    @property
    def ok(self) -> bool:
        return all(c.passed for c in self.checks)

    @property
    def failed(self) -> tuple:
        """The checks that failed."""
        return tuple(c for c in self.checks if not c.passed)

    def summary(self) -> str:
        """One line: ``accurate (3 checks passed)`` or the failed checks."""
        if self.ok:
            return f"accurate ({len(self.checks)} check{'s' if len(self.checks) != 1 else ''} passed)"
        return "INACCURATE: " + "; ".join(str(c) for c in self.failed)

    def __str__(self) -> str:
        head = "verdict: " + ("accurate" if self.ok else "INACCURATE")
        return "\n".join([head, *(f"  {c}" for c in self.checks)])

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{html.escape(c.name)}</td><td>{c.value:.3g}</td><td>{c.allowed:.3g}</td>"
            f"<td>{'ok' if c.passed else '<b>FAILED</b>'}</td>"
            f"<td>{html.escape(c.detail)}{'' if c.passed else '; try ' + html.escape(c.advice)}</td></tr>"
            for c in self.checks)
        return ("<table><tr><th>check</th><th>value</th><th>allowed</th><th></th><th></th></tr>"
                f"{rows}</table>")


def tolerance_scale(y: np.ndarray, rtol: float, atol: float) -> float:
    """The relative local tolerance of a run whose states reach ``max|y|``: ``rtol + atol / max|y|`` (the
    absolute tolerance counts where the state is small)."""
    size = float(np.max(np.abs(y))) if np.size(y) else 0.0
    return rtol + (atol / size if size > 0 and math.isfinite(size) else 0.0)


def energy_check(traj, rtol: float, atol: float) -> Check:
    """The power-balance (energy-drift) check of ``traj`` for a run at ``rtol``/``atol`` (module docstring)."""
    allowed = min(ENERGY_CAP, ENERGY_FACTOR * tolerance_scale(traj.y, rtol, atol))
    try:
        value = traj.energy_error()
    except (ArithmeticError, ValueError):
        value = math.inf
    if not math.isfinite(value):
        value = math.inf
    name = "energy drift" if traj.work is None else "power balance"
    return Check.of(name, value, allowed, "a tighter rtol, or a smaller step for a fixed-step method",
                    "relative to the largest energy term")


def constraint_checks(traj, rtol: float, atol: float) -> tuple[Check, ...]:
    """The constraint-drift checks of ``traj`` (none without constraints; module docstring)."""
    v = traj.constraint_violation
    if not v:
        return ()
    n = traj.model.n
    out = []
    for level, cols in (("position", slice(0, n)), ("velocity", slice(n, 2 * n))):
        size = float(np.max(np.abs(traj.y[:, cols]))) if traj.y.size else 0.0
        scale = max(size, atol / rtol) if math.isfinite(size) else math.inf
        worst = float(np.max(v[level])) if v[level].size else 0.0
        value = worst / scale if math.isfinite(worst) and scale > 0 else (0.0 if worst == 0 else math.inf)
        allowed = min(CONSTRAINT_CAP, CONSTRAINT_FACTOR * rtol)
        out.append(Check.of(f"constraint drift ({level})", value, allowed,
                            "stabilization='projection', a tighter rtol, or a smaller step",
                            ("largest |phi|" if level == "position" else "largest |A q' + b|")
                            + f" {worst:.3g} relative to max|{'q' if level == 'position' else 'dq/dt'}|"))
    return tuple(out)
