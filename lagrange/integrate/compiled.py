"""The compiled integrator loop: adaptive DOP853 / RK45 run entirely in numba, no Python per step.

``simulate(..., loop=...)`` chooses between this loop and scipy's ``solve_ivp``:

``"compiled"``
    The generic loops of :mod:`lagrange.integrate._rk_loops`, compiled once per machine and cached on
    disk, called with the model's ``field`` (:mod:`lagrange.codegen.rk_source`) as a numba first-class
    function: a new model only pays for JIT-compiling its own right-hand side. Implies ``backend="numba"``
    (``pip install "lagrange-dynamics[fast]"``). Supports ``DOP853`` and ``RK45`` for unconstrained systems without
    events or dry-friction switches; anything else is a :class:`TypeError` naming the feature.
``"scipy"``
    ``solve_ivp`` (events, constraints, friction switches, every scipy method).
``"auto"`` (default)
    The compiled loop when the model's backend is numba and the problem is supported, else scipy; the
    trajectory's ``method`` label says which loop ran and, for a numba model run by scipy, why.

The loop is a transcription of scipy's ``DOP853``/``RK45`` (same tableaux, error norm, step-size
controller, initial step, dense output at ``t_eval``), so ``rtol``/``atol`` mean the same thing and
results agree with ``solve_ivp`` to round-off-level differences in the step sequence.

Failures inside the loop come back as a :class:`LoopStatus` with the time reached and the outputs up to
there; :func:`integrate_compiled` raises :class:`~lagrange.errors.IntegrationError` carrying ``t``,
``state`` and ``partial`` (the :class:`~lagrange.results.trajectory.Trajectory` so far).

Interrupts: the loop runs in chunks of about :data:`CHUNK_SECONDS` (:func:`run_in_chunks`), returning to
Python in between, so Ctrl-C stops it within a fraction of a second; :func:`integrate_compiled` then raises
:class:`~lagrange.errors.IntegrationInterrupted` (a KeyboardInterrupt) carrying the same ``t``, ``state``
and ``partial``. Chunking does not change the result (bit-identical to one uninterrupted call).
"""

from __future__ import annotations

import dataclasses
import importlib.util
import time
import warnings
from collections.abc import Callable
from enum import Enum
from functools import cache
from pathlib import Path
from types import ModuleType

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import BackendError, IntegrationError, IntegrationInterrupted, MethodError
from ..model.coordinates import state_text
from ..records import record
from ..results.trajectory import Trajectory

__all__ = ["LOOPS", "LOOP_METHODS", "LoopStatus", "LoopResult", "choose_loop", "loop_backend", "kernel", "loops",
           "run_loop", "integrate_compiled", "stopped_error", "check_output_times", "first_class", "run_in_chunks",
           "interrupted_error", "PAUSED", "CHUNK_SECONDS"]

LOOPS = ("auto", "scipy", "compiled")
#: the methods of the compiled loop (functions of the same name, lower case, in ``_rk_loops``)
LOOP_METHODS = ("DOP853", "RK45")
#: default cap on accepted steps of one compiled run
MAX_STEPS = 10_000_000
#: the status a compiled loop returns when it paused after the work it was given (call it again to go on)
PAUSED = -1
#: target wall time of one chunk of a compiled loop: Ctrl-C is acted on between chunks (numba code cannot
#: check for signals), so this bounds the delay of an interrupt; the call overhead is a few µs per chunk
CHUNK_SECONDS = 0.05


