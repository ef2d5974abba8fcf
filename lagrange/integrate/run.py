"""The simulation driver: validate the request, choose the method from the registry, hand over.

``simulate`` does only what every method shares — normalize ``t_span``, validate every option
(:mod:`lagrange.integrate.options`), derive and prepare the equations (friction regularized on request), split the
inputs, build the initial state, resolve ``method="auto"`` — then checks the request against the method's
registry entry (:mod:`lagrange.integrate.registry`) and calls its run function with a
:class:`~lagrange.integrate.request.RunRequest`. Discontinuous forces (Coulomb friction ``sign(v)``) are handled
by :mod:`lagrange.integrate.switching` (events at each sign change plus Filippov sliding for sticking).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import IntegrationError, LagrangeError, MethodError, shown
from ..results.trajectory import Trajectory
from . import registry  # (auto is imported where method="auto" is resolved: a named method never loads it)
from .checks import assess
from .options import _DEPRECATED as _UNSET
from .options import (
    DEFAULT_MAX_OUTPUT_BYTES,
    DEFAULT_MAX_STEPS,
    StepOptions,
    check_output_size,
    check_run_options,
    merge_deprecated,
)
from .prepare import GimbalLockWarning, check_model, initial_state, model_for, split_inputs
from .request import RunRequest

__all__ = ["simulate", "initial_state", "choose_method", "GimbalLockWarning", "DEFAULT_RTOL", "DEFAULT_ATOL"]

#: the adaptive methods' tolerances when none are given
DEFAULT_RTOL, DEFAULT_ATOL = 1e-9, 1e-11


def choose_method(eqs, params=None, t_span=(0.0, 1.0), y0=None, rtol: float | None = None, *,
                  backend: str | None = None, events: bool = False, varying_inputs: bool = False
                  ) -> tuple[str, str]:
    """A sensible method and the reason (``method="auto"``; :func:`lagrange.integrate.auto.choose`).

    The Jacobian's eigenvalues are estimated by finite differences of the compiled right-hand side at ``y0``
    (with ``params``; no estimate without them); stiff problems get the Taylor method when its
    stability-limited cost is below an implicit method's, else LSODA; the rest the Taylor method (python
    backend with the C tape interpreter, or rtol ≤ 1e-11) or DOP853. The Taylor method only for analytic
    equations with no near-singularity at the values of ``params`` (:mod:`lagrange.codegen.analyticity`).
    With ``events`` or ``varying_inputs`` only methods of the registry that support them.
    """
    needs = _needs(eqs, [None] if events else [], [], _Varying() if varying_inputs else None)
    built = None
    if params is not None and y0 is not None:
        built = _decision_model(eqs, params, None, {}, None)
    from . import auto
    return auto.choose(eqs, None if built is None else built.fun, float(t_span[0]), y0, t_end=float(t_span[1]),
                       rtol=1e-9 if rtol is None else rtol, backend=backend or "python", needs=needs,
                       values=_values(eqs, built))


def _values(eqs, model) -> dict | None:
    """``{symbol: value}`` of the parameters bound to ``model`` (None without a model)."""
    return None if model is None else dict(zip(eqs.numeric_parameters, np.asarray(model.params, dtype=float)))


class _Varying:
    """Stands for a schedule of time-varying inputs in :func:`choose_method`."""

    @staticmethod
    def describe() -> str:
        return "time-varying inputs"


def _decision_model(eqs, params, model, constants, schedule) -> NumericModel | None:
    """The model whose ``fun(t, y)`` ``method="auto"`` differentiates: the given model with the run's values,
    else the python build (handed on to the run when the run would build the same), or None when it cannot be
    built (the run then reports why)."""
    try:
        return model_for(eqs, params, model, "python" if model is None else model.backend, inputs=constants,
                         schedule=schedule)
    except (LagrangeError, ArithmeticError):
        return None


def simulate(
    system,
    t_span,
    initial: Mapping,
    params: Mapping,
    *,
    method: str = "DOP853",
    rtol: float | None = None,
    atol: float | None = None,
    t_eval=None,
    n_points: int = 1001,
    events=None,
    max_step: float = np.inf,
    backend: str = "python",
    model: NumericModel | None = None,
    inputs: Mapping | None = None,
    friction="events",
    friction_epsilon=_UNSET,
    stabilization="projection",
    baumgarte=_UNSET,
    project_initial=_UNSET,
    step: float | StepOptions | None = None,
    loop: str = "auto",
    max_steps: int = DEFAULT_MAX_STEPS,
    max_output_bytes: int = DEFAULT_MAX_OUTPUT_BYTES,
) -> Trajectory:
    """Integrate Lagrange's equations of ``system``.

    Parameters
    ----------
    t_span : (t0, t1) or a number t1 (then t0 = 0)
    initial : dict keyed by coordinates, their velocities (``q.diff(t)``) or names (``"q"``, ``"q_dot"``); with
        constraints the speeds left out are computed from the velocity constraints, and a given value moved onto
        the constraints is named in an :class:`~lagrange.errors.InitialStateChangedWarning` (see
        :func:`~lagrange.integrate.constrained.consistent_initial`)
    params : dict of parameter values keyed by symbol or name
    inputs : dict ``{input or name: value}``, one value for each input of the system
        (:mod:`lagrange.model.inputs`): a number, a function ``u(t)``, a feedback law ``u(t, y)`` of the state
        ``y = [q, q̇]``, samples ``(t_samples, values)`` (interpolated linearly) or an expression of ``t``; see
        :mod:`lagrange.codegen.input_values`. Constants run on every route; time-varying values need a route
        that calls Python per step (the scipy methods: ``method="auto"`` picks one and ``loop="auto"`` the
        scipy loop); the compiled loops and ``method="taylor"`` refuse them, the geometric methods refuse
        inputs (an input does work: not a conservative system). The trajectory gives the values (``sol[u]``)
        and its power balance includes the inputs' power.
    method : a name of the method registry (:mod:`lagrange.integrate.registry`; ``lagrange methods`` prints the
        table of what each supports; case-insensitive): ``DOP853`` (default), ``RK45``, ``RK23``, ``LSODA``,
        ``Radau``, ``BDF`` or ``auto``
        (the implicit ones get the generated Jacobian), ``taylor`` (adaptive Taylor series of order
        ``ceil(−ln(rtol)/2 + 1)`` for unconstrained analytic systems: nothing compiled per model with the
        python backend (the tape interpreted in C, or by numba without a C compiler), a compiled series
        with numba; see :mod:`lagrange.integrate.taylor`),
        or a fixed-step geometric integrator for conservative unconstrained systems — ``midpoint``, ``gl4``,
        ``gl6`` (Gauss–Legendre, symplectic),
        ``verlet`` (Störmer–Verlet, needs a constant mass matrix and V(q)) or ``dg`` (discrete gradient,
        energy conserved to the Newton tolerance) — with ``step=h``; see :mod:`lagrange.integrate.fixed`.
    rtol, atol : tolerances of the adaptive methods (default 1e-9 and 1e-11); for a fixed-step method the
        accuracy its verdict checks (default ``FIXED_RTOL = 1e-2``, ``FIXED_ATOL = 1e-6`` of
        :mod:`lagrange.integrate.fixed`)
    t_eval : output times; default ``n_points`` equally spaced times (fixed-step methods record about
        ``n_points`` states instead)
    max_step : largest step of the adaptive scipy methods
    max_steps : the most steps a run may take: a run whose ``max_step`` (adaptive) or ``step`` (fixed-step)
        would take more over the span is refused up front (:class:`~lagrange.errors.OptionError`), and a scipy
        run that takes more anyway (tiny steps of its own choosing) stops there with an
        :class:`~lagrange.errors.IntegrationError` carrying the trajectory so far; an integer in [1, 10⁹],
        default 10⁷ (:data:`~lagrange.integrate.options.DEFAULT_MAX_STEPS`)
    max_output_bytes : the most memory the recorded states may take (output times × 2n × 8 bytes); a run
        that would record more is refused up front; default 10⁹
        (:data:`~lagrange.integrate.options.DEFAULT_MAX_OUTPUT_BYTES`)
    step : the step of the fixed-step geometric methods: a number or a :class:`~lagrange.integrate.options.StepOptions`
    events : scipy-style event callables ``event(t, y)`` (``terminal``/``direction`` attributes honoured)
    backend : ``python`` (default), ``numba``, ``reference`` or ``auto``; see :mod:`lagrange.codegen.numeric`
    model : a NumericModel from :meth:`System.compile` to reuse (skips code generation); it must be this
        system's, and ``params`` are bound to it by name
    friction : a :class:`~lagrange.integrate.options.FrictionOptions` (treatment ``"events"`` or
        ``"regularize"`` and ε), or the treatment alone (default ``"events"``); see
        :mod:`lagrange.integrate.switching`
    stabilization : a :class:`~lagrange.integrate.options.Stabilization` (``"projection"``, ``"baumgarte"`` with
        its gains α, β, or ``"none"``; ``project_initial``), or the method alone (default ``"projection"``);
        see :mod:`lagrange.integrate.constrained`
    friction_epsilon, baumgarte, project_initial : deprecated (DeprecationWarning): the fields of the option
        objects above
    loop : ``"auto"`` (default), ``"compiled"`` or ``"scipy"`` — who runs the steps of DOP853/RK45:
        the compiled numba loop (no Python per step; implies ``backend="numba"``) or ``solve_ivp``;
        ``"auto"`` uses the compiled loop for numba models without events, constraints or friction
        switches. See :mod:`lagrange.integrate.compiled`; the ``method`` label of the result says which
        loop ran (``"DOP853 (compiled loop)"``) and, for numba models run by scipy, why. For the
        fixed-step geometric methods ``"compiled"`` runs them in numba
        (:mod:`lagrange.integrate._geometric_loops`, needs numba, any backend), ``"scipy"`` in Python and
        ``"auto"`` compiled when the backend is numba.

    Returns
    -------
    Trajectory
        With its :attr:`~lagrange.results.trajectory.Trajectory.verdict`: the run's own accuracy checks
        (:mod:`lagrange.integrate.checks`). When one fails, ``success`` is False, ``status`` is
        ``RunStatus.INACCURATE`` and an :class:`~lagrange.errors.AccuracyWarning` names the check, the number
        and what to try.

    Raises
    ------
    MethodError
        An unknown method, loop, friction or stabilization value, or a method that does not support what the
        run needs (events, constraints, friction switches, inputs, a non-conservative system); the message
        lists the methods that do.
    OptionError
        An option out of range (rtol, atol, n_points, max_step, step, t_eval, friction epsilon, Baumgarte
        gains), or a ``model`` compiled for another system; the message names the option and the limit.
    InitialConditionError, ParameterError
        Missing or bad initial values, parameters or input values (all listed); a speed left out that the
        velocity constraints do not determine; an inconsistent state with ``project_initial=False``.
    InputError
        An input callable that is neither ``u(t)`` nor ``u(t, y)``, or time-varying inputs on a route that
        cannot evaluate them.
    SingularMassMatrixError
        The mass matrix is singular at the initial state, or becomes singular during the run (the
        coordinates involved are named; during a run also ``t``, ``state`` and ``partial``).
    IntegrationError
        A numerical fault during the run: a non-finite value, a math domain error (sqrt of a negative
        number), an overflow (blow-up), a collapsed step size, or a failed Newton solve of a fixed-step
        method. The message gives the time, the state and the likely cause; ``t`` and ``state`` say where
        it stopped and ``partial`` is the Trajectory computed up to there (its last point is the last
        accepted step).
    IntegrationInterrupted
        Ctrl-C (SIGINT) during any run (scipy, compiled RK, geometric, Taylor): raised within about a second
        (the compiled loops run in chunks of bounded work), a :class:`KeyboardInterrupt` (not a
        LagrangeError) carrying the same ``t``, ``state`` and ``partial`` (the trajectory up to the
        interrupt, ``success=False``).
    """
    t0, t1 = _span(t_span)
    fr, st = merge_deprecated(friction, stabilization, friction_epsilon=friction_epsilon, baumgarte=baumgarte,
                              project_initial=project_initial)
    entry = None if isinstance(method, str) and method.strip().lower() == "auto" else registry.get(method)
    step_options = _step_for(entry, step)
    events = _events(events)
    given = (rtol, atol)  # a fixed-step run's verdict checks the accuracy asked for, when asked
    rtol, atol = (DEFAULT_RTOL if rtol is None else rtol), (DEFAULT_ATOL if atol is None else atol)
    t_eval = check_run_options((t0, t1), rtol=rtol, atol=atol, n_points=n_points, max_step=max_step,
                               t_eval=t_eval, step=step_options,
                               adaptive=entry is None or entry.adaptive or given != (None, None),
                               max_steps=max_steps)
    # a Taylor-series method reads the whole right-hand side as one expression: a structural system gives it its
    # expanded equations (cached on disk) without deriving the structural form it would not use
    taylor = entry is not None and entry.family == "Taylor series" and model is None
    eqs = system.expanded if taylor and hasattr(system, "expanded") else system.derived
    if hasattr(system, "bindable"):  # values of declared parameters that cancel out: ignored, with a warning
        params = system.bindable(params, eqs)
    check_model(model, eqs)
    switches = NumericModel.switches_of(eqs)
    if switches and fr.treatment == "regularize":
        eqs, switches = NumericModel.regularized(eqs, fr.epsilon), []
    if eqs.planar_friction:  # friction over a surface: exact |v| (floored) or regularized sqrt(|v|² + ε²)
        eqs = NumericModel.planar_friction(eqs, fr.treatment, fr.epsilon)
    y0 = initial_state(eqs.coordinates, initial, speeds_optional=bool(eqs.m))  # (computed: consistent_initial)
    check_output_size(int(n_points) if t_eval is None else max(len(t_eval), 2), y0.size, max_output_bytes)
    params, constants, schedule = split_inputs(eqs, params, inputs, (t0, t1), y0)
    needs = _needs(eqs, events, switches, schedule) | ({"dense_output": ""} if t_eval is not None else {})
    why, bound = "", False
    if entry is None:
        decided = _decision_model(eqs, params, model, constants, schedule)
        # a structural system's expanded equations, when at hand, let auto weigh the Taylor method (not with a
        # given model: that model is of the structural equations)
        expanded = (system.expanded_at_hand() if eqs.is_structural and model is None
                    and hasattr(system, "expanded_at_hand") else None)
        from . import auto
        name, why = auto.choose(eqs, None if decided is None else decided.fun, t0, y0, t_end=t1, rtol=rtol,
                                backend=backend if model is None else model.backend, needs=needs,
                                projection=bool(eqs.m) and st.method == "projection", taylor_equations=expanded,
                                values=_values(eqs, decided))
        entry = registry.get(name)
        if eqs.is_structural and entry.family == "Taylor series":
            eqs = expanded  # the tape's equations: same coordinates, parameters, inputs and needs
        elif model is None and backend == "python" and loop != "compiled" and decided is not None:
            model, bound = decided, True  # the python model the run would build again (same equations and values)
    entry.check_equations(eqs)
    registry.check_supported(entry, needs,
                             conservative=all(Q == 0 for Q in eqs.nonconservative))
    if switches and eqs.m:
        raise MethodError("dry-friction sign() switches with constraints: use friction='regularize'")
    req = RunRequest(system=system, equations=eqs, method=entry.name, why=why, t_span=(t0, t1), y0=y0,
                     initial=initial, params=params, constants=constants, schedule=schedule, model=model,
                     backend=backend, loop=loop, rtol=rtol, atol=atol, max_step=max_step, n_points=int(n_points),
                     t_eval=t_eval, events=events, switches=switches, friction=fr, stabilization=st,
                     step=step_options, model_bound=bound, max_steps=int(max_steps))
    return assess(entry.runner()(req), req, entry, rtol=given[0], atol=given[1])


def _span(t_span) -> tuple[float, float]:
    """``(t0, t1)`` from ``(t0, t1)`` or a number ``t1``; IntegrationError unless two different finite times."""
    if not isinstance(t_span, tuple | list) and np.ndim(t_span) == 0:
        t_span = (0.0, t_span)
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError, OverflowError):
        raise IntegrationError(f"t_span must be two different finite times, got {shown(t_span)}") from None
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 == t0:
        raise IntegrationError(f"t_span must be two different finite times, got {t_span}")
    return t0, t1


def _step_for(entry, step) -> StepOptions | None:
    """The step of a fixed-step method (required); refused for an adaptive one (which ignores it)."""
    if entry is not None and entry.step_required:
        if step is None:
            raise MethodError(f"method {entry.name!r} is a fixed-step integrator: give step=h > 0")
        return step if isinstance(step, StepOptions) else StepOptions(step)
    return None if step is None else (step if isinstance(step, StepOptions) else StepOptions(step))


def _events(events) -> list:
    """The user's events as a list; MethodError naming one that is not callable."""
    if events is None:
        return []
    events = list(events) if isinstance(events, list | tuple) else [events]
    bad = [e for e in events if not callable(e)]
    if bad:
        raise MethodError(f"events must be callables event(t, y), got {bad[0]!r}")
    return events


def _needs(eqs, events, switches, schedule) -> dict[str, str]:
    """The features of the registry a run needs, each with the detail its error message names."""
    needs: dict[str, str] = {}
    if events:
        needs["events"] = f"{len(events)} event function{'s' if len(events) > 1 else ''}"
    holonomic = [nm for nm, pos in zip(eqs.constraint_names, eqs.constraint_positions) if pos is not None]
    other = [nm for nm, pos in zip(eqs.constraint_names, eqs.constraint_positions) if pos is None]
    if holonomic:
        needs["holonomic"] = ", ".join(holonomic)
    if other:
        needs["nonholonomic"] = ", ".join(other)
    if switches:
        needs["friction_switches"] = f"{len(switches)} switch{'es' if len(switches) > 1 else ''}"
    if eqs.is_rough:
        needs["rough"] = ""
    if eqs.inputs:
        needs["inputs"] = ", ".join(u.name for u in eqs.inputs)
    if schedule is not None:
        needs["varying_inputs"] = schedule.describe()
    return needs
