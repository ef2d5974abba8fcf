"""One run of a sweep: a picklable task ``task(point) -> {column: value}`` and the wrapper that times it and
turns any exception into a row.

:class:`SimulationTask` is the task for a :class:`~lagrange.System`: it carries the system and its compiled
:class:`~lagrange.codegen.numeric.NumericModel` (pickled by source, rebuilt once per worker process), binds
the point's parameter and initial values, calls :func:`lagrange.integrate.run.simulate` and reduces the
:class:`~lagrange.results.trajectory.Trajectory` to scalars: the default summaries (success, nfev, the final
time and state, the energy error — the power-balance residual when the system is not conservative) and
the user's summary functions.

Any picklable callable ``task(point) -> Mapping[str, scalar]`` can be swept instead (module-level
functions; with ``cloudpickle`` installed, lambdas and notebook functions too).
"""

from __future__ import annotations

import hashlib
import math
import pickle
import time
from collections import OrderedDict
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from ..conventions import VELOCITY_SUFFIX
from ..errors import SweepError
from ..integrate.prepare import given_entries
from ..integrate.run import initial_state
from ..model.coordinates import coordinate_name, key_name
from .pickling import dumps_task

__all__ = ["SimulationTask", "InputExpressions", "execute", "dumps_task", "state_name", "state_names",
           "scalar_columns", "release_task", "KEEP_TASKS"]

Summary = Callable[[Any], Any]


def state_names(system) -> list[str]:
    """``["q1", …, "q1_dot", …]``: the names of the state entries (and of initial values)."""
    names = [coordinate_name(q) for q in system.derived.coordinates]
    return names + [nm + VELOCITY_SUFFIX for nm in names]


def scalar_columns(name: str, value) -> dict[str, Any]:
    """A summary's value as table columns: a scalar under ``name``; a dict's entries under their keys; a 1-D
    array under ``name_0, name_1, …``. Raises SweepError for anything else."""
    if isinstance(value, Mapping):
        out: dict[str, Any] = {}
        for k, v in value.items():
            out.update(scalar_columns(str(k), v))
        return out
    if isinstance(value, (str, bool, int, float, type(None), np.generic)):
        return {name: value.item() if isinstance(value, np.generic) else value}
    arr = np.asarray(value)
    if arr.ndim == 0:
        return {name: arr.item()}
    if arr.ndim == 1:
        return {f"{name}_{i}": v.item() for i, v in enumerate(arr)}
    raise SweepError(f"summary {name!r} returned an array of shape {arr.shape}: return scalars, a dict of "
                     "scalars or a 1-D array")


