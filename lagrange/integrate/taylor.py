r"""``simulate(..., method="taylor")``: an adaptive Taylor integrator with no per-model compilation.

The model's right-hand side is translated into a tape (:mod:`lagrange.codegen.tape`, milliseconds) and
run by the interpreter in C (:mod:`lagrange.integrate.c_taylor`: the extension module built at install time,
else a library built once per machine; it loads in a millisecond): the time to a first result is the
derivation, the tape and the integration — nothing is generated or compiled per model. Taylor coefficients
come from automatic differentiation (each instruction of order k costs O(k), which amortizes the
interpretation), the order follows the tolerance (``p = ceil(−ln(rtol)/2 + 1)``: 13 at 1e-10, 20 at machine
precision) and the step follows the last two coefficients (Jorba & Zou 2005, the scheme heyoka uses), so
there are no rejected steps and the output at ``t_eval`` is the Taylor polynomial of the step that holds it.

Tolerance: ``rtol`` is the ε of the step-size rule; ``atol/rtol`` is the state size below which the error
criterion is absolute (Jorba & Zou's mixed criterion for ``atol = rtol``). As with any local criterion the
global error can exceed ε on long or chaotic runs (compare runs at two tolerances).

Two ways to run the tape (docs/guide.md, "The Taylor method: what is kept and why"): the C interpreter (any
model, nothing compiled per model) and, for a model built with ``backend="numba"`` — or when no C interpreter
is available —, the tape written out as straight-line code (:mod:`lagrange.codegen.taylor_source`) and
JIT-compiled once per model (cached on disk): faster per step, for long and repeated runs.
``Trajectory.nfev`` counts tape passes (steps × order).

Interrupts: the run proceeds in chunks of about :data:`CHUNK_SECONDS` of wall time; Ctrl-C (SIGINT) is
answered between chunks with an :class:`~lagrange.errors.IntegrationInterrupted` (a ``KeyboardInterrupt``)
whose ``partial`` attribute holds the trajectory up to there. Chunks do not change the result (a chunk
resumes from the exact state and time where the last one stopped).

Scope: unconstrained systems whose equations are analytic (no ``sign``/``Abs``/``Piecewise``); the work
integral of non-conservative systems is integrated with the state. Needs a C compiler (at install or at run
time) or numba (``pip install "lagrange-dynamics[fast]"``).

The tape, the compiled series and the C library are produced by :mod:`lagrange.codegen` and reached through
the compiled model (:meth:`~lagrange.codegen.numeric.NumericModel.taylor_tape`, ``taylor_series``,
``taylor_interpreter``); this module only runs them.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ..codegen.numeric import NumericModel
from ..errors import BackendError, InputError
from ..results.trajectory import Trajectory
from .compiled import (
    MAX_STEPS,
    LoopStatus,
    check_output_times,
    first_class,
    interrupted_error,
    kernel,
    stopped_error,
)

__all__ = ["taylor_order", "interpreter", "available_interpreter", "integrate_taylor", "restarter", "CHUNK_SECONDS",
           "ENGINES"]

_EPS = float(np.finfo(float).eps)
#: wall time of one uninterrupted chunk of a run (Ctrl-C is answered between chunks)
CHUNK_SECONDS = 0.1
_FIRST_CHUNK = 64  # steps; later chunks are sized from the measured time per step
#: the ways to run a tape: ``"c"`` (the interpreter), ``"series"`` (the compiled series, numba)
ENGINES = ("auto", "c", "series")
_MAX_STEPS_CODE = LoopStatus.MAX_STEPS.value[0]


def taylor_order(rtol: float) -> int:
    """Jorba & Zou's order for tolerance ε: ``ceil(−ln(ε)/2 + 1)``, at least 2 (13 at 1e-10, 20 at 2.2e-16)."""
    return max(2, math.ceil(-math.log(rtol) / 2 + 1))


def _c_library():
    """The loaded C interpreter, or the reason there is none (str)."""
    from . import c_taylor

    path, reason = NumericModel.taylor_interpreter()
    if path is None:
        return reason
    try:
        return c_taylor.load(path)
    except (OSError, AttributeError) as exc:  # verified, yet not a loadable library of ours
        return f"the C interpreter {path} does not load: {exc}"


