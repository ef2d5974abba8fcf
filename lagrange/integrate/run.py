"""The simulation driver: validate inputs, compile, integrate with scipy, return a Trajectory.

Discontinuous forces (Coulomb friction ``sign(v)``) are handled by
:mod:`lagrange.integrate.switching` (events at each sign change plus Filippov sliding for sticking);
see its docstring for the documented treatment.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..codegen.cse import rename_map
from ..codegen.numeric import NumericModel, compile_equations
from ..conventions import VELOCITY_SUFFIX, t
from ..errors import InitialConditionError, IntegrationError, LagrangeError, SingularMassMatrixError
from ..model.coordinates import coordinate_name, is_coordinate
from ..results.trajectory import Trajectory
from .scipy_ivp import IMPLICIT_METHODS, SCIPY_METHODS, jacobian_function

__all__ = ["simulate", "initial_state", "choose_method"]


def initial_state(coords: Sequence, initial: Mapping) -> np.ndarray:
    """``y0 = [q, q̇]`` from a dict keyed by coordinates, their derivatives or names (``"x_dot"``).

    Raises :class:`InitialConditionError` naming every missing, unknown or non-finite entry.
    """
    n = len(coords)
    names = [coordinate_name(c) for c in coords]
    slots: dict[int, float] = {}
    problems = []
    for key, value in initial.items():
        idx = None
        if isinstance(key, str):
            if key in names:
                idx = names.index(key)
            elif key.endswith(VELOCITY_SUFFIX) and key[: -len(VELOCITY_SUFFIX)] in names:
                idx = n + names.index(key[: -len(VELOCITY_SUFFIX)])
        elif is_coordinate(key) and key in coords:
            idx = coords.index(key)
        elif isinstance(key, sp.Derivative) and key.expr in coords and key.derivative_count == 1:
            idx = n + coords.index(key.expr)
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
        slots[idx] = v
    missing = [names[i] if i < n else names[i - n] + VELOCITY_SUFFIX for i in range(2 * n) if i not in slots]
    if missing:
        problems.append(f"missing initial value(s) for {', '.join(missing)}")
    if problems:
        raise InitialConditionError("; ".join(problems))
    return np.array([slots[i] for i in range(2 * n)], dtype=float)


def choose_method(model: NumericModel) -> tuple[str, str]:
    """A sensible scipy method and the reason (``method="auto"``).

    Dissipative systems (P or D present) may be stiff: LSODA switches automatically between Adams
    and BDF. Conservative or forced systems: DOP853, the most efficient at tight tolerances.
    """
    eqs = model.equations
    if eqs.power_function != 0 or eqs.rayleigh != 0:
        return "LSODA", "dissipation present (P or rayleigh): possibly stiff, LSODA switches to BDF if so"
    return "DOP853", "no dissipation: non-stiff, DOP853 is the most efficient explicit method"


def _power_function(model: NumericModel):
    eqs = model.equations
    ren = rename_map(eqs)
    ys = sp.symbols(f"y0:{2 * eqs.n}", real=True)
    ps = [ren[s] for s in eqs.parameters]
    f = sp.lambdify((ren[t], ys, ps), eqs.jacobi_rate.xreplace(ren), modules="math", cse=True)
    p = list(model.params)
    return lambda t_, y: f(t_, y, p)


def _state_text(model: NumericModel, y) -> str:
    names = [coordinate_name(c) for c in model.equations.coordinates]
    n = len(names)
    parts = [f"{names[i]}={y[i]:.6g}" for i in range(n)]
    parts += [f"{names[i]}{VELOCITY_SUFFIX}={y[n + i]:.6g}" for i in range(n)]
    return ", ".join(parts)


def _collapse_error(model: NumericModel, res, t0: float, y0) -> IntegrationError:
    """The step size collapsed: say when, where, and what usually causes it."""
    n2 = 2 * model.n
    last_t = float(res.t[-1]) if len(res.t) else t0
    last_y = res.y[:n2, -1] if res.y.size else y0
    return IntegrationError(
        f"integration stopped at t={last_t:.9g} ({_state_text(model, last_y)}): {res.message} The step size "
        "collapsed near this state: a singularity of the model (a coordinate reaching a division by zero), "
        "a blow-up, or stiffness (try method='LSODA' or 'Radau'). Results up to this time are lost; shorten "
        "t_span or use a terminal event to stop before it.",
        t=last_t,
        state=dict(zip(model.equations.coordinates, last_y)),
    )


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
    friction: str = "events",
    friction_epsilon: float = 1e-6,
) -> Trajectory:
    """Integrate Lagrange's equations of ``system``.

    Parameters
    ----------
    t_span : (t0, t1) or a number t1 (then t0 = 0)
    initial : dict keyed by coordinates, their velocities (``q.diff(t)``) or names (``"q"``, ``"q_dot"``)
    params : dict of parameter values keyed by symbol or name
    method : one of ``DOP853`` (default), ``RK45``, ``RK23``, ``LSODA``, ``Radau``, ``BDF`` or ``auto``
        The implicit methods get the generated Jacobian.
    rtol, atol : tolerances passed to scipy
    t_eval : output times; default ``n_points`` equally spaced times
    events : scipy-style event callables ``event(t, y)`` (``terminal``/``direction`` attributes honoured)
    backend : ``python`` (default), ``numba``, ``reference`` or ``auto``; see :mod:`lagrange.codegen.numeric`
    model : a NumericModel from :meth:`System.compile` to reuse (skips code generation)
    friction : ``"events"`` (default) or ``"regularize"``; see :mod:`lagrange.integrate.switching`
    friction_epsilon : velocity scale of the regularization

    Returns
    -------
    Trajectory

    Raises
    ------
    InitialConditionError, ParameterError
        Missing or bad inputs (all listed).
    SingularMassMatrixError
        The mass matrix is singular at the initial state (the coordinates involved are named).
    IntegrationError
        A non-finite value appeared (time and state reported) or scipy failed.
    """
    from .switching import run_switched, switching_functions

    if np.ndim(t_span) == 0:
        t_span = (0.0, float(t_span))
    t0, t1 = float(t_span[0]), float(t_span[1])
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 == t0:
        raise IntegrationError(f"t_span must be two different finite times, got {t_span}")
    options = {"events", "regularize"}
    if friction not in options:
        raise TypeError(f"friction must be one of {sorted(options)}, got {friction!r}")
    eqs = system.derived
    switches = switching_functions(eqs)
    if switches and friction == "regularize":
        from .switching import regularized_equations

        eqs = regularized_equations(eqs, friction_epsilon)
        switches = []
    if model is None:
        from ..codegen.numeric import compile_equations as _compile

        model = _compile(eqs, params, backend=backend)
    elif model.equations is not eqs:
        model = compile_equations(eqs, dict(zip(eqs.parameters, model.params)), backend=model.backend)
    y0 = initial_state(eqs.coordinates, initial)
    why = ""
    if method == "auto":
        method, why = choose_method(model)
    if method not in SCIPY_METHODS:
        raise TypeError(f"unknown method {method!r}; choose one of {', '.join(SCIPY_METHODS)} or 'auto'")
    if t_eval is None:
        t_eval = np.linspace(t0, t1, n_points)
    t_eval = np.asarray(t_eval, dtype=float)

    if not switches:
        try:
            model.fun(t0, y0)
        except SingularMassMatrixError:
            raise
    conservative = eqs.is_conservative
    n2 = 2 * eqs.n
    fun = model.fun
    power = None if conservative else _power_function(model)

    def f(t_, z):
        if power is None:
            out = fun(t_, z)
        else:
            y = z[:n2]
            out = list(fun(t_, y))
            out.append(power(t_, y.tolist()))
        s = sum(out)
        if s != s or s in (math.inf, -math.inf):
            raise IntegrationError(
                f"non-finite derivative at t={t_:.9g} ({_state_text(model, z)}); likely causes: a "
                "singular configuration (division by zero in the model), a blow-up, or a parameter out "
                "of range",
                t=float(t_),
                state=dict(zip([*model.equations.coordinates], z)),
            )
        return out

    z0 = y0 if conservative else np.append(y0, 0.0)
    jac = None
    if method in IMPLICIT_METHODS:
        jy = jacobian_function(model)
        if conservative:
            jac = jy
        else:
            def jac(t_, z):  # the work integral does not feed back
                J = np.zeros((n2 + 1, n2 + 1))
                J[:n2, :n2] = jy(t_, z[:n2])
                return J

    kwargs = dict(method=method, rtol=rtol, atol=atol, max_step=max_step)
    if jac is not None:
        kwargs["jac"] = jac
    try:
        if switches:
            res = run_switched(model, switches, (t0, t1), z0, t_eval, events, kwargs, power is not None)
        else:
            res = solve_ivp(f, (t0, t1), z0, t_eval=t_eval, events=events, **kwargs)
    except LagrangeError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError, np.linalg.LinAlgError) as exc:
        raise IntegrationError(f"integration failed: {exc}") from exc
    if res.status == -1:
        raise _collapse_error(model, res, t0, y0)
    Y = res.y.T
    label = method if not why else f"{method} (auto: {why})"
    return Trajectory(
        t=res.t,
        y=Y[:, :n2].copy(),
        model=model,
        method=label,
        success=bool(res.success),
        message=str(res.message),
        nfev=int(res.nfev),
        work=None if conservative else Y[:, n2].copy(),
        initial=(t0, y0.copy()),
        switches=(res.switched_model, res.sigma) if switches else (),
        t_events=list(res.t_events) if res.t_events is not None else [],
        y_events=[np.asarray(v)[:, :n2] if len(v) else np.empty((0, n2)) for v in res.y_events]
        if res.y_events is not None
        else [],
    )