class SimulationTask:
    """``task(point)``: simulate ``system`` with the point's values and summarize the trajectory.

    Parameters
    ----------
    system : System
    t_end : float — integrate over [0, t_end] (a terminal event may stop earlier)
    initial, params : base values (names or symbols as keys); the point's entries override them by name
    inputs : base values of the system's inputs (any form :func:`~lagrange.integrate.run.simulate` takes); a
        point entry named like an input sets it to that constant
    options : keyword arguments of :func:`~lagrange.integrate.run.simulate` (``method``, ``rtol``, …)
    summaries : callables ``f(trajectory)`` returning a scalar (column ``f.__name__``), a dict of scalars or
        a 1-D array (see :func:`scalar_columns`)
    setup : optional ``setup(system, point) -> (initial_updates, params_updates)`` for quantities that are
        neither parameters nor initial values (a top's spin and tilt → Euler angles and rates); it may return a
        third mapping, ``input_updates``, to vary a parameter of an input's function (``{u: lambda t:
        point["A"] * np.cos(t)}``)
    events : optional ``events(system) -> list`` of scipy-style event functions, built once per process
    backend : code-generation backend of the model compiled here and shipped to the workers

    Point names must be parameters, inputs (constant values), coordinates, velocities (``q_dot``) or, with
    ``setup``, anything.
    """

    def __init__(self, system, t_end: float, initial: Mapping, params: Mapping | None = None, *,
                 options: Mapping | None = None, summaries: Sequence[Summary] = (), setup: Callable | None = None,
                 events: Callable | None = None, backend: str = "python", first_point: Mapping | None = None,
                 inputs: Mapping | None = None):
        self.system = system
        self.t_end = float(t_end)
        names = state_names(system)
        coords = system.derived.coordinates  # (with constraints, speeds left out are computed by each run)
        y0 = initial_state(coords, initial, speeds_optional=bool(system.derived.m)) if initial else None
        given = given_entries(coords, initial) if initial else []
        self.initial = {nm: float(v) for nm, v, g in zip(names, y0, given) if g} if y0 is not None else {}
        self.params = {k.name if hasattr(k, "name") else str(k): v for k, v in (params or {}).items()}
        self.inputs = {k.name if hasattr(k, "name") else str(k): v for k, v in (inputs or {}).items()}
        self.options = dict(options or {})
        if "model" in self.options or "events" in self.options:
            raise SweepError("pass the model via `backend` and events as a factory `events(system) -> list`, "
                             "not as simulate options (they must be rebuilt in each worker process)")
        _check_option_names(self.options)
        self.summaries = tuple(summaries)
        self.setup, self.events = setup, events
        bind = {**self.params, **{k: v for k, v in (first_point or {}).items() if k in self.parameter_names}}
        # the inputs' slots are filled per run by simulate (constants, or the schedule of varying values)
        self.model = system.compile(bind, backend=backend, inputs={nm: 0.0 for nm in self.input_names})
        self._event_list: list | None = None

    @property
    def parameter_names(self) -> list[str]:
        inputs = set(self.system.derived.inputs)
        return [s.name for s in self.system.derived.numeric_parameters if s not in inputs]

    @property
    def input_names(self) -> list[str]:
        return [s.name for s in self.system.derived.inputs]

    def check_point(self, point: Mapping) -> None:
        """Raise SweepError naming every point entry that is neither a parameter nor a state entry."""
        if self.setup is not None:
            return
        known = set(self.parameter_names) | set(self.input_names) | set(state_names(self.system))
        unknown = [k for k in point if k not in known]
        if unknown:
            inputs = f", an input ({', '.join(self.input_names)})" if self.input_names else ""
            raise SweepError(f"cannot sweep {', '.join(unknown)}: not a parameter ({', '.join(self.parameter_names)})"
                             f"{inputs} nor an initial value ({', '.join(state_names(self.system))}) of this system")

    def fingerprint(self) -> str:
        """Text of everything but the point that defines a run (:mod:`lagrange.sweep.identity`): the derived
        equations, the base values, t_end, the options, the backend and the functions."""
        from ..codegen.derivation_cache import declaration_key
        from .identity import describe

        # the declaration (T, V, P, constraints, …, and the lagrange/sympy versions), else the generated code
        eqs = declaration_key(self.system) or hashlib.sha256(self.model.source.encode()).hexdigest()
        parts = {"equations": eqs, "t_end": self.t_end, "initial": self.initial, "params": self.params,
                 "inputs": self.inputs, "options": self.options, "backend": self.model.backend,
                 "summaries": list(self.summaries), "setup": self.setup, "events": self.events}
        return describe(parts)

    def __getstate__(self):
        state = dict(self.__dict__)
        state["_event_list"] = None  # closures: rebuilt in each process
        return state

    def __call__(self, point: Mapping) -> dict[str, Any]:
        initial, params, inputs = dict(self.initial), dict(self.params), dict(self.inputs)
        if self.setup is not None:
            ini, par, *more = self.setup(self.system, point)
            initial.update(_by_name(self.system, ini))
            params.update({k.name if hasattr(k, "name") else str(k): v for k, v in par.items()})
            for extra in more[:1]:
                inputs.update({k.name if hasattr(k, "name") else str(k): v for k, v in extra.items()})
        pnames, snames, unames = set(self.parameter_names), set(state_names(self.system)), set(self.input_names)
        for k, v in point.items():
            if k in pnames:
                params[k] = v
            elif k in unames:
                inputs[k] = v
            elif k in snames:
                initial[k] = v
        if self.events is not None and self._event_list is None:
            self._event_list = list(self.events(self.system))
        model = self.model.with_params(params) if params else self.model
        if self.input_names or inputs:
            options = {**self.options, "inputs": inputs}
        else:
            options = self.options
        traj = self.system.simulate(self.t_end, initial, params, model=model, events=self._event_list, **options)
        return {**default_summary(traj), **_user_summaries(self.summaries, traj)}


class InputExpressions:
    """A picklable ``setup`` for :class:`SimulationTask` that sweeps parameters of input expressions:
    ``setup(system, point) -> ({}, {}, {input: expression with the point's values substituted})``.

    ``expressions`` maps input names to sympy expressions of t and of names (the point's names among them)
    that are not parameters of the system (``F = F0*cos(w*t)`` with F0 swept). Point names that are not in
    the expressions are checked and applied by the task as usual.
    """

    def __init__(self, expressions: Mapping, names: Sequence[str]):
        self.expressions = dict(expressions)
        self.names = tuple(names)

    def __call__(self, system, point: Mapping):
        values = {k: float(v) for k, v in point.items() if k in self.names}
        out = {}
        for name, e in self.expressions.items():
            out[name] = e.subs({s: values[s.name] for s in e.free_symbols if s.name in values}) \
                if hasattr(e, "free_symbols") else e
        return {}, {}, out


