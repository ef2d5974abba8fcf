r"""``simulate(..., method="taylor")``: an adaptive Taylor integrator with no per-model compilation.

The model's right-hand side is translated into a tape (:mod:`lagrange.codegen.tape`, milliseconds) and
run by an interpreter compiled once per machine — in C by the system's compiler
(:mod:`lagrange.integrate.c_taylor`, loaded in a millisecond) or, without one, by numba
(:mod:`lagrange.integrate._taylor_loop`, cached on disk like the DOP853/RK45 loops; its first call in a
process costs about 0.2 s): the time to a first result is the derivation, the tape and the integration —
nothing is generated or JIT-compiled per model. Taylor coefficients come from automatic differentiation
(each instruction of order k costs O(k), which amortizes the interpretation), the order follows the
tolerance (``p = ceil(−ln(rtol)/2 + 1)``: 13 at 1e-10, 20 at machine precision) and the step follows the
last two coefficients (Jorba & Zou 2005, the scheme heyoka uses), so there are no rejected steps and the
output at ``t_eval`` is the Taylor polynomial of the step that holds it.

Tolerance: ``rtol`` is the ε of the step-size rule; ``atol/rtol`` is the state size below which the error
criterion is absolute (Jorba & Zou's mixed criterion for ``atol = rtol``). As with any local criterion the
global error can exceed ε on long or chaotic runs (compare runs at two tolerances).

Two ways to run the tape, same arithmetic, same results: the interpreter (any model; nothing compiled
per model; its C and numba builds are transcriptions of each other) and, for a model built with
``backend="numba"``, the tape written out as straight-line code
(:mod:`lagrange.codegen.taylor_source`) and JIT-compiled once per model (cached on disk) — faster per step,
for long runs and repeated runs. Small systems get it written out for the run's order (every sum term by
term, one compile per model and order); larger ones keep loops over the order. ``Trajectory.nfev`` counts
tape passes (steps × order).

Scope: unconstrained systems whose equations are analytic (no ``sign``/``Abs``/``Piecewise``); the work
integral of non-conservative systems is integrated with the state. Needs a C compiler or numba
(``pip install "lagrange-dynamics[fast]"``); the compiled series needs numba.
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from ..codegen.numeric import NumericModel
from ..codegen.tape import Tape, build_tape
from ..errors import BackendError
from ..results.trajectory import Trajectory
from .compiled import MAX_STEPS, LoopStatus, check_output_times, first_class, kernel, stopped_error

__all__ = ["taylor_order", "tape_of", "compiled_series", "interpreter", "available_interpreter",
           "integrate_taylor"]

_EPS = float(np.finfo(float).eps)
_TAPES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SERIES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def taylor_order(rtol: float) -> int:
    """Jorba & Zou's order for tolerance ε: ``ceil(−ln(ε)/2 + 1)``, at least 2 (13 at 1e-10, 20 at 2.2e-16)."""
    return max(2, math.ceil(-math.log(rtol) / 2 + 1))


def tape_of(eqs) -> Tape:
    """The tape of ``eqs``, built once per Equations (equal equations share it)."""
    if eqs not in _TAPES:
        _TAPES[eqs] = build_tape(eqs)
    return _TAPES[eqs]


def compiled_series(tape: Tape, order: int | None = None):
    """The tape's straight-line ``series`` (:mod:`lagrange.codegen.taylor_source`), compiled by numba once per
    model and cached on disk like the other generated modules: written out for ``order`` when that stays
    within :data:`~lagrange.codegen.taylor_source.UNROLL_TERMS` terms, else the loop form (any order)."""
    cached = _SERIES.setdefault(tape, {})  # order (None: the loop form) -> compiled series
    if order not in cached:
        from ..codegen.numba_backend import load_cached
        from ..codegen.taylor_source import UNROLL_TERMS, series_source, unrolled_source, unrolled_terms

        if order is not None and unrolled_terms(tape, order) <= UNROLL_TERMS:
            cached[order] = load_cached("taylor", unrolled_source(tape, order), "the Taylor series module").series
        else:
            cached[order] = cached[None] = cached.get(None) or load_cached("taylor", series_source(tape),
                                                                          "the Taylor series module").series
    return cached[order]


