"""Preparing a run: the initial state, the model for the equations, the initial mass matrix, the inputs.

Shared by the run functions of the methods (:mod:`lagrange.integrate.registry`); everything numeric comes from
the compiled model (:class:`~lagrange.codegen.numeric.NumericModel`).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence
from functools import lru_cache

import numpy as np

from ..codegen.numeric import NumericModel
from ..conventions import VELOCITY_SUFFIX
from ..errors import (
    InitialConditionError,
    InputError,
    LagrangeError,
    NonAnalyticWarning,
    OptionError,
    ParameterError,
    SingularMassMatrixError,
    shown,
)
from ..model.coordinates import canonical_keys, coordinate_name, is_coordinate

__all__ = ["initial_state", "given_entries", "model_for", "check_initial_mass_matrix", "refuse_route",
           "constant_input_run", "split_inputs", "check_model",
           "GimbalLockWarning"]


def initial_state(coords: Sequence, initial: Mapping, *, speeds_optional: bool = False) -> np.ndarray:
    """``y0 = [q, q̇]`` from a dict keyed by coordinates, their derivatives or names (``"x_dot"``).

    ``speeds_optional`` (a constrained system): velocities left out are 0 here and computed by the run from
    the velocity constraints (:func:`~lagrange.integrate.constrained.consistent_initial`; :func:`given_entries`
    says which entries were given). Raises :class:`InitialConditionError` naming every missing, unknown or
    non-finite entry.
    """
    names, slot_of = _slots(tuple(coords))
    initial = canonical_keys(initial, coords)  # dynamicsymbols and their derivatives
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
        except OverflowError:
            problems.append(f"initial value of {key} = {shown(value)} is beyond the floating-point range")
            continue
        except (TypeError, ValueError):
            problems.append(f"initial value of {key} = {shown(value)} is not a number")
            continue
        if not math.isfinite(v):
            problems.append(f"initial value of {key} = {v} is not finite")
        values[idx], filled[idx] = v, True
    if speeds_optional:
        values[n:] = [v if f else 0.0 for v, f in zip(values[n:], filled[n:])]
        filled[n:] = [True] * n
    if not all(filled):
        missing = [names[i] if i < n else names[i - n] + VELOCITY_SUFFIX for i in range(2 * n) if not filled[i]]
        problems.append(f"missing initial value(s) for {', '.join(missing)}")
    if problems:
        raise InitialConditionError("; ".join(problems))
    return np.array(values, dtype=float)


def given_entries(coords: Sequence, initial: Mapping) -> list[bool]:
    """Which of the 2n entries of ``[q, q̇]`` the dict ``initial`` gives (keys as in :func:`initial_state`)."""
    _, slot_of = _slots(tuple(coords))
    out = [False] * (2 * len(coords))
    for key in canonical_keys(initial, coords):  # dynamicsymbols and their derivatives, as initial_state takes them
        try:
            idx = slot_of.get(key)
        except TypeError:
            idx = None
        if idx is not None:
            out[idx] = True
    return out


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


class GimbalLockWarning(UserWarning):
    """Euler angles near θ = 0 or π: the mass matrix is nearly singular (gimbal lock)."""


#: |sin θ| below which Euler angles are reported as at (or next to) gimbal lock
GIMBAL_SIN = 1e-3
_GIMBAL_HINT = (" Gimbal lock: Wells' Euler angles are singular at θ = 0 or π (only ψ + φ is defined there). "
                "Use RigidBody(..., orientation=Quaternion(q0, q1, q2, q3)) — it is regular everywhere (a "
                "sleeping top) — or tilt the reference axes.")


def _lockable(system) -> list:
    """The nutation angles θ of the bodies of ``system`` whose Euler angles can lock (ψ and φ both move with the
    coordinates); remembered per bodies tuple."""
    seen = getattr(system, "__dict__", {}).get("_gimbal_angles")
    if seen is not None and seen[0] is system.bodies:
        return seen[1]
    from ..model.rotations import EulerAngles

    coords = tuple(system.coordinates)
    angles = [b.orientation.theta for b in system.bodies if isinstance(getattr(b, "orientation", None), EulerAngles)
              and b.orientation.psi.has(*coords) and b.orientation.phi.has(*coords)]
    if hasattr(system, "__dict__"):
        system.__dict__["_gimbal_angles"] = (system.bodies, angles)
    return angles


def _gimbal_hint(system, model: NumericModel, t0: float, y0) -> str:
    """The gimbal-lock hint when it is the cause at ``(t0, y0)``: a body's Euler angles can lock and its θ is
    within :data:`GIMBAL_SIN` of 0 or π there (or cannot be evaluated); else ""."""
    angles = _lockable(system) if hasattr(system, "bodies") else []
    if not angles:
        return ""
    from ..conventions import t

    values = {t: float(t0), **dict(zip(model.equations.parameters, model.params.tolist())),
              **{q: float(v) for q, v in zip(system.coordinates, y0)}}
    for theta in angles:
        try:
            if abs(math.sin(float(theta.xreplace(values)))) < GIMBAL_SIN:
                return _GIMBAL_HINT
        except (TypeError, ValueError):  # θ not a number at this state: the hint cannot be ruled out
            return _GIMBAL_HINT
    return ""


def check_initial_mass_matrix(system, model: NumericModel, t0: float, y0) -> None:
    """Raise on a singular mass matrix (naming coordinates; the gimbal-lock hint when Euler angles are at θ = 0
    or π there) and warn when it is nearly singular at Euler angles' gimbal lock."""
    hint = _gimbal_hint(system, model, t0, y0)
    try:
        model.fun(t0, y0)
    except SingularMassMatrixError as exc:
        raise SingularMassMatrixError(str(exc).rstrip(".") + "." + hint) from None
    if hint and not model.m:
        try:  # M is symmetric: LAPACK's eigenvalues (numpy's, so a run does not import scipy.linalg)
            w = [abs(x) for x in np.linalg.eigvalsh(model.mass_matrix(t0, y0)).tolist()]
        except np.linalg.LinAlgError:  # no convergence: treated as singular
            w = [0.0]
        cond = max(w) / min(w) if min(w) > 0 else math.inf  # its 2-norm condition number
        if cond > 1e8:
            import warnings

            warnings.warn(f"the mass matrix is nearly singular at the initial state (condition number "
                          f"{cond:.2g}).{hint}", GimbalLockWarning, stacklevel=3)