def _check_option_names(options: Mapping) -> None:
    """SweepError naming every option that is not a keyword of :func:`~lagrange.integrate.run.simulate` (with
    the closest names), once before any run, instead of the same TypeError in every row."""
    import difflib
    import inspect

    from ..integrate.run import simulate

    known = [p.name for p in inspect.signature(simulate).parameters.values()
             if p.kind is p.KEYWORD_ONLY and p.name not in ("model", "events", "inputs")]
    unknown = [str(k) for k in options if k not in known]
    if unknown:
        hints = []
        for k in unknown:
            close = difflib.get_close_matches(k, known, n=2)
            hints.append(f"{k!r}" + (f" (did you mean {' or '.join(map(repr, close))}?)" if close else ""))
        raise SweepError(f"unknown simulate option(s) {', '.join(hints)}: the options of a sweep are the keywords "
                         f"of lagrange.simulate ({', '.join(known)}); the system's inputs go in `inputs=`")


def state_name(system, key) -> str:
    """The name of a key given by object (:func:`~lagrange.model.coordinates.key_name`)."""
    return key_name(key, system.coordinates)


def _by_name(system, values: Mapping) -> dict[str, float]:
    if not values:
        return {}
    names = state_names(system)
    n = len(names) // 2
    out = {state_name(system, key): float(v) for key, v in values.items()}
    unknown = [k for k in out if k not in names]
    if unknown:
        raise SweepError(f"setup returned unknown initial value(s) {', '.join(unknown)} "
                         f"(state: {', '.join(names[:n])} and velocities)")
    return out


def default_summary(traj) -> dict[str, Any]:
    """success, nfev, t_final, final_<state name>, energy_error (power-balance residual, relative)."""
    row: dict[str, Any] = {"success": bool(traj.success), "nfev": int(traj.nfev), "t_final": float(traj.t[-1])}
    row.update({f"final_{nm}": float(v) for nm, v in zip(traj.names, traj.y[-1])})
    try:
        row["energy_error"] = float(traj.energy_error())
    except (ValueError, ZeroDivisionError, FloatingPointError):
        row["energy_error"] = math.nan
    return row


def _user_summaries(summaries: Sequence[Summary], traj) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for f in summaries:
        out.update(scalar_columns(getattr(f, "__name__", type(f).__name__), f(traj)))
    return out




#: per process: the unpickled task of each recent sweep (unpickled once, not per run), least recently used first
_TASKS: OrderedDict[str, Any] = OrderedDict()
#: how many unpickled tasks a worker process keeps (older ones are released: long-lived Dask workers would
#: otherwise accumulate one per sweep)
KEEP_TASKS = 2


def release_task(token: str) -> bool:
    """Forget the unpickled task of sweep ``token`` in this process (run on every Dask worker when a sweep
    ends); whether it was held."""
    return _TASKS.pop(token, None) is not None


def execute(payload: bytes | Any, token: str, rid: str, point: Mapping) -> dict[str, Any]:
    """Run one point in a worker: the row ``{run_id, status, error, wall_time, …results}``.

    ``payload`` is a task pickled by :func:`dumps_task` (unpickled once per process and kept under
    ``token``, at most :data:`KEEP_TASKS` of them) or the task itself (in-process runs). An exception of the
    task gives ``status = "error"`` and ``error = "Type: message"``; so does a result column that would
    overwrite a reserved column or a swept value (:mod:`lagrange.sweep.identity`); the other runs are
    unaffected. Ctrl-C (KeyboardInterrupt) is not caught: it stops the sweep.
    """
    from .identity import clashing_columns

    if isinstance(payload, bytes):
        task = _TASKS.get(token)
        if task is None:
            task = _TASKS[token] = pickle.loads(payload)  # noqa: S301 - our own payload
            while len(_TASKS) > KEEP_TASKS:
                _TASKS.popitem(last=False)
        _TASKS.move_to_end(token)
    else:
        task = payload
    t0 = time.perf_counter()
    try:
        values = dict(task(dict(point)))
        status, error = "ok", ""
    except Exception as exc:  # noqa: BLE001 - one failing run must not stop the sweep: it is reported
        values, status, error = {}, "error", f"{type(exc).__name__}: {exc}".strip()
    clash = clashing_columns(values, point)
    if clash:
        values, status = {}, "error"
        error = (f"SweepError: the task returned column(s) {', '.join(map(repr, clash))}, which would overwrite "
                 "a reserved column (run_id, run_config, status, error, wall_time) or a swept value: rename the "
                 "summary")
    return {"run_id": rid, "status": status, "error": error, **values, "wall_time": time.perf_counter() - t0}
