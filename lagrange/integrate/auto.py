r"""``method="auto"``: choose an adaptive method of the registry from cheap numerical estimates.

The decision costs a few right-hand-side evaluations of the compiled model (which the run builds anyway, and
which :func:`lagrange.codegen.numeric.NumericModel.build` keeps in memory): no symbolic Jacobian is built to
test stiffness.

1. **Candidates.** Only the adaptive methods of :data:`~lagrange.integrate.registry.METHODS` whose entry covers
   everything the request needs (events, holonomic and non-holonomic constraints, friction switches, rough
   constraints, constant or time-varying inputs, dense output) are considered; the Taylor method also needs
   analytic unconstrained equations and a tape interpreter (:func:`~lagrange.integrate.taylor_run.taylor_ready`).
2. **Stiffness estimate.** The Jacobian :math:`J = \partial f/\partial y` of the compiled right-hand side at
   the initial state by finite differences (:func:`estimate_stiffness`: forward and backward differences, the
   smaller one kept across a ``sign()`` switch), then its eigenvalues :math:`\lambda`: the fastest decay rate
   :math:`\mu = \max(-\operatorname{Re}\lambda)` and the stiffness ratio :math:`\mu / \min|\lambda \ne 0|`.
   The problem is *stiff for explicit methods* when :math:`\mu T > 10^3` and the ratio exceeds :math:`10^3`
   (:math:`T` the horizon): an explicit Runge–Kutta method then takes about :math:`\mu T / 3` steps whatever
   the tolerance.
3. **Cost estimates** (seconds, :func:`taylor_seconds` and :func:`implicit_seconds`; constants measured on
   the stiff benchmark problem, ``benchmarks/auto_choice.py``): the Taylor method's steps are limited by its
   stability interval, about :math:`p/2` for order :math:`p`, so it needs about :math:`2\mu T` tape passes,
   each costing about ``tape.size`` × 23 ns × :math:`p/12`. An implicit scipy method (LSODA) costs about 0.15 s
   × (n/2)² on this machine's scale (its generated Jacobian is built symbolically, then about a thousand steps
   run in Python). The cheaper one wins.
4. **Choice.**

   * stiff, Taylor cheaper → ``taylor`` (moderately stiff problems with a smooth slow motion: 5–20× faster than
     LSODA on the damped double pendulum at c = 10³);
   * stiff otherwise → ``LSODA`` (BDF when stiff, with the generated Jacobian), or ``Radau`` when the request
     keeps holonomic constraints by projection (LSODA would fall back to Baumgarte stabilization);
   * not stiff → ``taylor`` with the python backend when its tape interpreter is built in C (its steps run
     compiled, scipy's DOP853 steps in Python), or at ``rtol ≤ 1e-11`` with any backend; else ``DOP853``.

The reason is returned with the name; the run records it in the trajectory's ``method`` label
(``"taylor (interpreted tape, c; auto: ...)"``), which ``lagrange simulate`` prints.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import LagrangeError
from . import registry

__all__ = ["Stiffness", "estimate_stiffness", "taylor_seconds", "implicit_seconds", "candidates", "choose"]

#: μ T above which explicit methods are stability-limited, and the stiffness ratio above which this is stiffness
STIFF_STEPS = 1e3
STIFF_RATIO = 1e3
#: eigenvalues below this fraction of the spectral radius are not resolved by the finite differences
RESOLUTION = 1e-8
#: seconds per tape instruction per Taylor pass at order 12 (C interpreter; measured, benchmarks/auto_choice.py)
TAPE_SECONDS = 23e-9
#: one implicit scipy run (LSODA with its generated Jacobian) on a 2-DOF system, seconds (measured likewise)
IMPLICIT_SECONDS = 0.15
#: the compiled series (numba backend) runs a pass about 3× faster than the C interpreter but JIT-compiles first
SERIES_SPEEDUP, SERIES_JIT_SECONDS = 3.0, 0.1


@dataclass(frozen=True, slots=True)
class Stiffness:
    """Eigenvalue estimates of the Jacobian of ``f`` at one state.

    Attributes
    ----------
    decay : fastest decay rate max(−Re λ) (1/time; 0 when no mode decays)
    radius : spectral radius max |λ|
    ratio : decay / slowest nonzero |λ| (1 when every eigenvalue is zero)
    rhs_seconds : wall time of one evaluation of ``f`` (measured while differencing)
    """

    decay: float
    radius: float
    ratio: float
    rhs_seconds: float

    def is_stiff(self, horizon: float) -> bool:
        """Stiff for explicit methods over ``horizon``: μ·T > 10³ and a stiffness ratio > 10³."""
        return self.decay * horizon > STIFF_STEPS and self.ratio > STIFF_RATIO


def estimate_stiffness(fun: Callable, t0: float, y0: np.ndarray) -> Stiffness | None:
    r"""Eigenvalues of the finite-difference Jacobian of ``fun(t, y) -> (2n,)`` at ``(t0, y0)``.

    Column :math:`j` is the forward difference :math:`(f(y + h e_j) − f(y))/h` with
    :math:`h = \sqrt{\varepsilon}\max(1, |y_j|)`, checked against the forward difference over :math:`2h`; where
    they disagree (a ``sign()`` switch at ``y``, which would read as a huge rate) the differences on each side
    of the switch, the smaller one kept. 4n + 1 evaluations (two more per switched column). Eigenvalues below 1e-8 × the
    spectral radius are not resolved: the stiffness ratio is at most 1e8.

    Returns None when ``fun`` fails (singular mass matrix, a domain error) or gives non-finite values: the
    caller then decides without the estimate and the run reports the fault.

    >>> st = estimate_stiffness(lambda t, y: np.array([y[1], -1e4 * y[0] - 1e3 * y[1]]), 0.0, np.zeros(2))
    >>> round(st.decay), round(st.ratio)
    (990, 98)
    """
    y0 = np.asarray(y0, dtype=float)
    start = time.perf_counter()
    try:
        J, calls = _jacobian(fun, float(t0), y0)
        seconds = (time.perf_counter() - start) / calls
        if not np.all(np.isfinite(J)):
            return None
        lam = np.linalg.eigvals(J)
    except (LagrangeError, ArithmeticError, ValueError, TypeError, np.linalg.LinAlgError):
        return None
    mags = np.abs(lam)
    radius = float(np.max(mags, initial=0.0))
    decay = float(np.max(-lam.real, initial=0.0)) + 0.0  # no -0.0
    # below about 1e-8 × radius an eigenvalue is not resolved by the differences: count it as that
    slow = max(float(np.min(mags)) if mags.size else 0.0, RESOLUTION * radius)
    return Stiffness(decay, radius, decay / slow if decay and slow else 1.0, seconds)


def _jacobian(fun: Callable, t0: float, y0: np.ndarray) -> tuple[np.ndarray, int]:
    """The difference Jacobian at ``y0`` and the number of evaluations of ``fun`` it took.

    Forward differences with ``h``, checked against forward differences over ``2h``; in a column where they
    disagree (a jump at ``y0``, e.g. ``sign(v)`` at v = 0, makes difference quotients scale as 1/h) the
    differences are taken on each side of the jump (between ``y0 ± h`` and ``y0 ± 2h``), the smaller kept."""
    size = y0.size
    h = math.sqrt(np.finfo(float).eps) * np.maximum(1.0, np.abs(y0))
    E = np.diag(h)

    def values(states) -> np.ndarray:  # row i: f at states[i]
        return np.array([np.asarray(fun(t0, y), dtype=float)[:size] for y in states]).reshape(len(states), size)

    f0 = values(y0[None, :])[0]
    fp, f2 = values(y0 + E), values(y0 + 2 * E)
    J = ((fp - f0) / h[:, None]).T
    wide = ((f2 - f0) / (2 * h[:, None])).T
    scale = np.maximum(np.maximum(np.linalg.norm(J, axis=0), np.linalg.norm(wide, axis=0)), 1.0)
    jumps = np.flatnonzero(np.linalg.norm(J - wide, axis=0) > 1e-3 * scale)
    calls = 1 + 2 * size + 2 * len(jumps)
    for j in jumps:
        fm, f_2 = values(np.stack([y0 - E[j], y0 - 2 * E[j]]))
        J[:, j] = min((f2[j] - fp[j]) / h[j], (fm - f_2) / h[j], key=np.linalg.norm)
    return J, calls


def taylor_seconds(stiffness: Stiffness, horizon: float, tape_size: int, order: int, *,
                   compiled_series: bool = False) -> float:
    r"""Estimated run time of the Taylor method limited by stability: about :math:`2\mu T` passes (steps of
    :math:`p/(2\mu)`, the stability interval of the order-:math:`p` Taylor polynomial, times :math:`p` passes
    per step), each ``tape_size`` instructions at :data:`TAPE_SECONDS` × p/12.

    >>> round(taylor_seconds(Stiffness(3.9e3, 3.9e3, 1e6, 1e-6), 10.0, 19, 12), 3)
    0.034
    """
    passes = 2.0 * stiffness.decay * horizon
    seconds = passes * tape_size * TAPE_SECONDS * order / 12
    return seconds / SERIES_SPEEDUP + SERIES_JIT_SECONDS if compiled_series else seconds


def implicit_seconds(n: int) -> float:
    """Estimated first-result time of LSODA with its generated Jacobian for ``n`` coordinates (the symbolic
    Jacobian grows about as n²): :data:`IMPLICIT_SECONDS` × (n/2)².

    >>> implicit_seconds(2)
    0.15
    """
    return IMPLICIT_SECONDS * max(1.0, (n / 2) ** 2)


def candidates(needs: dict[str, str]) -> tuple[str, ...]:
    """The adaptive methods of the registry that cover ``needs`` (keys of
    :data:`~lagrange.integrate.registry.FEATURES`), in table order; heyoka only when asked for by name.

    >>> candidates({"events": "1 event function"})
    ('DOP853', 'RK45', 'RK23', 'LSODA', 'Radau', 'BDF')
    >>> "taylor" in candidates({})
    True
    """
    return tuple(m.name for m in registry.METHODS
                 if m.adaptive and m.name != "heyoka" and all(getattr(m, f) for f in needs))


@dataclass(frozen=True, slots=True)
class _Context:
    """What :func:`choose` knows about the request."""

    n: int
    horizon: float
    rtol: float
    backend: str
    projection: bool


def choose(eqs, fun: Callable | None, t0: float, y0, *, t_end: float, rtol: float, backend: str,
           needs: dict[str, str], projection: bool = False) -> tuple[str, str]:
    """The method for ``method="auto"`` and the reason (see the module docstring).

    Parameters
    ----------
    eqs : the derived Equations (friction treatment applied)
    fun : ``fun(t, y) -> dy/dt`` of the compiled model with the run's parameters (None: no stiffness estimate)
    t0, t_end : the horizon; y0 : the initial state, shape (2n,)
    rtol : the run's relative tolerance; backend : the model's backend
    needs : the registry features the request needs (:func:`lagrange.integrate.run._needs`)
    projection : holonomic constraints kept by projection (prefer a method that projects)

    Raises
    ------
    MethodError
        No adaptive method covers ``needs`` (the registry's message names the combination).
    """
    allowed = candidates(needs)
    if not allowed:  # cannot happen with today's table (DOP853 supports everything); refuse by the registry
        registry.check_supported(registry.get("DOP853"), needs)
    ctx = _Context(eqs.n, abs(float(t_end) - float(t0)), float(rtol), backend, projection)
    stiffness = estimate_stiffness(fun, float(t0), y0) if fun is not None else None
    taylor = _taylor_info(eqs, allowed, ctx)
    if stiffness is not None and stiffness.is_stiff(ctx.horizon):
        return _stiff_choice(stiffness, taylor, allowed, ctx)
    estimate = ("" if stiffness is None else
                f" (fastest decay {stiffness.decay:.3g}/time over {ctx.horizon:g}: not stiff)")
    if taylor is not None and (taylor[1] == "c" and backend in ("python", "reference") or ctx.rtol <= 1e-11):
        where = ("steps in the compiled tape interpreter, scipy's DOP853 in Python" if backend != "numba"
                 else "needs fewer operations than DOP853 at this tolerance")
        return "taylor", f"smooth{estimate}: the Taylor method (order {taylor[0]}) {where}"
    name = _first(("DOP853", "RK45", "LSODA", "Radau"), allowed)
    return name, f"non-stiff{estimate}: {name}, the most efficient explicit method the request allows"


def _first(preferred: tuple[str, ...], allowed: tuple[str, ...]) -> str:
    return next(m for m in preferred if m in allowed)


def _taylor_info(eqs, allowed: tuple[str, ...], ctx: _Context) -> tuple[int, str, int] | None:
    """``(order, interpreter, tape size)`` when the Taylor method may run this request, else None."""
    if "taylor" not in allowed or eqs.is_structural:  # the tape needs the expanded equations: set-up O(n³)
        return None
    from ..codegen.numeric import NumericModel
    from .taylor import available_interpreter, taylor_order

    engine = available_interpreter()
    if engine is None:
        return None
    try:
        tape = NumericModel.tape_for(eqs)
    except TypeError as exc:  # TapeError (a LagrangeError): not analytic (sign, Abs, ...) or constrained
        if not isinstance(exc, LagrangeError):
            raise
        return None
    return taylor_order(ctx.rtol), "series" if ctx.backend == "numba" else engine, tape.size


def _stiff_choice(st: Stiffness, taylor, allowed: tuple[str, ...], ctx: _Context) -> tuple[str, str]:
    """Taylor when its stability-limited cost beats an implicit method's, else LSODA (Radau to project)."""
    head = (f"stiff: fastest decay rate {st.decay:.3g}/time over a horizon of {ctx.horizon:g} (stiffness ratio "
            f"{st.ratio:.3g})")
    implicit = implicit_seconds(ctx.n)
    if taylor is not None:
        est = taylor_seconds(st, ctx.horizon, taylor[2], taylor[0], compiled_series=taylor[1] == "series")
        if est < implicit:
            return "taylor", (f"{head}; the Taylor method (order {taylor[0]}) stays stable with steps ~{taylor[0]}/"
                              f"(2·rate): estimated {est:.2g} s against ~{implicit:.2g} s for an implicit method")
        head += f"; the Taylor method would take ~{est:.2g} s"
    name = _first(("Radau", "LSODA", "BDF") if ctx.projection else ("LSODA", "Radau", "BDF"), allowed)
    why = ("keeps the constraints by projection" if ctx.projection and name == "Radau"
           else "switches to BDF with the generated Jacobian")
    return name, f"{head}; {name} {why}"
