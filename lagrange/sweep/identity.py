"""What defines a run of a sweep: the configuration key that keys ``resume``, and the reserved column names.

A run is the point (its :func:`~lagrange.sweep.grid.run_id`) *and* everything else that determines its
result: for a :class:`~lagrange.sweep.task.SimulationTask` the system's declaration (its derivation-cache
key: T, V, P, constraints, bodies, … and the lagrange and sympy versions; so a changed V or T is a different
run), the base parameter, initial and input values, ``t_end``, the simulate options
(method, tolerances, step, …), the backend and the summary, setup and event functions; for any other task
callable, its pickled form (module-level functions pickle by reference: their module and name).

A function is identified by what it computes (:func:`describe_function`): its module and qualified name, its
code (bytecode, constants, names, and nested code objects such as inner lambdas, recursively), its default
arguments, the values in its closure cells, and the values of the globals its code names — a function of the
same module among them identified the same way, recursively; a function of another module (a library's) by
module and name. So two lambdas differ when their bodies differ, a closure over another value is another run,
and a changed helper or global constant of the summary's module is another run. Line numbers and file names
are not part of it (moving a function does not change its runs). Values without a deterministic text (a
``repr`` holding an address) make the key differ between processes: such runs are recomputed, never reused. The
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

import functools
import hashlib
import math
import types
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

__all__ = ["RESERVED", "run_config", "describe", "describe_function", "reserved_columns", "check_point_names",
           "clashing_columns"]

#: columns every sweep table has
RESERVED = ("run_id", "run_config", "status", "error", "wall_time")
#: the default summary columns of a SimulationTask (plus ``final_<state>``)
SUMMARY = ("success", "nfev", "t_final", "energy_error")


def describe(value: Any, _active: frozenset = frozenset()) -> str:
    """A deterministic text of ``value`` for hashing: floats exactly (``float.hex``), arrays by their bytes,
    sympy objects by ``srepr``, functions by code, closure and globals (:func:`describe_function`), other
    callables by module and qualified name, containers recursively (sets sorted). Anything else by type and
    ``repr`` (a repr holding an address makes the key differ between processes: such runs are recomputed on
    resume, never wrongly reused). ``_active``: ids of the functions being described (a recursive function
    names itself instead of recursing)."""
    if value is None or isinstance(value, (bool, int, str, bytes)):
        return repr(value)
    if isinstance(value, float):
        return value.hex() if math.isfinite(value) else repr(value)
    if isinstance(value, np.generic):
        return describe(value.item())
    if isinstance(value, np.ndarray):
        digest = hashlib.sha256(np.ascontiguousarray(value).tobytes()).hexdigest()
        return f"array{value.shape}{value.dtype.str}:{digest}"
    if isinstance(value, Mapping):
        items = sorted((describe(k, _active), describe(v, _active)) for k, v in value.items())
        return "{" + ",".join(f"{k}:{v}" for k, v in items) + "}"
    if isinstance(value, (list, tuple)):
        return "(" + ",".join(describe(v, _active) for v in value) + ")"
    if isinstance(value, (set, frozenset)):
        return "set(" + ",".join(sorted(describe(v, _active) for v in value)) + ")"
    if isinstance(value, types.CodeType):
        return _describe_code(value, _active)
    if hasattr(value, "free_symbols") and hasattr(value, "func"):  # a sympy object
        import sympy as sp

        return sp.srepr(value)
    if isinstance(value, (types.FunctionType, types.MethodType, functools.partial)):
        return describe_function(value, _active)
    if isinstance(value, types.ModuleType):
        return f"module:{value.__name__}"
    if callable(value) and hasattr(value, "__qualname__"):
        return f"{getattr(value, '__module__', '?')}.{value.__qualname__}"
    if callable(value) and hasattr(value, "__dict__"):  # a callable object: its class and its attributes
        cls = type(value)
        return f"{cls.__module__}.{cls.__qualname__}:{describe(vars(value), _active)}"
    return f"{type(value).__module__}.{type(value).__qualname__}:{value!r}"


def describe_function(fn: Any, _active: frozenset = frozenset()) -> str:
    """A deterministic text of what the function ``fn`` computes (module docstring): module and qualified
    name, code (recursively), defaults, closure values and the values of the globals its code names (functions
    of the same module recursively, by code). Bound methods add their instance (class and attributes);
    :func:`functools.partial` its function and bound arguments."""
    if isinstance(fn, functools.partial):
        return (f"partial({describe_function(fn.func, _active)},{describe(fn.args, _active)},"
                f"{describe(fn.keywords, _active)})")
    if isinstance(fn, types.MethodType):
        owner = fn.__self__
        state = describe(vars(owner), _active) if hasattr(owner, "__dict__") else describe(owner, _active)
        return f"method({describe(fn.__func__, _active)},{type(owner).__module__}.{type(owner).__qualname__}:{state})"
    name = f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', '?')}"
    if not isinstance(fn, types.FunctionType):
        return name
    if id(fn) in _active:  # recursion (a function calling itself, or two calling each other)
        return f"recursive:{name}"
    active = _active | {id(fn)}
    code = fn.__code__
    closure = [_cell_value(cell) for cell in fn.__closure__ or ()]
    module = getattr(fn, "__module__", None)
    referenced = {}
    for nm in sorted(_global_names(code)):
        if nm in fn.__globals__:
            value = fn.__globals__[nm]
            if isinstance(value, types.FunctionType) and value.__module__ != module:
                referenced[nm] = f"{value.__module__}.{value.__qualname__}"  # a library's function: by name
            else:
                referenced[nm] = describe(value, active)
    parts = (name, _describe_code(code, active), describe(fn.__defaults__, active),
             describe(fn.__kwdefaults__, active), describe(closure, active), describe(referenced, active))
    return "function(" + ",".join(parts) + ")"


def _cell_value(cell) -> Any:
    try:
        return cell.cell_contents
    except ValueError:  # a cell not yet assigned
        return "<empty cell>"


def _describe_code(code: types.CodeType, active: frozenset) -> str:
    """Bytecode, constants (nested code objects recursively), names, argument layout and flags: what the code
    computes, without its file name and line numbers."""
    consts = ",".join(describe(c, active) for c in code.co_consts)
    return (f"code({code.co_code.hex()},({consts}),{code.co_names},{code.co_varnames},{code.co_freevars},"
            f"{code.co_argcount},{code.co_kwonlyargcount},{code.co_flags})")


def _global_names(code: types.CodeType) -> set[str]:
    """The names ``code`` and its nested code objects look up (globals among them)."""
    names = set(code.co_names)
    for c in code.co_consts:
        if isinstance(c, types.CodeType):
            names |= _global_names(c)
    return names


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