def model_for(eqs, params, model: NumericModel | None, backend: str, baumgarte: tuple | None = None, *,
              inputs: dict | None = None, schedule=None, bound: bool = False) -> NumericModel:
    """The model of the run: ``model`` (checked by :func:`check_model`) with ``params`` and the input constants
    ``inputs`` bound BY NAME when it was built for ``eqs`` (and no Baumgarte ``baumgarte=(α, β)`` is asked for),
    else ``eqs`` compiled with those values (and the given model's backend); then the ``schedule`` of the
    time-varying inputs attached. ``bound=True``: ``model`` was built for ``eqs`` with exactly these values
    (``RunRequest.model_bound``) and is used as it is unless Baumgarte gains are asked for."""
    if bound and model is not None and model.equations is eqs and not (baumgarte and eqs.m):
        return model if model.schedule is schedule else model.with_schedule(schedule)
    values = {**dict(params), **(inputs or {})}
    if model is not None and (model.equations is eqs or model.equations == eqs) and not (baumgarte and eqs.m):
        out = model.with_params(values) if values else model
    else:
        if model is not None:  # the given model's values fill in names the call leaves out
            values = {**{s.name: v for s, v in zip(model.equations.numeric_parameters, model.params)}, **values}
        out = NumericModel.build(eqs, values, backend=backend if model is None else model.backend,
                                 baumgarte=baumgarte if eqs.m else None)
    return out if out.schedule is schedule else out.with_schedule(schedule)


