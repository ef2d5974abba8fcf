"""Option objects of :func:`~lagrange.integrate.run.simulate`, and the validation of every simulate option.

The options that belong together travel as small frozen dataclasses that check themselves on construction
(:class:`~lagrange.errors.OptionError` naming the option, the value and the limit):

* :class:`FrictionOptions` — ``simulate(friction=FrictionOptions("regularize", epsilon=1e-4))``; the plain
  string ``friction="regularize"`` is shorthand for ``FrictionOptions("regularize")``;
* :class:`Stabilization` — ``simulate(stabilization=Stabilization("baumgarte", alpha=5, beta=5))``, with
  ``project_initial``; ``stabilization="none"`` is shorthand;
* :class:`StepOptions` — ``simulate(method="gl4", step=StepOptions(0.01))``; a number ``step=0.01`` is
  shorthand.

The flat keywords ``friction_epsilon``, ``baumgarte`` and ``project_initial`` still work for one release, with a
:class:`DeprecationWarning` (:func:`merge_deprecated`). :func:`check_run_options` validates the numbers
(tolerances, ``n_points``, ``max_step``, ``t_eval``) before anything is compiled; the limits are the constants
below.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..errors import MethodError, OptionError
from ..records import record

__all__ = ["FrictionOptions", "Stabilization", "StepOptions", "FRICTIONS", "STABILIZATIONS", "MAX_POINTS",
           "MAX_STEPS", "DEFAULT_MAX_STEPS", "DEFAULT_MAX_OUTPUT_BYTES", "check_run_options", "check_step_count",
           "check_output_size",
           "merge_deprecated", "as_friction", "as_stabilization", "as_step"]

FRICTIONS = ("events", "regularize")
STABILIZATIONS = ("projection", "baumgarte", "none")
#: most output points a run may record (8 bytes × 2n per point: 10⁷ points of a 5-DOF system is 800 MB)
MAX_POINTS = 10_000_000
#: the largest ``max_steps`` a run may be given: beyond this it would run for days
MAX_STEPS = 10**9
#: ``simulate(max_steps=...)`` by default: the steps a run may need (span / max_step, or span / step for a
#: fixed-step method) before it is refused up front; the compiled loops stop at the same count
DEFAULT_MAX_STEPS = 10_000_000
#: ``simulate(max_output_bytes=...)`` by default: the size of the recorded states (output times × 2n × 8 bytes)
DEFAULT_MAX_OUTPUT_BYTES = 1_000_000_000


def _positive_finite(option: str, value, *, allow_zero: bool = False) -> float:
    """``value`` as a float, or OptionError naming ``option`` when it is not a finite number > 0 (>= 0)."""
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise OptionError(f"{option} must be a number, got {value!r}")
    v = float(value)
    if not math.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        raise OptionError(f"{option} must be a finite number {'>= 0' if allow_zero else '> 0'}, got {value!r}")
    return v


def _choice(option: str, value, choices: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in choices:
        raise MethodError(f"{option} must be one of {', '.join(map(repr, choices))}, got {value!r}")
    return value


@record(frozen=True)
class FrictionOptions:
    """How dry-friction ``sign()`` switches are integrated (:mod:`lagrange.integrate.switching`).

    Attributes
    ----------
    treatment : ``"events"`` (default: exact, segment by segment) or ``"regularize"``
        (``sign(u) → u/sqrt(u² + ε²)``)
    epsilon : ε, the velocity scale of the regularization (finite, > 0; default 1e-6)
    """

    treatment: str = "events"
    epsilon: float = 1e-6

    def __post_init__(self):
        _choice("friction", self.treatment, FRICTIONS)
        object.__setattr__(self, "epsilon", _positive_finite("friction epsilon", self.epsilon))

    def __str__(self) -> str:
        return self.treatment if self.treatment == "events" else f"{self.treatment} (epsilon {self.epsilon:g})"


@record(frozen=True)
class Stabilization:
    """Constraint drift control (:mod:`lagrange.integrate.constrained`).

    Attributes
    ----------
    method : ``"projection"`` (default), ``"baumgarte"`` or ``"none"``
    alpha, beta : Baumgarte's gains in 1/time (finite, >= 0; default 10, 10)
    project_initial : project an inconsistent initial state onto the constraints (default) or raise
    """

    method: str = "projection"
    alpha: float = 10.0
    beta: float = 10.0
    project_initial: bool = True

    def __post_init__(self):
        _choice("stabilization", self.method, STABILIZATIONS)
        object.__setattr__(self, "alpha", _positive_finite("Baumgarte alpha", self.alpha, allow_zero=True))
        object.__setattr__(self, "beta", _positive_finite("Baumgarte beta", self.beta, allow_zero=True))
        if not isinstance(self.project_initial, bool | np.bool_):
            raise OptionError(f"project_initial must be True or False, got {self.project_initial!r}")

    def __str__(self) -> str:
        return self.method


@record(frozen=True)
class StepOptions:
    """The step of a fixed-step (geometric) method.

    Attributes
    ----------
    h : the step (finite, > 0; the run takes ``round(span / h)`` steps, at most :data:`MAX_STEPS`)
    estimate : whether the run's verdict includes Richardson's error estimate (default True): a second run
        at twice the step, about half the cost of the first
        (:func:`lagrange.integrate.fixed.step_doubling_check`); False skips it (the verdict then has the
        energy check only)
    """

    h: float
    estimate: bool = True

    def __post_init__(self):
        object.__setattr__(self, "h", _positive_finite("step", self.h))
        if not isinstance(self.estimate, bool | np.bool_):
            raise OptionError(f"StepOptions estimate must be True or False, got {self.estimate!r}")
        object.__setattr__(self, "estimate", bool(self.estimate))


def as_friction(value) -> FrictionOptions:
    """``friction=`` as a :class:`FrictionOptions` (a string is the treatment)."""
    return value if isinstance(value, FrictionOptions) else FrictionOptions(_choice("friction", value, FRICTIONS))


def as_stabilization(value) -> Stabilization:
    """``stabilization=`` as a :class:`Stabilization` (a string is the method)."""
    if isinstance(value, Stabilization):
        return value
    return Stabilization(_choice("stabilization", value, STABILIZATIONS))


def as_step(value) -> StepOptions | None:
    """``step=`` as a :class:`StepOptions` (a number is the step; None: not given)."""
    if value is None or isinstance(value, StepOptions):
        return value
    return StepOptions(value)


_DEPRECATED = object()


def merge_deprecated(friction, stabilization, *, friction_epsilon=_DEPRECATED, baumgarte=_DEPRECATED,
                     project_initial=_DEPRECATED, stacklevel: int = 3) -> tuple[FrictionOptions, Stabilization]:
    """The friction and stabilization objects, with the deprecated flat keywords folded in (each one given
    warns once with :class:`DeprecationWarning` and says what replaces it)."""
    fr, st = as_friction(friction), as_stabilization(stabilization)
    if friction_epsilon is not _DEPRECATED:
        warnings.warn("simulate(friction_epsilon=...) is deprecated: pass friction=FrictionOptions(treatment, "
                      "epsilon=...)", DeprecationWarning, stacklevel=stacklevel)
        fr = FrictionOptions(fr.treatment, friction_epsilon)
    changes = {}
    if baumgarte is not _DEPRECATED:
        warnings.warn("simulate(baumgarte=(alpha, beta)) is deprecated: pass stabilization=Stabilization("
                      "'baumgarte', alpha=..., beta=...)", DeprecationWarning, stacklevel=stacklevel)
        try:
            alpha, beta = baumgarte
        except (TypeError, ValueError):
            raise OptionError(f"baumgarte must be a pair (alpha, beta), got {baumgarte!r}") from None
        changes.update(alpha=alpha, beta=beta)
    if project_initial is not _DEPRECATED:
        warnings.warn("simulate(project_initial=...) is deprecated: pass stabilization=Stabilization(..., "
                      "project_initial=...)", DeprecationWarning, stacklevel=stacklevel)
        changes["project_initial"] = project_initial
    if changes:
        st = Stabilization(**{"method": st.method, "alpha": st.alpha, "beta": st.beta,
                              "project_initial": st.project_initial, **changes})
    return fr, st


def _count(option: str, value, limit: int) -> int:
    """``value`` as an int in [1, limit], or OptionError naming ``option``."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or not 1 <= value <= limit:
        raise OptionError(f"{option} must be an integer between 1 and {limit:.0e}, got {value!r}")
    return int(value)


