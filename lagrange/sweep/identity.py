"""What defines a run of a sweep: the configuration key that keys ``resume``, and the reserved column names.

A run is the point (its :func:`~lagrange.sweep.grid.run_id`) *and* everything else that determines its
result: for a :class:`~lagrange.sweep.task.SimulationTask` the system's declaration (its derivation-cache
key: T, V, P, constraints, bodies, … and the lagrange and sympy versions; so a changed V or T is a different
run), the base parameter, initial and input values, ``t_end``, the simulate options
(method, tolerances, step, …), the backend and the summary, setup and event functions; for any other task
callable, its pickled form (module-level functions pickle by reference: their module and name). The
:func:`run_config` of these is stored with every row (column ``run_config``); ``resume=True`` reuses a stored
row only when both its run id and its configuration match, so rows computed with another ``t_end``, V or
tolerance are computed again, never silently reused.

Reserved columns: ``run_id``, ``run_config``, ``status``, ``error``, ``wall_time`` in every table, and for a
system the default summaries ``success``, ``nfev``, ``t_final``, ``energy_error`` and ``final_<state>``. A
swept name equal to one of them is refused before any run (:class:`~lagrange.errors.SweepError`); a task or
summary returning a column that is reserved or named like a swept quantity gives that run
``status = "error"`` naming the column (it never overwrites the point's value or the status).
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

__all__ = ["RESERVED", "run_config", "describe", "reserved_columns", "check_point_names", "clashing_columns"]

#: columns every sweep table has
RESERVED = ("run_id", "run_config", "status", "error", "wall_time")
#: the default summary columns of a SimulationTask (plus ``final_<state>``)
SUMMARY = ("success", "nfev", "t_final", "energy_error")


def describe(value: Any) -> str:
    """A deterministic text of ``value`` for hashing: floats exactly (``float.hex``), arrays by their bytes,
    sympy objects by ``srepr``, callables by module and qualified name, containers recursively. Anything
    else by type and ``repr`` (a repr holding an address makes the key differ between processes: such runs
    are recomputed on resume, never wrongly reused)."""
    if value is None or isinstance(value, (bool, int, str)):
        return repr(value)
    if isinstance(value, float):
        return value.hex() if math.isfinite(value) else repr(value)
    if isinstance(value, np.generic):
        return describe(value.item())
    if isinstance(value, np.ndarray):
        digest = hashlib.sha256(np.ascontiguousarray(value).tobytes()).hexdigest()
        return f"array{value.shape}{value.dtype.str}:{digest}"
    if isinstance(value, Mapping):
        items = sorted((describe(k), describe(v)) for k, v in value.items())
        return "{" + ",".join(f"{k}:{v}" for k, v in items) + "}"
    if isinstance(value, (list, tuple)):
        return "(" + ",".join(describe(v) for v in value) + ")"
    if hasattr(value, "free_symbols") and hasattr(value, "func"):  # a sympy object
        import sympy as sp

        return sp.srepr(value)
    if callable(value) and hasattr(value, "__qualname__"):
        return f"{getattr(value, '__module__', '?')}.{value.__qualname__}"
    return f"{type(value).__module__}.{type(value).__qualname__}:{value!r}"


def run_config(task: Any) -> str:
    """A 16-hex-digit key of everything but the point that defines a run of ``task`` (module docstring)."""
    fingerprint = getattr(task, "fingerprint", None)
    if callable(fingerprint):
        text = fingerprint()
    else:
        from .pickling import dumps_task

        try:
            text = "task:" + hashlib.sha256(dumps_task(task)).hexdigest()
        except Exception:  # noqa: BLE001 - an unpicklable task still runs in-process: key it by name
            text = "task:" + describe(task)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def reserved_columns(task: Any, state_names: Sequence[str] = ()) -> set[str]:
    """The reserved column names of a table of ``task`` (a SimulationTask has its default summaries)."""
    names = set(RESERVED)
    if hasattr(task, "fingerprint"):
        names |= set(SUMMARY) | {f"final_{nm}" for nm in state_names}
    return names


def check_point_names(names: Sequence[str], reserved: set[str]) -> None:
    """SweepError naming every swept name that is a reserved column."""
    from ..errors import SweepError

    bad = [nm for nm in names if nm in reserved]
    if bad:
        raise SweepError(f"cannot sweep {', '.join(map(repr, bad))}: reserved column name(s) of the sweep table "
                         f"({', '.join(sorted(reserved))}); rename the parameter (or the setup quantity)")


def clashing_columns(values: Mapping[str, Any], point: Mapping[str, Any]) -> list[str]:
    """The columns of a task's result that would overwrite a reserved column or the point's values."""
    return [k for k in values if k in RESERVED or k in point]