class LoopStatus(Enum):
    """How a compiled run ended; the value is ``(code, what happened and how to fix it)``."""

    SUCCESS = (0, "The solver successfully reached the end of the integration interval.")
    STEP_TOO_SMALL = (1, "the step size fell below 10 ulp of t: a singularity of the model (a coordinate "
                         "reaching a division by zero), a blow-up, stiffness (try method='LSODA' or 'Radau' with "
                         "loop='scipy'), or Euler angles passing through gimbal lock (use a Quaternion orientation)")
    NON_FINITE = (2, "a non-finite derivative or state appeared: a blow-up, a singular configuration or a "
                     "parameter out of range")
    DIVISION_BY_ZERO = (3, "division by zero while evaluating the model: a singular mass matrix (a massless "
                           "coordinate or gimbal lock) or a coordinate reaching a singular value")
    MAX_STEPS = (4, "the maximum number of steps was reached: raise max_steps, loosen rtol/atol or shorten "
                    "t_span")
    INTERRUPTED = (5, "interrupted by Ctrl-C (SIGINT)")

    @classmethod
    def from_code(cls, code: int) -> LoopStatus:
        return _STATUS_OF_CODE[code]

    @property
    def message(self) -> str:
        return self.value[1]


_STATUS_OF_CODE = {s.value[0]: s for s in LoopStatus}


@record(frozen=True)
class LoopResult:
    """Raw output of one compiled run: ``t`` (k,), ``z`` (k, nz) at the output times reached, the time and
    state where the loop stopped, and counters."""

    status: LoopStatus
    t: np.ndarray
    z: np.ndarray
    t_reached: float
    z_reached: np.ndarray
    nfev: int
    steps: int
    rejected: int


def _numba_available() -> bool:
    return importlib.util.find_spec("numba") is not None


def unsupported(eqs, method: str, *, events, switches, varying_inputs: bool = False) -> str | None:
    """Why the compiled loop cannot run this problem (None when it can)."""
    if varying_inputs:
        return "time-varying inputs (callables or samples; constant inputs are supported)"
    if method not in LOOP_METHODS:
        return f"method {method!r} (the compiled loop has {', '.join(LOOP_METHODS)})"
    if events:
        return "events"
    if switches:
        return "dry-friction sign() switches (use friction='regularize')"
    if eqs.is_rough:
        return "rough constraints"
    if eqs.m:
        return "constraints"
    return None


def loop_backend(loop: str, *, backend: str, model: NumericModel | None) -> str:
    """The backend a run with ``loop`` will have (the given model's, else the requested one, ``"auto"``
    resolved), after checking ``loop``: :class:`TypeError` for an unknown one, :class:`BackendError` for
    ``"compiled"`` without numba. Shared by the adaptive and the fixed-step loops."""
    if loop not in LOOPS:
        raise MethodError(f"loop must be one of {', '.join(map(repr, LOOPS))}, got {loop!r}")
    if loop == "compiled" and not _numba_available():
        raise BackendError("loop='compiled' needs numba: install it with `pip install \"lagrange-dynamics[fast]\"`")
    if model is not None:
        return model.backend
    return ("numba" if _numba_available() else "python") if backend == "auto" else backend


def choose_loop(loop: str, *, backend: str, model: NumericModel | None, eqs, method: str, events, switches,
                varying_inputs: bool = False) -> tuple[bool, str]:
    """``(use the compiled loop?, note for the method label)`` for ``simulate(loop=...)``.

    ``backend`` is the requested backend (used when ``model`` is None). Raises :class:`TypeError` for an
    unknown ``loop`` or, with ``loop="compiled"``, an unsupported feature; :class:`BackendError` when
    numba is missing or the given model (or ``backend="reference"``) is not numba code.
    """
    effective = loop_backend(loop, backend=backend, model=model)
    if loop == "scipy":
        return False, "scipy loop" if effective == "numba" else ""
    why = unsupported(eqs, method, events=events, switches=switches, varying_inputs=varying_inputs)
    if loop == "compiled":
        if effective == "reference" or (model is not None and effective != "numba"):
            raise BackendError(f"loop='compiled' runs generated numba code, but the model's backend is "
                               f"{effective!r}: use backend='numba'")
        if why:
            raise TypeError(f"loop='compiled' does not support {why}: use loop='scipy' (or 'auto')")
        return True, "compiled loop"
    if effective != "numba":
        return False, ""
    if why:
        return False, f"scipy loop: {why} not supported by the compiled loop"
    return True, "compiled loop"


