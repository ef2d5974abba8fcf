"""scipy's ``solve_ivp`` methods (DOP853, RK45, RK23, LSODA, Radau, BDF) and the compiled DOP853/RK45 loops.

:func:`run` is the run function of their registry entries (:mod:`lagrange.integrate.registry`): it picks the
loop (scipy's, or the compiled numba loop of :mod:`lagrange.integrate.compiled`), the constraint treatment
(projection after each step, or Baumgarte), the friction driver (:mod:`lagrange.integrate.switching`) or the
rough-constraint driver (:mod:`lagrange.integrate.rough`), and builds the Trajectory. The implicit methods get
the generated Jacobian of the model (:attr:`~lagrange.codegen.numeric.NumericModel.jacobian`), never finite
differences (except for feedback inputs, whose ∂u/∂y is not generated).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.integrate import solve_ivp

from ..codegen.numeric import NumericModel
from ..errors import IntegrationError, LagrangeError, SingularMassMatrixError
from ..results.trajectory import Trajectory
from .constrained import Projector, consistent_initial
from .faults import FAULT_CAUSES, collapse_error, model_fault, state_text_of, with_partial
from .prepare import check_initial_mass_matrix, given_entries, model_for, refuse_route
from .request import RunRequest
from .stepper import STEPPABLE, StepLog, interrupt_of, interrupted_run, recording, step_loop

__all__ = ["SCIPY_METHODS", "IMPLICIT_METHODS", "run", "state_function"]

SCIPY_METHODS = ("DOP853", "RK45", "RK23", "LSODA", "Radau", "BDF")
IMPLICIT_METHODS = ("Radau", "BDF", "LSODA")


def __getattr__(name: str):
    if name == "jacobian_function":  # moved to code generation (lagrange/integrate/__init__.py states the rule)
        warnings.warn("lagrange.integrate.scipy_ivp.jacobian_function moved: use model.jacobian (the compiled "
                      "model's generated Jacobian) or lagrange.codegen.run_functions.jacobian_function",
                      DeprecationWarning, stacklevel=2)
        return lambda model: model.jacobian
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def state_function(model: NumericModel, *, with_work: bool, log: StepLog | None = None):
    """``f(t, z)`` for scipy: ``[q̇, q̈]`` (+ the power dh/dt as the last entry when ``with_work``), with a
    non-finite check that reports the time and state.

    With a ``log``, a failed solve of the model (a pivot of the generated LDLᵀ lost) is a rejected trial step,
    not the end of the run: ``f`` notes the state in ``log`` (:meth:`StepLog.fault`) and returns NaN, so the
    step's error estimate is NaN and scipy's controller rejects the step and shrinks it (RK23/RK45/DOP853
    shrink by their minimum factor; Radau's and BDF's Newton iterations fail to converge, which shrinks the
    step too); a NaN state (a later stage of such a step) gives NaN again. Whether the configuration itself is
    singular is decided where the run stops (:func:`_trial_fault_error`)."""
    eqs = model.equations
    n2 = 2 * eqs.n
    fun = model.fun
    power = model.power if with_work else None
    needs_lam = model.lam_required
    dyn, pcall = model.dynamics, model._pcall

    def f(t_, z):
        try:
            return evaluate(t_, z)
        except SingularMassMatrixError as exc:  # mid-run: keep where it happened
            if log is not None:
                log.fault(t_, z)
                return [math.nan] * len(z)
            raise SingularMassMatrixError(str(exc), t=float(t_), state=dict(zip(eqs.coordinates, z))) from None
        except LagrangeError:
            raise
        except (ValueError, OverflowError, ZeroDivisionError) as exc:
            raise model_fault(model, t_, z, exc) from None

    def rejected(t_, z):
        # the later stages of a step already rejected by a failed solve: the model is not evaluated at NaN
        return log is not None and log.trial_fault is not None and not np.isfinite(z).all()

    def evaluate(t_, z):
        if rejected(t_, z):
            return [math.nan] * len(z)
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
                f"complex derivative at t={t_:.9g} ({state_text_of(model, z)}): the model left its domain (a "
                "negative number raised to a fractional power, e.g. the square root of a negative number): a "
                "coordinate passed a limit of the model, or a parameter is out of range",
                t=float(t_), state=dict(zip([*model.equations.coordinates], z)))
        if s != s or s in (math.inf, -math.inf):
            raise IntegrationError(
                f"non-finite derivative at t={t_:.9g} ({state_text_of(model, z)}); likely causes: a "
                "singular configuration (division by zero in the model), a blow-up, or a parameter out "
                "of range",
                t=float(t_),
                state=dict(zip([*model.equations.coordinates], z)),
            )
        return out

    return f


def _trial_fault_error(model: NumericModel, log: StepLog) -> LagrangeError | None:
    """The error of a run whose step size collapsed while trial stages kept failing the model's solve (the
    last such stage after the last accepted step is within the collapsed step of it): SingularMassMatrixError
    when the configuration there is singular (dependent constraints, or a mass matrix singular on the
    motions the constraints allow — computed, :meth:`NumericModel.singularity`), else an IntegrationError
    naming the ill-conditioned solve at a regular configuration. None when the collapse had another cause."""
    if log.trial_fault is None:
        return None
    t_f, z_f = log.trial_fault
    y_f = z_f[: 2 * model.n]
    state = dict(zip(model.equations.coordinates, y_f))
    kind, text = model.singularity(t_f, y_f)
    t_a = log.last[0] if log.last is not None else t_f
    tail = (f" The step size collapsed approaching this state from the last accepted one (t={t_a:.9g}): every "
            "smaller trial step failed there too.")
    if kind == "ill-conditioned":
        return IntegrationError(f"integration stopped at t={t_a:.9g}: the model's linear solve failed in every "
                                f"trial step: {text}.{tail}", t=t_f, state=state)
    return SingularMassMatrixError(text + "." + tail, t=t_f, state=state)


def _jacobian(model: NumericModel, method: str, conservative: bool):
    """The generated Jacobian for implicit methods (unconstrained systems; scipy's finite differences
    otherwise, and for structural equations, whose generated Jacobian would need their expanded M and f)."""
    if method not in IMPLICIT_METHODS or model.m or model.schedule is not None or model.equations.is_structural:
        return None  # (a feedback input's ∂u/∂y is not in the generated Jacobian: scipy's differences)
    jy = model.jacobian
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


def run(req: RunRequest) -> Trajectory:
    """Run a scipy method (or the compiled loop) for the validated request ``req``."""
    from .compiled import choose_loop, integrate_compiled

    eqs, method, (t0, t1) = req.equations, req.method, req.t_span
    stabilization = req.stabilization.method
    notes = [f"auto: {req.why}"] if req.why else []
    if eqs.m and stabilization == "projection" and method not in STEPPABLE:
        stabilization = "baumgarte"
        notes.append(f"{method} keeps a step history, so constraint drift is controlled by Baumgarte "
                     "stabilization instead of projection")
    if req.loop == "compiled":
        refuse_route("loop='compiled' (the compiled numba RK loops)", req.schedule)
    use_compiled, loop_note = choose_loop(req.loop, backend=req.backend, model=req.model, eqs=eqs, method=method,
                                          events=req.events, switches=req.switches,
                                          varying_inputs=req.schedule is not None)
    backend = "numba" if use_compiled and req.model is None else req.backend
    notes += [loop_note] if loop_note else []
    gains = (req.stabilization.alpha, req.stabilization.beta) if eqs.m and stabilization == "baumgarte" else None
    model = model_for(eqs, req.params, req.model, backend, gains, inputs=req.constants, schedule=req.schedule,
                      bound=req.model_bound)
    y0 = req.y0
    initial_report, adjustments = {}, {}
    if eqs.m:
        y0, initial_report, adjustments = consistent_initial(model, t0, y0, req.stabilization.project_initial,
                                                             given_entries(eqs.coordinates, req.initial))
    t_eval = np.linspace(t0, t1, req.n_points) if req.t_eval is None else req.t_eval
    if not req.switches:
        check_initial_mass_matrix(req.system, model, t0, y0)
    if use_compiled:  # its IntegrationError already carries `partial` (lagrange.integrate.compiled)
        try:
            return integrate_compiled(model, method, (t0, t1), y0, t_eval, rtol=req.rtol, atol=req.atol,
                                      max_step=req.max_step, label=f"{method} ({'; '.join(notes)})",
                                      max_steps=req.max_steps)
        except ValueError as exc:  # bad t_eval or tolerances, worded as scipy words them
            raise IntegrationError(f"integration failed: {exc}") from exc
    return _run_scipy(req, model, y0, t_eval, stabilization, notes, (initial_report, adjustments))


def _run_scipy(req: RunRequest, model: NumericModel, y0, t_eval, stabilization: str, notes: list,
               initial_report: tuple) -> Trajectory:
    """scipy's loop: plain, projected, friction-switched or rough."""
    from .rough import run_rough
    from .switching import run_switched

    eqs, method, (t0, t1) = req.equations, req.method, req.t_span
    conservative = eqs.is_conservative
    n2 = 2 * eqs.n
    log = StepLog(t_eval, max_steps=req.max_steps)
    f = state_function(model, with_work=not conservative, log=log)
    z0 = y0 if conservative else np.append(y0, 0.0)
    jac = _jacobian(model, method, conservative)
    all_events = list(req.events) + _contact_events(model)
    kwargs = dict(method=recording(method, log), rtol=req.rtol, atol=req.atol, max_step=req.max_step)
    if jac is not None:
        kwargs["jac"] = jac
    try:
        if req.switches:
            res = run_switched(model, req.switches, (t0, t1), z0, t_eval, all_events, kwargs, not conservative)
        elif eqs.is_rough:
            proj = Projector(model.constraint_functions, eqs.n) if stabilization == "projection" else None
            res = run_rough(model, lambda mm: state_function(mm, with_work=not conservative), (t0, t1), z0,
                            t_eval, all_events, kwargs, proj)
        elif eqs.m and stabilization == "projection":
            proj = Projector(model.constraint_functions, eqs.n)
            res = step_loop(f, (t0, t1), z0, t_eval=t_eval, events=all_events, post_step=proj, **kwargs)
        else:
            res = solve_ivp(f, (t0, t1), z0, t_eval=t_eval, events=all_events or None, **kwargs)
    except (IntegrationError, SingularMassMatrixError) as exc:  # a numerical fault mid-run: keep the results
        raise with_partial(exc, model, log, conservative, t0, y0, method) from None
    except (KeyboardInterrupt, SystemError) as exc:  # Ctrl-C: IntegrationInterrupted with the partial result
        if interrupt_of(exc) is None:
            raise
        raise interrupted_run(model, log, conservative, t0, y0, method) from None
    except LagrangeError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError, np.linalg.LinAlgError) as exc:
        t_last, z_last = log.last if log.last is not None else (t0, z0)
        cause = next((f" Likely cause: {text}." for kind, text in FAULT_CAUSES if isinstance(exc, kind)), "")
        fault = IntegrationError(f"integration failed after t={t_last:.9g} ({state_text_of(model, z_last)}): "
                                 f"{type(exc).__name__}: {exc}.{cause}")
        fault.__cause__ = exc
        raise with_partial(fault, model, log, conservative, t0, y0, method) from exc
    if res.status == -1:
        fault = _trial_fault_error(model, log) or collapse_error(model, res, t0, y0, log)
        raise with_partial(fault, model, log, conservative, t0, y0, method)
    if not np.isfinite(res.y).all():  # never NaN from a rejected trial stage in the output
        raise with_partial(IntegrationError("the run produced non-finite output values after failed solves of the "
                                            "model; " + collapse_error(model, res, t0, y0, log).args[0]),
                           model, log, conservative, t0, y0, method)
    if log.trial_faults:
        notes.append(f"{log.trial_faults} trial stage(s) at an ill-conditioned or singular solve: steps rejected "
                     "and shrunk")
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
        initial_constraint_violation=initial_report[0],
        initial_adjustments=initial_report[1],
        point_params=getattr(res, "point_params", None),
        switches=(res.switched_model, res.sigma, res.transitions) if req.switches else (),
        t_events=list(res.t_events) if res.t_events is not None else [],
        y_events=[np.asarray(v)[:, :n2] if len(v) else np.empty((0, n2)) for v in res.y_events]
        if res.y_events is not None
        else [],
    )
