"""The simulation driver: validate inputs, compile, integrate with scipy, return a Trajectory.

Discontinuous forces (Coulomb friction ``sign(v)``) are handled by
:mod:`lagrange.integrate.switching` (events at each sign change plus Filippov sliding for sticking);
see its docstring for the documented treatment.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from functools import lru_cache

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.linalg.lapack import dsyev

from ..codegen.cse import numeric_arguments, rename_map
from ..codegen.input_values import VARYING_ROUTES, resolve_inputs
from ..codegen.numeric import NumericModel, compile_equations, lam_required
from ..conventions import VELOCITY_SUFFIX
from ..errors import (
    InitialConditionError,
    InputError,
    IntegrationError,
    LagrangeError,
    ParameterError,
    SingularMassMatrixError,
)
from ..model.coordinates import coordinate_name, is_coordinate, state_text
from ..results.trajectory import Trajectory
from .constrained import STABILIZATIONS, Projector, baumgarte_rhs, consistent_initial
from .rough import run_rough
from .scipy_ivp import IMPLICIT_METHODS, SCIPY_METHODS, jacobian_function
from .stepper import STEPPABLE, StepLog, interrupt_of, interrupted_run, recording, step_loop

__all__ = ["simulate", "initial_state", "choose_method"]


def initial_state(coords: Sequence, initial: Mapping) -> np.ndarray:
    """``y0 = [q, q̇]`` from a dict keyed by coordinates, their derivatives or names (``"x_dot"``).

    Raises :class:`InitialConditionError` naming every missing, unknown or non-finite entry.
    """
    names, slot_of = _slots(tuple(coords))
    n = len(names)
    values = [math.nan] * (2 * n)
    filled = [False] * (2 * n)
    problems = []
    for key, value in initial.items():
        try:
            idx = slot_of.get(key)
        except TypeError:  # an unhashable key
            idx = None
        if idx is None:
            problems.append(f"{key} is not a coordinate or velocity of this system ({', '.join(names)})")
            continue
        try:
            v = float(value)
        except (TypeError, ValueError):
            problems.append(f"initial value of {key} = {value!r} is not a number")
            continue
        if not math.isfinite(v):
            problems.append(f"initial value of {key} = {v} is not finite")
        values[idx], filled[idx] = v, True
    if not all(filled):
        missing = [names[i] if i < n else names[i - n] + VELOCITY_SUFFIX for i in range(2 * n) if not filled[i]]
        problems.append(f"missing initial value(s) for {', '.join(missing)}")
    if problems:
        raise InitialConditionError("; ".join(problems))
    return np.array(values, dtype=float)


@lru_cache(maxsize=256)
def _slots(coords: tuple) -> tuple[list[str], dict]:
    """The coordinate names and the state slot of every accepted key: a coordinate or its name (i), its
    velocity ``q.diff(t)`` or ``"<name>_dot"`` (n + i)."""
    n = len(coords)
    names = [coordinate_name(c) for c in coords]
    slot_of: dict = {}
    for i, (c, name) in enumerate(zip(coords, names)):  # names first: a coordinate may be called "x_dot"
        slot_of.setdefault(name, i)
        if is_coordinate(c):
            slot_of.setdefault(c, i)
            slot_of.setdefault(c.diff(c.args[0]), n + i)
    for i, name in enumerate(names):
        slot_of.setdefault(name + VELOCITY_SUFFIX, n + i)
    return names, slot_of


def _stiffness(eqs, params, t_span, y0) -> tuple[float, float] | None:
    """(fastest decay rate max(−Re λ), stiffness ratio) of the Jacobian at the initial state, or None."""
    if eqs.m or params is None or y0 is None:
        return None
    try:
        model = compile_equations(eqs, params)
        lam = np.linalg.eigvals(jacobian_function(model)(float(t_span[0]), y0))
    except (LagrangeError, np.linalg.LinAlgError, ValueError, TypeError, ZeroDivisionError):
        return None
    decay = float(np.max(-lam.real, initial=0.0))
    nonzero = np.abs(lam)[np.abs(lam) > 1e-9 * max(1.0, float(np.max(np.abs(lam))))]
    slow = float(np.min(nonzero)) if nonzero.size else 1.0
    return decay, decay / slow


def _taylor_ready(eqs) -> bool:
    """Whether ``method="taylor"`` can run ``eqs`` here (a C compiler or numba, analytic unconstrained
    equations)."""
    from ..codegen.tape import TapeError
    from .taylor import available_interpreter, tape_of

    if available_interpreter() is None:
        return False
    try:
        tape_of(eqs)
    except TapeError:
        return False
    return True


def choose_method(eqs, params=None, t_span=(0.0, 1.0), y0=None, rtol: float | None = None, *,
                  backend: str | None = None, events: bool = False, varying_inputs: bool = False
                  ) -> tuple[str, str]:
    """A sensible method and the reason (``method="auto"``).

    From the Jacobian's eigenvalues at the initial state: a fast decay (rate × horizon > 10³) much faster
    than the slowest mode (ratio > 10³) is stiffness → Radau with the generated Jacobian (explicit methods
    would need hundreds of thousands of steps). Otherwise dissipative systems (P or D) get LSODA, which
    switches to BDF if stiffness appears later. The rest get DOP853, the most efficient Runge–Kutta method
    at tight tolerances — or the Taylor method when the equations are analytic and unconstrained and there
    are no ``events``: with ``backend`` ``"python"`` (or ``"reference"``) whenever the tape interpreter built
    in C is here (it loads in a millisecond, and its steps run compiled while scipy's DOP853 loop runs in
    Python: 4–70× faster at equal rtol in the benchmark, and more accurate), otherwise when ``rtol ≤ 1e-11`` (and a C
    compiler or numba can run the tape), where its order grows with the accuracy at an unchanged step
    (measured in ``benchmarks/results/workprecision.md``). With ``varying_inputs`` (callable or sampled input
    values, evaluated in Python per step) never the Taylor method, whose tape holds only constants.
    """
    horizon = abs(float(t_span[1]) - float(t_span[0]))
    st = _stiffness(eqs, params, t_span, y0)
    if st is not None and st[0] * horizon > 1e3 and st[1] > 1e3:
        return "Radau", (f"stiff: fastest decay rate {st[0]:.3g}/time over a horizon of {horizon:g} "
                         f"(stiffness ratio {st[1]:.3g}); Radau with the generated Jacobian")
    if eqs.power_function != 0 or eqs.rayleigh != 0:
        return "LSODA", "dissipation present (P or rayleigh): possibly stiff later, LSODA switches to BDF if so"
    python_model = backend in ("python", "reference")
    taylor_wanted = python_model or (rtol is not None and rtol <= 1e-11)
    if not events and not varying_inputs and taylor_wanted and _taylor_ready(eqs):
        from .taylor import interpreter, taylor_order

        order = taylor_order(rtol if rtol is not None else 1e-9)
        if python_model and interpreter() == "c":
            return "taylor", (f"no dissipation, non-stiff, {backend} backend: the Taylor method (order {order}) "
                              "steps in the compiled tape interpreter, scipy's DOP853 in Python")
        if rtol is not None and rtol <= 1e-11:
            return "taylor", (f"no dissipation, non-stiff, rtol={rtol:g}: the Taylor method (order "
                              f"{order}) needs fewer operations than DOP853 here")
    return "DOP853", "no dissipation: non-stiff, DOP853 is the most efficient explicit method"


def _power_function(model: NumericModel):
    """``power(t, y_list, lam_list)``: dh/dt, the power of everything not in L (incl. moving constraints)."""
    eqs = model.equations
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    f = sp.lambdify((tt, ys, ps, list(eqs.multipliers)), eqs.jacobi_rate.xreplace(ren), modules="math", cse=True)
    p = list(model.params)
    if model.schedule is not None:  # the inputs' power at their values now
        return lambda t_, y, lam=(): f(t_, y, model.parameters_at(t_, y), list(lam) + [0.0] * (eqs.m - len(lam)))
    return lambda t_, y, lam=(): f(t_, y, p, list(lam) + [0.0] * (eqs.m - len(lam)))


def _state_text(model: NumericModel, y) -> str:
    return state_text(model.equations.coordinates, y)


def _collapse_error(model: NumericModel, res, t0: float, y0, log: StepLog | None = None) -> IntegrationError:
    """The step size collapsed: say when (the last accepted step, from ``log`` when given), where, and what
    usually causes it."""
    n2 = 2 * model.n
    last_t = float(res.t[-1]) if len(res.t) else t0
    last_y = res.y[:n2, -1] if res.y.size else y0
    if log is not None and log.last is not None:
        last_t, last_y = log.last[0], log.last[1][:n2]
    return IntegrationError(
        f"integration stopped at t={last_t:.9g} ({_state_text(model, last_y)}): {res.message} The step size "
        "collapsed near this state: a singularity of the model (a coordinate reaching a division by zero), "
        "a blow-up, stiffness (try method='LSODA' or 'Radau'), or Euler angles passing through gimbal lock "
        "(θ = 0 or π: use a Quaternion orientation). The trajectory up to this time is in the error's "
        "`partial` attribute; shorten t_span or use a terminal event to stop before it.",
        t=last_t,
        state=dict(zip(model.equations.coordinates, last_y)),
    )


def _state_function(model: NumericModel, *, with_work: bool):
    """``f(t, z)`` for scipy: ``[q̇, q̈]`` (+ the power dh/dt as the last entry when ``with_work``), with a
    non-finite check that reports the time and state."""
    eqs = model.equations
    n2 = 2 * eqs.n
    fun = model.fun
    power = _power_function(model) if with_work else None
    needs_lam = lam_required(eqs)
    dyn, pcall = model.dynamics, model._pcall

    def f(t_, z):
        try:
            return evaluate(t_, z)
        except SingularMassMatrixError as exc:  # mid-run: keep where it happened
            raise SingularMassMatrixError(str(exc), t=float(t_), state=dict(zip(eqs.coordinates, z))) from None
        except LagrangeError:
            raise
        except (ValueError, OverflowError, ZeroDivisionError) as exc:
            raise _model_fault(model, t_, z, exc) from None

    def evaluate(t_, z):
        if power is None:
            out = fun(t_, z)
        else:
            y = z[:n2]
            if needs_lam:
                try:
                    full = list(dyn(t_, y, pcall))
                except ZeroDivisionError:
                    raise model.singular_error(t_, y) from None
                out, lam = full[:n2], full[n2:]
            else:
                out, lam = list(fun(t_, y)), []
            out.append(power(t_, y.tolist(), lam))
        s = sum(out)
        if isinstance(s, complex):  # plain Python: a negative number to a fractional power is complex
            raise IntegrationError(
                f"complex derivative at t={t_:.9g} ({_state_text(model, z)}): the model left its domain (a "
                "negative number raised to a fractional power, e.g. the square root of a negative number): a "
                "coordinate passed a limit of the model, or a parameter is out of range",
                t=float(t_), state=dict(zip([*model.equations.coordinates], z)))
        if s != s or s in (math.inf, -math.inf):
            raise IntegrationError(
                f"non-finite derivative at t={t_:.9g} ({_state_text(model, z)}); likely causes: a "
                "singular configuration (division by zero in the model), a blow-up, or a parameter out "
                "of range",
                t=float(t_),
                state=dict(zip([*model.equations.coordinates], z)),
            )
        return out

    return f


_FAULT_CAUSES = (
    (ValueError, "the model left its domain (a square root or logarithm of a negative number, or asin/acos "
                 "beyond ±1): a coordinate passed a limit of the model, or a parameter is out of range"),
    (OverflowError, "a value overflowed: a blow-up (the motion escapes to infinity in finite time) or a step "
                    "too large for the model's growth"),
    (ZeroDivisionError, "a division by zero in the model: a singular configuration (a coordinate reaching a "
                        "singular value)"),
)


def _model_fault(model: NumericModel, t_: float, z, exc: Exception) -> IntegrationError:
    """An arithmetic error raised while evaluating the model, as an IntegrationError with time, state and
    the likely cause."""
    cause = next(text for kind, text in _FAULT_CAUSES if isinstance(exc, kind))
    return IntegrationError(
        f"evaluating the model failed at t={t_:.9g} ({_state_text(model, z)}): {type(exc).__name__}: {exc}. "
        f"Likely cause: {cause}.",
        t=float(t_), state=dict(zip(model.equations.coordinates, z)),
    )


def _with_partial(exc: LagrangeError, model: NumericModel, log: StepLog, conservative: bool, t0: float, y0,
                  method: str) -> LagrangeError:
    """``exc`` (an IntegrationError or a mid-run SingularMassMatrixError) again, carrying ``partial``: the
    trajectory up to the last accepted step, from ``log``; ``t``/``state`` default to where that ended."""
    n2 = 2 * model.n
    T, Z = log.arrays()
    partial = None
    if len(T):
        partial = Trajectory(t=T, y=Z[:, :n2].copy(), model=model, method=f"{method} (stopped early)",
                             success=False, message=str(exc), nfev=log.steps,
                             work=None if conservative else Z[:, n2].copy(), initial=(t0, np.array(y0).copy()))
    t_fault = exc.t if getattr(exc, "t", None) is not None else (float(T[-1]) if len(T) else t0)
    state = exc.state if getattr(exc, "state", None) is not None else (
        dict(zip(model.equations.coordinates, Z[-1, :n2])) if len(T) else None)
    note = (f" The trajectory up to t={T[-1]:.9g} ({len(T)} points) is in the error's `partial` attribute."
            if partial is not None and "`partial`" not in str(exc) else "")
    out = type(exc)(str(exc) + note, t=t_fault, state=state, partial=partial)
    out.__cause__ = exc.__cause__
    return out


def _jacobian(model: NumericModel, method: str, conservative: bool):
    """The generated Jacobian for implicit methods (unconstrained systems; scipy's finite differences
    otherwise)."""
    if method not in IMPLICIT_METHODS or model.m or model.schedule is not None:
        return None  # (a feedback input's ∂u/∂y is not in the generated Jacobian: scipy's differences)
    jy = jacobian_function(model)
    if conservative:
        return jy
    n2 = 2 * model.n

    def jac(t_, z):  # the work integral does not feed back
        J = np.zeros((n2 + 1, n2 + 1))
        J[:n2, :n2] = jy(t_, z[:n2])
        return J

    return jac


def _contact_events(model: NumericModel) -> list:
    """Terminal events at the sign change of the multiplier of each unilateral constraint."""
    out = []
    for k, uni in enumerate(model.equations.unilateral):
        if not uni:
            continue

        def ev(t_, z, k=k):
            return float(model.multipliers(t_, z[: 2 * model.n])[k])

        ev.terminal = True
        ev.direction = -1
        ev.contact = model.equations.constraint_names[k]
        out.append(ev)
    return out


def _contact_message(model: NumericModel, res) -> str:
    names = [n for n, u in zip(model.equations.constraint_names, model.equations.unilateral) if u]
    if not names or res.t_events is None:
        return ""
    fired = [(names[i], tev[0]) for i, tev in enumerate(list(res.t_events)[-len(names):]) if len(tev)]
    return "".join(f" Contact lost: the force of {nm} reached zero at t={te:.9g}; switch models there."
                   for nm, te in fired)


class GimbalLockWarning(UserWarning):
    """Euler angles near θ = 0 or π: the mass matrix is nearly singular (gimbal lock)."""


def _gimbal_hint(system) -> str:
    """The gimbal-lock hint when a body of ``system`` has Euler angles, else ""; remembered per bodies tuple."""
    seen = getattr(system, "__dict__", {}).get("_gimbal_hint")
    if seen is not None and seen[0] is system.bodies:
        return seen[1]
    hint = _euler_hint(system.bodies)
    if hasattr(system, "__dict__"):
        system.__dict__["_gimbal_hint"] = (system.bodies, hint)
    return hint


def _euler_hint(bodies) -> str:
    from ..model.rotations import EulerAngles

    if any(isinstance(getattr(b, "orientation", None), EulerAngles) for b in bodies):
        return (" Gimbal lock: Wells' Euler angles are singular at θ = 0 or π (only ψ + φ is defined there). "
                "Use RigidBody(..., orientation=Quaternion(q0, q1, q2, q3)) — it is regular everywhere (a "
                "sleeping top) — or tilt the reference axes.")
    return ""


def _check_initial_mass_matrix(system, model: NumericModel, t0: float, y0) -> None:
    """Raise on a singular mass matrix (naming coordinates, with a gimbal-lock hint for Euler angles) and
    warn when it is nearly singular."""
    hint = _gimbal_hint(system)
    try:
        model.fun(t0, y0)
    except SingularMassMatrixError as exc:
        raise SingularMassMatrixError(str(exc).rstrip(".") + "." + hint) from None
    if hint and not model.m:
        w, _, info = dsyev(model.mass_matrix(t0, y0), compute_v=0)  # M is symmetric: LAPACK's eigenvalues
        w = [abs(x) for x in w.tolist()]
        cond = max(w) / min(w) if info == 0 and min(w) > 0 else math.inf  # its 2-norm condition number
        if cond > 1e8:
            import warnings

            warnings.warn(f"the mass matrix is nearly singular at the initial state (condition number "
                          f"{cond:.2g}).{hint}", GimbalLockWarning, stacklevel=3)


def _model_for(eqs, params, model: NumericModel | None, backend: str, crhs=None, *, inputs: dict | None = None,
               schedule=None) -> NumericModel:
    """``model`` when it was built for ``eqs`` (and no Baumgarte ``crhs`` is asked for), else ``eqs`` compiled
    with ``params`` and ``backend`` — or with the given model's parameter values and backend; then the input
    constants ``inputs`` ({name: value}) bound and the ``schedule`` of the time-varying ones attached."""
    if model is not None and model.equations is eqs and crhs is None:
        out = model.with_params(inputs) if inputs else model
    else:
        p = params if model is None else {**dict(zip(eqs.numeric_parameters, model.params)), **(inputs or {})}
        out = compile_equations(eqs, p, backend=backend if model is None else model.backend, constraint_rhs=crhs)
    return out if out.schedule is schedule else out.with_schedule(schedule)


def _refuse_route(route: str, schedule) -> None:
    """InputError when ``route`` cannot evaluate the time-varying inputs of ``schedule``."""
    if schedule is not None:
        raise InputError(f"{route} cannot run time-varying inputs ({schedule.describe()}): it does not call Python "
                         f"per step, so it supports constant inputs only. Time-varying inputs run with "
                         f"{VARYING_ROUTES}")


def _split_inputs(eqs, params: Mapping, inputs, t_span, y0) -> tuple[dict, dict, object]:
    """``(params with the inputs' constants, those constants, the schedule of the varying ones)``; refuses an
    input given among the parameters."""
    names = {u.name for u in eqs.inputs}
    given = [k.name if isinstance(k, sp.Symbol) else str(k) for k in params]
    wrong = [k for k in given if k in names]
    if wrong:
        raise ParameterError(f"{', '.join(wrong)} {'is an input' if len(wrong) == 1 else 'are inputs'}, not "
                             f"parameter(s): give the value(s) as simulate(..., inputs={{'{wrong[0]}': ...}})")
    if not eqs.inputs and not inputs:
        return dict(params), {}, None
    constants, schedule = resolve_inputs(eqs, inputs, t_span, y0)
    return {**params, **constants}, constants, schedule


def _simulate_taylor(system, eqs, t_span, initial, params, *, model, backend, t_eval, n_points, rtol, atol,
                     max_step, events, switches, why, constants=None, schedule=None) -> Trajectory:
    """``method="taylor"`` (:mod:`lagrange.integrate.taylor`): checks, model, initial state, run."""
    from .taylor import integrate_taylor, interpreter

    if events:
        raise TypeError("method='taylor' does not locate events: use method='DOP853' (or another scipy method)")
    if switches:
        raise TypeError("method='taylor' needs analytic equations, and this system has dry-friction sign() "
                        "switches: use method='DOP853' (events) or friction='regularize' with an RK method")
    _refuse_route("method='taylor' (its tape holds constants only)", schedule)
    model = _model_for(eqs, params, model, backend, inputs=constants)
    y0 = initial_state(eqs.coordinates, initial)
    _check_initial_mass_matrix(system, model, t_span[0], y0)
    t_eval = np.linspace(t_span[0], t_span[1], n_points) if t_eval is None else t_eval
    how = "compiled series" if model.backend == "numba" else f"interpreted tape, {interpreter()}"
    label = f"taylor ({how}" + (f"; auto: {why})" if why else ")")
    try:
        return integrate_taylor(model, t_span, y0, t_eval, rtol=rtol, atol=atol, max_step=max_step, label=label)
    except ValueError as exc:
        raise IntegrationError(f"integration failed: {exc}") from exc


def simulate(
    system,
    t_span,
    initial: Mapping,
    params: Mapping,
    *,
    method: str = "DOP853",
    rtol: float = 1e-9,
    atol: float = 1e-11,
    t_eval=None,
    n_points: int = 1001,
    events=None,
    max_step: float = np.inf,
    backend: str = "python",
    model: NumericModel | None = None,
    inputs: Mapping | None = None,
    friction: str = "events",
    friction_epsilon: float = 1e-6,
    stabilization: str = "projection",
    baumgarte: tuple = (10.0, 10.0),
    project_initial: bool = True,
    step: float | None = None,
    loop: str = "auto",
) -> Trajectory:
    """Integrate Lagrange's equations of ``system``.

    Parameters
    ----------
    t_span : (t0, t1) or a number t1 (then t0 = 0)
    initial : dict keyed by coordinates, their velocities (``q.diff(t)``) or names (``"q"``, ``"q_dot"``)
    params : dict of parameter values keyed by symbol or name
    inputs : dict ``{input or name: value}``, one value for each input of the system
        (:mod:`lagrange.model.inputs`): a number, a function ``u(t)``, a feedback law ``u(t, y)`` of the state
        ``y = [q, q̇]``, samples ``(t_samples, values)`` (interpolated linearly) or an expression of ``t``; see
        :mod:`lagrange.codegen.input_values`. Constants run on every route; time-varying values need a route
        that calls Python per step (the scipy methods: ``method="auto"`` picks one and ``loop="auto"`` the
        scipy loop); the compiled loops and ``method="taylor"`` refuse them, the geometric methods refuse
        inputs (an input does work: not a conservative system). The trajectory gives the values (``sol[u]``)
        and its power balance includes the inputs' power.
    method : one of ``DOP853`` (default), ``RK45``, ``RK23``, ``LSODA``, ``Radau``, ``BDF`` or ``auto``
        (the implicit ones get the generated Jacobian), ``taylor`` (adaptive Taylor series of order
        ``ceil(−ln(rtol)/2 + 1)`` for unconstrained analytic systems: nothing compiled per model with the
        python backend (the tape interpreted in C, or by numba without a C compiler), a compiled series
        with numba; see :mod:`lagrange.integrate.taylor`),
        or a fixed-step geometric integrator for conservative unconstrained systems — ``midpoint``, ``gl4``,
        ``gl6`` (Gauss–Legendre, symplectic),
        ``verlet`` (Störmer–Verlet, needs a constant mass matrix and V(q)) or ``dg`` (discrete gradient,
        energy conserved to the Newton tolerance) — with ``step=h``; see :mod:`lagrange.integrate.fixed`.
    rtol, atol : tolerances passed to scipy
    t_eval : output times; default ``n_points`` equally spaced times (fixed-step methods record about
        ``n_points`` states instead)
    max_step : largest step of the adaptive scipy methods
    step : the step of the fixed-step geometric methods
    events : scipy-style event callables ``event(t, y)`` (``terminal``/``direction`` attributes honoured)
    backend : ``python`` (default), ``numba``, ``reference`` or ``auto``; see :mod:`lagrange.codegen.numeric`
    model : a NumericModel from :meth:`System.compile` to reuse (skips code generation)
    friction : ``"events"`` (default) or ``"regularize"``; see :mod:`lagrange.integrate.switching`
    friction_epsilon : velocity scale of the regularization
    stabilization : ``"projection"`` (default), ``"baumgarte"`` or ``"none"`` — constraint drift control,
        see :mod:`lagrange.integrate.constrained`
    baumgarte : (α, β) in 1/time for Baumgarte stabilization
    project_initial : project an inconsistent initial state onto the constraints (default) or raise
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

    Raises
    ------
    InitialConditionError, ParameterError
        Missing or bad initial values, parameters or input values (all listed).
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
        Ctrl-C (SIGINT) during a scipy, compiled RK or geometric run (the Taylor loops: see
        :mod:`lagrange.integrate.taylor`): raised within about a second (the compiled loops run in chunks of
        bounded work), a :class:`KeyboardInterrupt` (not a LagrangeError) carrying the same ``t``, ``state``
        and ``partial`` (the trajectory up to the interrupt, ``success=False``).
    """
    from .switching import run_switched, switching_functions

    if not isinstance(t_span, tuple | list) and np.ndim(t_span) == 0:
        t_span = (0.0, float(t_span))
    t0, t1 = float(t_span[0]), float(t_span[1])
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 == t0:
        raise IntegrationError(f"t_span must be two different finite times, got {t_span}")
    if friction not in ("events", "regularize"):
        raise TypeError(f"friction must be 'events' or 'regularize', got {friction!r}")
    if stabilization not in STABILIZATIONS:
        raise TypeError(f"stabilization must be one of {', '.join(STABILIZATIONS)}, got {stabilization!r}")
    if hasattr(system, "bindable"):  # values of declared parameters that cancel out: ignored, with a warning
        params = system.bindable(params)
    eqs = system.derived
    switches = switching_functions(eqs)
    if switches and friction == "regularize":
        from .switching import regularized_equations

        eqs = regularized_equations(eqs, friction_epsilon)
        switches = []
    if eqs.planar_friction:  # friction over a surface: exact |v| (floored) or regularized sqrt(|v|² + ε²)
        from ..codegen.rough_friction import planar_friction_for

        eqs = planar_friction_for(eqs, friction, friction_epsilon)
    if switches and eqs.m:
        raise TypeError("sign() switches (dry friction) with constraints: use friction='regularize'")
    params, constants, schedule = _split_inputs(eqs, params, inputs, (t0, t1), initial_state(eqs.coordinates,
                                                                                              initial))
    why = ""
    if method == "auto":
        method, why = choose_method(eqs, params, (t0, t1), initial_state(eqs.coordinates, initial), rtol=rtol,
                                    backend=backend if model is None else model.backend, events=bool(events),
                                    varying_inputs=schedule is not None)
    from .fixed import GEOMETRIC, fixed_loop, integrate_fixed

    if method in GEOMETRIC:
        if eqs.inputs:
            raise InputError(f"method={method!r} (a geometric integrator) cannot run inputs "
                             f"({', '.join(u.name for u in eqs.inputs)}): an input does work on the system, which "
                             "then has no Hamiltonian structure to preserve; use a scipy method (DOP853, ...) or "
                             "'auto'")
        if t_eval is not None or events:
            raise TypeError(f"{method} is a fixed-step integrator: it takes step= and n_points=, not t_eval/events")
        compiled = fixed_loop(loop, backend=backend, model=model)
        y0 = initial_state(eqs.coordinates, initial)
        return integrate_fixed(system, (t0, t1), y0, params, method=method, step=step, n_points=n_points,
                               model=model, compiled=compiled)
    if method == "taylor":
        return _simulate_taylor(system, eqs, (t0, t1), initial, params, model=model, backend=backend, t_eval=t_eval,
                                n_points=n_points, rtol=rtol, atol=atol, max_step=max_step, events=events,
                                switches=switches, why=why, constants=constants, schedule=schedule)
    if method not in SCIPY_METHODS:
        raise TypeError(f"unknown method {method!r}; choose one of {', '.join(SCIPY_METHODS)}, 'taylor', "
                        f"{', '.join(GEOMETRIC)} (fixed step) or 'auto'")
    notes = [f"auto: {why}"] if why else []
    if eqs.m and stabilization == "projection" and method not in STEPPABLE:
        stabilization = "baumgarte"
        notes.append(f"{method} keeps a step history, so constraint drift is controlled by Baumgarte "
                     "stabilization instead of projection")
    from .compiled import choose_loop, integrate_compiled

    if loop == "compiled":
        _refuse_route("loop='compiled' (the compiled numba RK loops)", schedule)
    use_compiled, loop_note = choose_loop(loop, backend=backend, model=model, eqs=eqs, method=method,
                                          events=events, switches=switches, varying_inputs=schedule is not None)
    if use_compiled and model is None:
        backend = "numba"
    notes += [loop_note] if loop_note else []
    crhs = baumgarte_rhs(eqs, *baumgarte) if eqs.m and stabilization == "baumgarte" else None
    model = _model_for(eqs, params, model, backend, crhs, inputs=constants, schedule=schedule)
    y0 = initial_state(eqs.coordinates, initial)
    initial_report = {}
    if eqs.m:
        y0, initial_report = consistent_initial(model, t0, y0, project_initial)
    if t_eval is None:
        t_eval = np.linspace(t0, t1, n_points)
    t_eval = np.asarray(t_eval, dtype=float)
    if not switches:
        _check_initial_mass_matrix(system, model, t0, y0)
    conservative = eqs.is_conservative
    n2 = 2 * eqs.n
    f = _state_function(model, with_work=not conservative)
    z0 = y0 if conservative else np.append(y0, 0.0)
    jac = _jacobian(model, method, conservative)
    all_events = list(events or []) + _contact_events(model)
    if use_compiled:  # its IntegrationError already carries `partial` (lagrange.integrate.compiled)
        try:
            return integrate_compiled(model, method, (t0, t1), y0, t_eval, rtol=rtol, atol=atol, max_step=max_step,
                                      label=f"{method} ({'; '.join(notes)})")
        except ValueError as exc:  # bad t_eval or tolerances, worded as scipy words them
            raise IntegrationError(f"integration failed: {exc}") from exc
    log = StepLog(t_eval)
    kwargs = dict(method=recording(method, log), rtol=rtol, atol=atol, max_step=max_step)
    if jac is not None:
        kwargs["jac"] = jac
    try:
        if switches:
            res = run_switched(model, switches, (t0, t1), z0, t_eval, all_events, kwargs, not conservative)
        elif eqs.is_rough:
            proj = Projector(model.constraint_functions, eqs.n) if stabilization == "projection" else None
            res = run_rough(model, lambda mm: _state_function(mm, with_work=not conservative), (t0, t1), z0,
                            t_eval, all_events, kwargs, proj)
        elif eqs.m and stabilization == "projection":
            proj = Projector(model.constraint_functions, eqs.n)
            res = step_loop(f, (t0, t1), z0, t_eval=t_eval, events=all_events, post_step=proj, **kwargs)
        else:
            res = solve_ivp(f, (t0, t1), z0, t_eval=t_eval, events=all_events or None, **kwargs)
    except (IntegrationError, SingularMassMatrixError) as exc:  # a numerical fault mid-run: keep the results
        raise _with_partial(exc, model, log, conservative, t0, y0, method) from None
    except (KeyboardInterrupt, SystemError) as exc:  # Ctrl-C: IntegrationInterrupted with the partial result
        if interrupt_of(exc) is None:
            raise
        raise interrupted_run(model, log, conservative, t0, y0, method) from None
    except LagrangeError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError, np.linalg.LinAlgError) as exc:
        t_last, z_last = log.last if log.last is not None else (t0, z0)
        cause = next((f" Likely cause: {text}." for kind, text in _FAULT_CAUSES if isinstance(exc, kind)), "")
        fault = IntegrationError(f"integration failed after t={t_last:.9g} ({_state_text(model, z_last)}): "
                                 f"{type(exc).__name__}: {exc}.{cause}")
        fault.__cause__ = exc
        raise _with_partial(fault, model, log, conservative, t0, y0, method) from exc
    if res.status == -1:
        raise _with_partial(_collapse_error(model, res, t0, y0, log), model, log, conservative, t0, y0, method)
    Y = res.y.T
    if eqs.m:
        notes.append(f"constraints: {stabilization}")
    label = method + (f" ({'; '.join(notes)})" if notes else "")
    return Trajectory(
        t=res.t,
        y=Y[:, :n2].copy(),
        model=model,
        method=label,
        success=bool(res.success),
        message=str(res.message) + _contact_message(model, res),
        nfev=int(res.nfev),
        work=None if conservative else Y[:, n2].copy(),
        initial=(t0, y0.copy()),
        initial_constraint_violation=initial_report,
        point_params=getattr(res, "point_params", None),
        switches=(res.switched_model, res.sigma, res.transitions) if switches else (),
        t_events=list(res.t_events) if res.t_events is not None else [],
        y_events=[np.asarray(v)[:, :n2] if len(v) else np.empty((0, n2)) for v in res.y_events]
        if res.y_events is not None
        else [],
    )