_LOADED: dict[tuple[str, str], ModuleType] = {}  # (cache directory, file name): the module


def kernel(filename: str, prefix: str, what: str) -> ModuleType:
    """A self-contained numba module of this package (``filename``), imported once per process.

    The module is staged like the generated model modules (:func:`~lagrange.codegen.numba_backend.write_module`),
    named ``prefix`` + the hash of its text and of the lagrange, numba, NumPy and Python versions; numba's
    cache of it is kept as a sealed bundle in lagrange's cache directory
    (:func:`~lagrange.codegen.cache.cache_dir`), which works even when lagrange is installed in a read-only
    site-packages, and the kernel is compiled once per machine and version. A corrupted numba cache is
    purged and rebuilt once; ``what`` names the feature in errors.
    """
    key = (NumericModel.cache_location(), filename)
    if key not in _LOADED:
        _LOADED[key] = NumericModel.load_kernel(Path(__file__).with_name(filename).read_text(encoding="utf-8"),
                                                prefix, what)
    return _LOADED[key]


def loops() -> ModuleType:
    """The compiled DOP853/RK45 loops (:mod:`lagrange.integrate._rk_loops`), see :func:`kernel`."""
    return kernel("_rk_loops.py", "rkloops", "loop='compiled'")


@cache
def _address_class() -> type:
    """The wrapper-address class of :func:`first_class` (numba is imported only when it is needed)."""
    from numba.core.types import FunctionType, WrapperAddressProtocol
    from numba.experimental.function_type import _get_wrapper_address

    class Address(WrapperAddressProtocol):
        def __init__(self, function, signature):
            self.function = function  # the compiled code must outlive the address
            self._signature = signature
            self.address = _get_wrapper_address(function, signature)
            self._numba_type_ = FunctionType(signature)  # numba's typeof reads this instead of rebuilding it

        def __wrapper_address__(self) -> int:
            return self.address

        def signature(self):
            return self._signature

    return Address


def first_class(function, signature):
    """``function`` (a numba dispatcher compiled for ``signature``) as a first-class function argument whose
    address is looked up once: passing the dispatcher itself makes numba resolve its compiled wrapper on
    every call (about 18 µs, a tenth of a short Taylor run). The object is kept on the dispatcher, so the two
    live and die together."""
    address = getattr(function, "_lagrange_address", None)
    if address is None:
        address = _address_class()(function, signature)
        function._lagrange_address = address
    return address


def _field(model: NumericModel):
    """The model's compiled ``field(t, z, p, out) -> ok`` (:mod:`lagrange.codegen.rk_source`)."""
    field = getattr(getattr(model.dynamics, "py_func", None), "__globals__", {}).get("field")
    if field is None:
        raise BackendError("this model has no compiled field for the loop (build it with backend='numba', "
                           "no constraints)")
    return field