def interpreter(engine: str = "auto", *, backend: str = "python") -> str:
    """How a model's tape runs here: ``"c"`` (the C interpreter, preferred for a model of any backend but
    numba: it loads in a millisecond and compiles nothing per model) or ``"series"`` (the compiled series:
    the default for ``backend="numba"`` models, and the fallback without a C interpreter when numba is
    installed — one JIT compile per model, cached on disk).

    Raises
    ------
    ValueError
        ``engine`` is not one of :data:`ENGINES`.
    BackendError
        The engine asked for is not available here, or neither is (no C compiler and no numba).
    """
    from .compiled import _numba_available

    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {', '.join(map(repr, ENGINES))}, got {engine!r} (the numba "
                         "interpreter was retired: 'series' runs the compiled series with numba)")
    if engine == "series" or (engine == "auto" and backend == "numba"):
        if not _numba_available():
            raise BackendError("the compiled Taylor series needs numba: pip install \"lagrange-dynamics[fast]\"")
        return "series"
    found = _c_library()
    if not isinstance(found, str):
        return "c"
    if engine == "c":
        raise BackendError(f"the C Taylor interpreter is unavailable: {found}")
    if _numba_available():
        return "series"
    raise BackendError("method='taylor' needs a C compiler (at install or at run time) or numba "
                       f"(`pip install \"lagrange-dynamics[fast]\"`); C: {found}")


def available_interpreter() -> str | None:
    """:func:`interpreter` for a python-backend model (``"c"`` or ``"series"``), or None when neither can run
    a tape here."""
    try:
        return interpreter()
    except BackendError:
        return None


class _Chunks:
    """Runs a tape engine in chunks of about :data:`CHUNK_SECONDS`, so Ctrl-C is answered between them."""

    def __init__(self, max_steps: int):
        self.left = int(max_steps)
        self.size = _FIRST_CHUNK

    def next_size(self) -> int:
        return max(1, min(self.size, self.left))

    def record(self, steps: int, seconds: float) -> None:
        self.left -= steps
        if steps:
            per_step = max(seconds, 1e-9) / steps
            self.size = int(min(max(CHUNK_SECONDS / per_step, 1), 4 * self.size + 1, 10**7))


def _reraise_interrupt(exc: BaseException) -> None:
    """Raise KeyboardInterrupt when ``exc`` was caused by one: numba's boxing of a compiled call's results runs
    Python code, and a Ctrl-C handled there comes back as ``SystemError`` (the chunk's results are lost; the
    partial trajectory is the one before the chunk)."""
    seen = exc.__cause__ or exc.__context__
    while seen is not None:
        if isinstance(seen, KeyboardInterrupt):
            raise KeyboardInterrupt from exc
        seen = seen.__cause__ or seen.__context__


def _run(engine: str, model: NumericModel, tape, t0, t1, z0, p, floor, order, max_step, t_eval, max_steps):
    """``(status, t reached, z reached, Y, n_out, steps)``: the whole run, in interruptible chunks. On
    KeyboardInterrupt the exception carries ``_lagrange_partial = (t, z, Y, n_out, steps)``."""
    if engine == "c":
        lib = _c_library()

        def chunk(t, z, first, n):
            status, t_new, z_new, k, steps = lib.run(tape, t, t1, z, p, floor, order, max_step, t_eval[first:],
                                                     n, Y[first:])
            return status, t_new, z_new, k, steps
    else:
        k = kernel("_taylor_loop.py", "taylorloop", "method='taylor'")
        fn = k.entry("taylor_fn")
        series = first_class(model.taylor_series(order), k.SERIES)

        def chunk(t, z, first, n):
            try:
                status, t_new, z_new, Yc, k_out, steps = fn(series, tape.const_code, tape.const_vals, tape.n_slots,
                                                            tape.n, tape.nz, t, t1, z, p, floor, order, max_step,
                                                            t_eval[first:], n)
            except SystemError as exc:  # Ctrl-C's handler ran inside numba's boxing (Python code): unwrap it
                _reraise_interrupt(exc)
                raise
            Y[first:first + k_out] = Yc[:k_out]
            return status, t_new, z_new, k_out, steps

    Y = np.empty((t_eval.size, tape.nz))
    chunks = _Chunks(max_steps)
    t, z, n_out, steps = t0, z0, 0, 0
    try:
        while True:
            n = chunks.next_size()
            start = time.perf_counter()
            status, t, z, k_out, done = chunk(t, np.ascontiguousarray(z), n_out, n)
            chunks.record(done, time.perf_counter() - start)
            n_out += k_out
            steps += done
            if status != _MAX_STEPS_CODE or chunks.left <= 0:
                return status, t, z, Y, n_out, steps
    except KeyboardInterrupt as exc:
        exc._lagrange_partial = (t, z, Y, n_out, steps)
        raise