def interpreter(engine: str = "auto") -> str:
    """Who interprets the tape of a model not built with numba: ``"c"`` (:mod:`lagrange.integrate.c_taylor`,
    preferred: it loads in a millisecond where numba's first call costs 0.2 s) or ``"numba"``
    (:mod:`lagrange.integrate._taylor_loop`); ``engine="auto"`` picks C when it builds here.

    Raises :class:`~lagrange.errors.BackendError` when neither is available (or the one asked for is not).
    """
    from . import c_taylor
    from .compiled import _numba_available

    if engine not in ("auto", "c", "numba"):
        raise ValueError(f"engine must be 'auto', 'c' or 'numba', got {engine!r}")
    if engine in ("auto", "c") and c_taylor.library() is not None:
        return "c"
    if engine == "c":
        raise BackendError(f"the C Taylor interpreter is unavailable: {c_taylor.unavailable_reason()}")
    if _numba_available():
        return "numba"
    raise BackendError("method='taylor' needs a C compiler or numba (`pip install \"lagrange-dynamics[fast]\"`); C: "
                       f"{c_taylor.unavailable_reason()}")


def available_interpreter() -> str | None:
    """:func:`interpreter` (``"c"`` or ``"numba"``), or None when neither can run a tape here."""
    try:
        return interpreter()
    except BackendError:
        return None


def integrate_taylor(model: NumericModel, t_span, y0, t_eval, *, rtol: float, atol: float,
                     max_step: float = np.inf, max_steps: int = MAX_STEPS, label: str | None = None,
                     engine: str = "auto") -> Trajectory:
    """Integrate ``model`` from ``y0 = [q, q̇]`` with the Taylor method (module docstring). A model built with
    ``backend="numba"`` runs its compiled series; any other is interpreted by ``engine``
    (:func:`interpreter`).

    Raises
    ------
    TapeError
        Constraints or a non-analytic function in the equations (named).
    BackendError
        No way to run the tape here (no C compiler and no numba).
    IntegrationError
        The run stopped early (singular mass matrix, non-finite coefficients, collapsed step, too many
        steps); ``t``, ``state`` and ``partial`` say where and what was computed.
    """
    tape = tape_of(model.equations)
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
    if model.backend == "numba":
        k = kernel("_taylor_loop.py", "taylorloop", "method='taylor'")
        code, t_end, z_end, Y, n_out, steps = k.entry("taylor_fn")(
            first_class(compiled_series(tape, order), k.SERIES), tape.const_code, tape.const_vals, tape.n_slots,
            tape.n, tape.nz, t0, t1, z0, p, atol / rtol, order, max_step, t_eval, int(max_steps))
    elif interpreter(engine) == "c":
        from .c_taylor import library

        code, t_end, z_end, Y, n_out, steps = library().run(tape, t0, t1, z0, p, atol / rtol, order, max_step, t_eval,
                                                            int(max_steps))
    else:
        k = kernel("_taylor_loop.py", "taylorloop", "method='taylor'")
        code, t_end, z_end, Y, n_out, steps = k.entry("taylor")(
            tape.const_code, tape.const_vals, tape.code, tape.consts, tape.n_slots, tape.n, tape.nz, tape.mass,
            tape.force, tape.power, tape.slot_t, t0, t1, z0, p, atol / rtol, order, max_step, t_eval, int(max_steps))
    status = LoopStatus.from_code(int(code))
    n2 = 2 * tape.n
    Y = np.array(Y[:n_out])
    ok = status is LoopStatus.SUCCESS
    message = (f"{status.message if ok else 'stopped early'} ({steps} Taylor steps of order {order}, "
               f"tape of {tape.size} instructions)")
    traj = Trajectory(t=t_eval[:n_out].copy(), y=Y[:, :n2].copy(), model=model,
                      method=label or f"taylor (order {order})", success=ok, message=message,
                      nfev=int(steps) * order, work=None if tape.nz == n2 else Y[:, n2].copy(),
                      initial=(t0, y0.copy()))
    if ok:
        return traj
    raise stopped_error("the Taylor method", status, t_end, np.array(z_end), traj)