def run_loop(model: NumericModel, method: str, t_span, z0, t_eval, *, rtol: float, atol: float,
             max_step: float = np.inf, first_step: float | None = None, max_steps: int = MAX_STEPS) -> LoopResult:
    """Run the compiled ``method`` loop from ``z0`` (``y0``, plus the work 0 for non-conservative systems).

    Tolerances are validated as scipy does (``rtol`` below 100 ε is raised to it with a warning;
    negative ``atol`` or non-positive ``max_step`` is a ValueError), and ``t_eval`` must lie in
    ``t_span``, sorted in the direction of integration.
    """
    t0, t1 = float(t_span[0]), float(t_span[1])
    rtol, atol, max_step = float(rtol), float(atol), float(max_step)
    eps100 = 100 * np.finfo(float).eps
    if rtol < eps100:
        warnings.warn(f"rtol={rtol:g} is below 100 eps; using {eps100:g}", stacklevel=3)
        rtol = eps100
    if atol < 0:
        raise ValueError("atol must be non-negative")
    if not max_step > 0:
        raise ValueError("max_step must be positive")
    t_eval = check_output_times(t_eval, t0, t1)
    if method not in LOOP_METHODS:
        raise TypeError(f"the compiled loop has the methods {', '.join(LOOP_METHODS)}, not {method!r}")
    field = _field(model)
    kernels = loops()
    loop = getattr(kernels, method.lower())
    f = first_class(field, kernels.FIELD)
    y = np.array(z0, dtype=float)  # the loop's state, updated in place (bounded chunks, see run_in_chunks)
    f0 = np.empty_like(y)
    Y = np.empty((t_eval.size, y.size))
    fs = np.array([t0, float(first_step or 0.0)])
    counts = np.zeros(5, dtype=np.int64)  # n_out, nfev, steps, rejected, started
    p = np.ascontiguousarray(model.params, dtype=float)
    max_steps = int(max_steps)

    def chunk(n: int) -> int:
        return loop(f, t1, p, rtol, atol, max_step, t_eval, max_steps, int(min(counts[2] + n, max_steps)), y, f0,
                    Y, fs, counts)

    code = run_in_chunks(chunk)
    n_out = int(counts[0])
    return LoopResult(LoopStatus.INTERRUPTED if code is None else LoopStatus.from_code(int(code)),
                      t_eval[:n_out].copy(), Y[:n_out].copy(), float(fs[0]), y.copy(), int(counts[1]),
                      int(counts[2]), int(counts[3]))


def run_in_chunks(chunk: Callable[[int], int], first: int = 16) -> int | None:
    """Run a compiled loop in chunks of bounded work until it ends; its status, or None after Ctrl-C.

    ``chunk(n)`` runs at most ``n`` more units of work (accepted steps) of a loop whose whole state lives
    in arrays it updates in place, and returns :data:`PAUSED` when there is more to do. ``n`` adapts so a
    chunk takes about :data:`CHUNK_SECONDS`: numba code cannot check for signals, so Python's SIGINT handler
    (which only sets a flag) is acted on between chunks, and a KeyboardInterrupt raised there leaves the
    state of the last finished chunk intact, for the caller to report. A chunk ends only after a whole
    step, so the result is bit-identical to one uninterrupted call.
    """
    n = first
    try:
        while True:
            start = time.perf_counter()
            status = chunk(n)
            if status != PAUSED:
                return status
            elapsed = time.perf_counter() - start
            n = max(1, min(8 * n, int(n * CHUNK_SECONDS / elapsed) if elapsed > 0 else 8 * n))
    except KeyboardInterrupt:
        return None


def integrate_compiled(model: NumericModel, method: str, t_span, y0, t_eval, *, rtol: float, atol: float,
                       max_step: float = np.inf, label: str | None = None, max_steps: int = MAX_STEPS
                       ) -> Trajectory:
    """Integrate ``model`` from ``y0 = [q, q̇]`` with the compiled loop and return the Trajectory.

    Non-conservative systems carry the work integral ∫ dh/dt dt as an extra state (same tolerances as
    the scipy path). ``label`` is the Trajectory's ``method`` (default ``"<method> (compiled loop)"``).

    Raises
    ------
    IntegrationError
        The loop stopped early (:class:`LoopStatus`); ``t``, ``state`` and ``partial`` say where and
        what was computed.
    IntegrationInterrupted
        Ctrl-C (acted on between chunks, :func:`run_in_chunks`); the same ``t``, ``state`` and ``partial``
        (the output times reached, then the state reached).
    """
    eqs = model.equations
    n2 = 2 * eqs.n
    conservative = eqs.is_conservative
    y0 = np.asarray(y0, dtype=float)
    z0 = y0 if conservative else np.append(y0, 0.0)
    res = run_loop(model, method, t_span, z0, t_eval, rtol=rtol, atol=atol, max_step=max_step,
                   max_steps=max_steps)
    ok = res.status is LoopStatus.SUCCESS
    if res.status is LoopStatus.INTERRUPTED:  # the output times reached, then the state reached
        message = f"interrupted by Ctrl-C at t={res.t_reached:.9g} ({res.steps} steps)"
        if not len(res.t) or res.t[-1] != res.t_reached:
            res = dataclasses.replace(res, t=np.append(res.t, res.t_reached),
                                      z=np.vstack([res.z.reshape(len(res.t), -1), res.z_reached]))
    else:
        message = f"{res.status.message if ok else 'stopped early'} ({res.steps} steps, {res.rejected} rejected)"
    traj = Trajectory(t=res.t, y=res.z[:, :n2].copy(), model=model, method=label or f"{method} (compiled loop)",
                      success=ok, message=message, nfev=res.nfev,
                      work=None if conservative else res.z[:, n2].copy(), initial=(float(t_span[0]), y0.copy()))
    if ok:
        return traj
    if res.status is LoopStatus.INTERRUPTED:
        raise interrupted_error(f"the compiled {method} loop", res.t_reached, res.z_reached, traj)
    raise stopped_error(f"the compiled {method} loop", res.status, res.t_reached, res.z_reached, traj)