def check_model(model, eqs) -> None:
    """Refuse a ``model=`` that is not a NumericModel of the system's equations ``eqs`` (same coordinates,
    parameters and equations; a model of another system would silently integrate the wrong equations)."""
    if model is None:
        return
    if not isinstance(model, NumericModel):
        raise OptionError(f"model= must be a NumericModel from System.compile, got {type(model).__name__}")
    if model.equations is eqs or model.equations == eqs:
        return
    mine = [coordinate_name(c) for c in eqs.coordinates]
    theirs = [coordinate_name(c) for c in model.equations.coordinates]
    what = (f"coordinates {', '.join(theirs)} instead of {', '.join(mine)}" if mine != theirs else
            "the same coordinates but different equations or parameters")
    raise OptionError(f"model= was compiled for a different system ({what}): pass the model compiled from this "
                      "system (System.compile), or none")


def refuse_route(route: str, schedule) -> None:
    """InputError when ``route`` cannot evaluate the time-varying inputs of ``schedule``."""
    if schedule is not None:
        raise InputError(f"{route} cannot run time-varying inputs ({schedule.describe()}): it does not call Python "
                         f"per step, so it supports constant inputs only. Time-varying inputs run with "
                         f"{NumericModel.varying_routes()}")


def constant_input_run(req, route: str) -> tuple[NumericModel, np.ndarray]:
    """``(model, t_eval)`` for a method whose compiled code holds the inputs as constants (the Taylor method,
    heyoka): time-varying inputs refused naming ``route``, the model built (or ``req.model`` checked), the
    initial mass matrix checked, the output times (``n_points`` evenly spaced unless ``t_eval`` was given)."""
    refuse_route(route, req.schedule)
    model = model_for(req.equations, req.params, req.model, req.backend, inputs=req.constants,
                      bound=req.model_bound)
    t0, t1 = req.t_span
    check_initial_mass_matrix(req.system, model, t0, req.y0)
    t_eval = np.linspace(t0, t1, req.n_points) if req.t_eval is None else req.t_eval
    return model, t_eval


def split_inputs(eqs, params: Mapping, inputs, t_span, y0) -> tuple[dict, dict, object]:
    """``(params with the inputs' constants, those constants, the schedule of the varying ones)``; refuses an
    input given among the parameters."""
    names = {u.name for u in eqs.inputs}
    given = [getattr(k, "name", None) if not isinstance(k, str) else k for k in params]
    given = [str(k) if g is None else g for k, g in zip(params, given)]
    wrong = [k for k in given if k in names]
    if wrong:
        raise ParameterError(f"{', '.join(wrong)} {'is an input' if len(wrong) == 1 else 'are inputs'}, not "
                             f"parameter(s): give the value(s) as simulate(..., inputs={{'{wrong[0]}': ...}})")
    if not eqs.inputs and not inputs:
        return dict(params), {}, None
    constants, schedule = NumericModel.resolve_inputs(eqs, inputs, t_span, y0)
    return {**params, **constants}, constants, schedule


def warn_untrusted(method: str, eqs, model: NumericModel, t_span, y0) -> None:
    """Warn with :class:`~lagrange.errors.NonAnalyticWarning` when the Taylor-series ``method``, asked for by name,
    runs equations with a kink or a near-singularity at the values bound to ``model``
    (:meth:`NumericModel.taylor_obstacle`; the non-analytic functions the tape refuses with its own error)."""
    t0, t1 = (float(v) for v in t_span)
    y0 = np.asarray(y0, dtype=float)
    try:
        rates = np.asarray(model.fun(t0, y0), dtype=float)
    except (LagrangeError, ArithmeticError, ValueError, TypeError):
        rates = None
    values = dict(zip(eqs.numeric_parameters, np.asarray(model.params, dtype=float)))
    found = NumericModel.taylor_obstacle(eqs, values, y0, rates, t1 - t0, t0)
    if found is not None and found.kind != "function":
        warnings.warn(f"method={method!r} needs analytic equations, and these have {found.describe()}: its step "
                      "control can step across the layer where the force changes and return a wrong answer; use "
                      "method='DOP853' (or 'Radau' when stiff, or 'auto', which excludes the Taylor methods here)",
                      NonAnalyticWarning, stacklevel=4)