def integrate_taylor(model: NumericModel, t_span, y0, t_eval, *, rtol: float, atol: float,
                     max_step: float = np.inf, max_steps: int = MAX_STEPS, label: str | None = None,
                     engine: str = "auto") -> Trajectory:
    """Integrate ``model`` from ``y0 = [q, q̇]`` with the Taylor method (module docstring). A model built with
    ``backend="numba"`` runs its compiled series; any other is interpreted in C (``engine``: see
    :func:`interpreter`).

    Raises
    ------
    TapeError
        Constraints or a non-analytic function in the equations (named).
    BackendError
        No way to run the tape here (no C compiler and no numba).
    InputError
        The model has time-varying inputs (a schedule): the tape holds inputs as constants.
    IntegrationError
        The run stopped early (singular mass matrix, non-finite coefficients, collapsed step, too many
        steps); ``t``, ``state`` and ``partial`` say where and what was computed.
    IntegrationInterrupted
        Ctrl-C (a KeyboardInterrupt), answered within about :data:`CHUNK_SECONDS`; its ``partial`` attribute
        is the trajectory up to there, ``t`` and ``state`` where the run stopped.
    """
    if model.schedule is not None:  # the tape holds the inputs as constants: never run as if they were absent
        raise InputError("method='taylor' cannot follow time-varying inputs (the model has a schedule; constant "
                         "inputs are parameters): use method='DOP853' or another scipy method")
    tape = model.taylor_tape()
    t0, t1 = float(t_span[0]), float(t_span[1])
    rtol, atol, max_step = float(rtol), float(atol), float(max_step)
    if not (rtol > 0 and math.isfinite(rtol)):
        raise ValueError(f"the Taylor method needs rtol > 0, got {rtol}")
    if not (atol > 0 and math.isfinite(atol)):
        raise ValueError(f"the Taylor method needs atol > 0 (atol/rtol is the absolute-criterion scale), got {atol}")
    if not max_step > 0:
        raise ValueError("max_step must be positive")
    rtol = max(rtol, _EPS)
    t_eval = check_output_times(t_eval, t0, t1)
    y0 = np.asarray(y0, dtype=float)
    z0 = np.ascontiguousarray(y0 if tape.nz == y0.size else np.append(y0, 0.0))
    order = taylor_order(rtol)
    p = np.ascontiguousarray(model.params, dtype=float)
    how = interpreter(engine, backend=model.backend)
    try:
        code, t_end, z_end, Y, n_out, steps = _run(how, model, tape, t0, t1, z0, p, atol / rtol, order, max_step,
                                                   t_eval, int(max_steps))
    except KeyboardInterrupt as exc:
        # interrupted while the engine was being loaded or compiled, nothing integrated yet: an empty partial
        nothing = (t0, z0, np.empty((t_eval.size, tape.nz)), 0, 0)
        t_end, z_end, Y, n_out, steps = getattr(exc, "_lagrange_partial", nothing)
        partial = _trajectory(model, tape, t_eval, Y, n_out, y0, t0, label, order, steps,
                              f"interrupted (Ctrl-C) at t={t_end:.9g}", False)
        raise interrupted_error("the Taylor method", t_end, np.array(z_end), partial) from exc
    status = LoopStatus.from_code(int(code))
    ok = status is LoopStatus.SUCCESS
    message = (f"{status.message if ok else 'stopped early'} ({steps} Taylor steps of order {order}, "
               f"tape of {tape.size} instructions)")
    traj = _trajectory(model, tape, t_eval, Y, n_out, y0, t0, label, order, steps, message, ok)
    if ok:
        return traj
    raise stopped_error("the Taylor method", status, t_end, np.array(z_end), traj)


def _trajectory(model, tape, t_eval, Y, n_out, y0, t0, label, order, steps, message, ok) -> Trajectory:
    n2 = 2 * tape.n
    Y = np.array(Y[:n_out])
    return Trajectory(t=t_eval[:n_out].copy(), y=Y[:, :n2].copy(), model=model,
                      method=label or f"taylor (order {order})", success=ok, message=message,
                      nfev=int(steps) * order, work=None if tape.nz == n2 else Y[:, n2].copy(),
                      initial=(t0, y0.copy()))


def restarter(model: NumericModel, *, rtol: float, atol: float, engine: str = "auto"):
    """``(restart, order)``: ``restart(t, z, t_end, max_step, max_steps) -> (t reached, z reached)`` runs the
    same engine, order and tolerance as :func:`integrate_taylor` from the state ``z`` (``[q, q̇]`` and, for a
    non-conservative system, the work integral) for at most ``max_steps`` steps towards ``t_end``; the checks of
    :mod:`lagrange.integrate.taylor_checks` restart a run with it."""
    tape = model.taylor_tape()
    rtol = max(float(rtol), _EPS)
    order = taylor_order(rtol)
    p = np.ascontiguousarray(model.params, dtype=float)
    how = interpreter(engine, backend=model.backend)
    none, floor = np.empty(0), float(atol) / rtol
    lib = _c_library() if how == "c" else None  # (found and verified once, not per restart)

    def restart(t, z, t_end, max_step, max_steps):
        z = np.ascontiguousarray(z, dtype=float)
        if lib is not None:
            _, t_new, z_new, _, _ = lib.run(tape, float(t), float(t_end), z, p, floor, order, float(max_step), none,
                                            int(max_steps), np.empty((0, tape.nz)))
        else:
            _, t_new, z_new, *_ = _run(how, model, tape, float(t), float(t_end), z, p, floor, order,
                                       float(max_step), none, int(max_steps))
        return float(t_new), np.asarray(z_new, dtype=float)

    return restart, order