def stopped_error(what: str, status: LoopStatus, t_reached: float, z_reached, partial: Trajectory
                  ) -> IntegrationError:
    """The IntegrationError of a compiled run that ended with ``status`` at ``(t_reached, z_reached)``:
    where, in which state, why, and ``partial`` (the trajectory up to there)."""
    coords = partial.model.equations.coordinates
    return IntegrationError(
        f"{what} stopped at t={t_reached:.9g} ({state_text(coords, z_reached)}): {status.message}. The "
        f"trajectory up to there ({len(partial.t)} output points) is in the exception's `partial` attribute.",
        t=float(t_reached), state=dict(zip(coords, np.asarray(z_reached)[:2 * len(coords)])), partial=partial)


def interrupted_error(what: str, t_reached: float, z_reached, partial: Trajectory) -> IntegrationInterrupted:
    """The :class:`~lagrange.errors.IntegrationInterrupted` of a run stopped by Ctrl-C at ``(t_reached,
    z_reached)``, carrying ``partial`` (the trajectory up to there)."""
    coords = partial.model.equations.coordinates
    return IntegrationInterrupted(
        f"{what} was interrupted (Ctrl-C) at t={t_reached:.9g} ({state_text(coords, z_reached)}); the trajectory "
        f"up to there ({len(partial.t)} output points) is in the exception's `partial` attribute.",
        t=float(t_reached), state=dict(zip(coords, np.asarray(z_reached)[:2 * len(coords)])), partial=partial)


def check_output_times(t_eval, t0: float, t1: float) -> np.ndarray:
    """``t_eval`` as a contiguous float array, checked as scipy checks it (one-dimensional, within
    ``[t0, t1]``, sorted in the direction of integration); ValueError worded as scipy's."""
    t_eval = np.ascontiguousarray(t_eval, dtype=float)
    if t_eval.ndim != 1:
        raise ValueError("t_eval must be 1-dimensional")
    if not t_eval.size:
        return t_eval
    lo, hi = min(t0, t1), max(t0, t1)
    # NaN fails every comparison: "not within" (as scipy's any(t_eval < lo) would miss it, it must not pass)
    if t_eval.size == 1:  # the common single output time, without array reductions
        if not lo <= float(t_eval[0]) <= hi:
            raise ValueError("Values in `t_eval` are not within `t_span`.")
        return t_eval
    if not (t_eval.min() >= lo and t_eval.max() <= hi):
        raise ValueError("Values in `t_eval` are not within `t_span`.")
    d = np.diff(t_eval)
    if (t1 > t0 and not d.min() > 0) or (t1 < t0 and not d.max() < 0):
        raise ValueError("Values in `t_eval` are not properly sorted.")
    return t_eval