def check_step_count(span: float, h: float, option: str, max_steps) -> None:
    """OptionError when steps of at most ``h`` (the option named ``option``: ``max_step`` or ``step``) would
    need more than ``max_steps`` (an integer in [1, MAX_STEPS], checked too) over ``span``."""
    limit = _count("max_steps", max_steps, MAX_STEPS)
    if span / h > limit:
        raise OptionError(f"{option}={h!r} would take {span / h:.3g} steps over the span {span:g}, more than the "
                          f"limit max_steps={limit:,}: use {option} >= {span / limit:.3g}, or raise max_steps (up "
                          f"to {MAX_STEPS:.0e})")


def check_output_size(n_times: int, n_state: int, max_output_bytes) -> None:
    """OptionError when ``n_times`` recorded states of ``n_state`` floats would exceed ``max_output_bytes``
    (a positive integer: refused too when it is not one)."""
    limit = _count("max_output_bytes", max_output_bytes, 2**62)
    size = n_times * n_state * 8
    if size > limit:
        raise OptionError(f"the run would record {n_times:,} states of {n_state} numbers ({size:.3g} bytes), more "
                          f"than max_output_bytes={limit:,}: ask for fewer output times (n_points or t_eval), or "
                          "raise max_output_bytes if the memory is there")


def check_run_options(t_span, *, rtol, atol, n_points, max_step, t_eval, step: StepOptions | None,
                      adaptive: bool, max_steps=DEFAULT_MAX_STEPS) -> np.ndarray | None:
    """Validate the numeric options of a run over ``t_span = (t0, t1)``; return ``t_eval`` as an array.

    Raises
    ------
    OptionError
        ``rtol`` not finite or <= 0, ``atol`` not finite or < 0, ``atol = rtol = 0``; ``n_points`` not an
        integer in [2, MAX_POINTS]; ``max_steps`` not an integer in [1, MAX_STEPS]; ``max_step`` not > 0 or so
        small that the span needs more than ``max_steps`` steps; ``step`` the same; ``t_eval`` not
        one-dimensional, empty, not finite, outside the span, unsorted or longer than MAX_POINTS.
    """
    t0, t1 = t_span
    span = abs(t1 - t0)
    limit = _count("max_steps", max_steps, MAX_STEPS)
    if adaptive:
        _positive_finite("rtol", rtol)  # so atol = rtol = 0 is refused too
        _positive_finite("atol", atol, allow_zero=True)
        if isinstance(max_step, bool) or not isinstance(max_step, int | float | np.integer | np.floating) \
                or math.isnan(max_step) or max_step <= 0:
            raise OptionError(f"max_step must be a number > 0 (inf: no limit), got {max_step!r}")
        check_step_count(span, float(max_step), "max_step", limit)
    if step is not None:
        check_step_count(span, step.h, "step", limit)
    if isinstance(n_points, bool) or not isinstance(n_points, int | np.integer):
        raise OptionError(f"n_points must be an integer, got {n_points!r}")
    if not 2 <= n_points <= MAX_POINTS:
        raise OptionError(f"n_points must be between 2 and {MAX_POINTS:,}, got {n_points}")
    if t_eval is None:
        return None
    try:
        te = np.asarray(t_eval, dtype=float)
    except (TypeError, ValueError):
        raise OptionError(f"t_eval must be a sequence of times, got {t_eval!r}") from None
    if te.ndim != 1:
        raise OptionError(f"t_eval must be one-dimensional, got shape {te.shape}")
    if te.size == 0:
        raise OptionError("t_eval is empty: give at least one output time, or leave it out (n_points equally "
                          "spaced times)")
    if te.size > MAX_POINTS:
        raise OptionError(f"t_eval has {te.size:,} times, more than the limit {MAX_POINTS:,}")
    if te.size and not np.all(np.isfinite(te)):
        raise OptionError("t_eval contains a non-finite time")
    lo, hi = min(t0, t1), max(t0, t1)
    if te.size and (te.min() < lo or te.max() > hi):
        bad = te[(te < lo) | (te > hi)][0]
        raise OptionError(f"t_eval contains t={bad:g}, outside the span [{lo:g}, {hi:g}]")
    d = np.diff(te)
    if d.size and ((t1 > t0 and not d.min() > 0) or (t1 < t0 and not d.max() < 0)):
        raise OptionError("t_eval must be strictly sorted in the direction of integration")
    return te
