r"""``method="auto"``: choose an adaptive method of the registry from cheap numerical estimates.

The decision costs 2n + 1 evaluations of the compiled right-hand side (the model the run uses: ``simulate``
hands the model it built to decide on to the run, parameters bound once) and a few microseconds of
arithmetic; no symbolic Jacobian is built to test stiffness, and eigenvalues are computed only when a cheap
bound cannot rule stiffness out (``benchmarks/auto_choice.py`` measures the decision against the runs).

1. **Candidates.** Only the adaptive methods of :data:`~lagrange.integrate.registry.METHODS` whose entry covers
   everything the request needs (events, holonomic and non-holonomic constraints, friction switches, rough
   constraints, constant or time-varying inputs, dense output) are considered; the Taylor method also needs
   analytic unconstrained equations and a tape interpreter (:func:`~lagrange.integrate.taylor_run.taylor_ready`),
   and the expanded equations (a structural system's are weighed only when at hand, in memory or in the on-disk
   derivation cache: :meth:`lagrange.System.expanded_at_hand`; the run then uses them). It is excluded, with the
   reason in the method line, when the equations hold a non-analytic or user function, a kink, or a
   near-singularity at the run's parameter values — a regularization such as :math:`\sqrt{x^2+\varepsilon^2}` or
   :math:`\tanh(v/\varepsilon)` with a small ε, which fools its step control
   (:mod:`lagrange.codegen.analyticity`); the Jacobian is then also estimated at the real state nearest the
   near-singularity (the *probe*: 2n + 1 more evaluations), and a problem stiff there (regularized friction
   sticking: decay rate ~ friction/ε) is treated as stiff.
2. **Stiffness estimate.** The Jacobian :math:`J = \partial f/\partial y` of the compiled right-hand side at
   the initial state by forward differences (:func:`difference_jacobian`: 2n + 1 evaluations; when the
   equations are not known to be analytic — no Taylor tape — each column is checked against a ``sign()``
   switch at the state, and across one the smaller one-sided difference is kept). First a bound
   (:func:`decay_bound`, Gershgorin's discs of the block-balanced :math:`J`) on the fastest decay rate
   :math:`\mu = \max(-\operatorname{Re}\lambda)`: when :math:`\text{bound} \cdot T \le 10^3` the problem is not
   stiff and no eigenvalue is computed. Otherwise the eigenvalues :math:`\lambda` of :math:`J`
   (:func:`estimate_stiffness`): :math:`\mu` and the stiffness ratio :math:`\mu / \min|\lambda \ne 0|`.
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
from collections.abc import Callable, Mapping
from functools import lru_cache

import numpy as np

from ..errors import LagrangeError
from ..records import record
from . import registry

__all__ = ["Stiffness", "estimate_stiffness", "difference_jacobian", "decay_bound", "taylor_seconds",
           "implicit_seconds", "candidates", "choose"]

#: μ T above which explicit methods are stability-limited, and the stiffness ratio above which this is stiffness
STIFF_STEPS = 1e3
STIFF_RATIO = 1e3
_SQRT_EPS = math.sqrt(float(np.finfo(float).eps))
#: eigenvalues below this fraction of the spectral radius are not resolved by the finite differences
RESOLUTION = 1e-8
#: seconds per tape instruction per Taylor pass at order 12 (C interpreter; measured, benchmarks/auto_choice.py)
TAPE_SECONDS = 23e-9
#: one implicit scipy run (LSODA with its generated Jacobian) on a 2-DOF system, seconds (measured likewise)
IMPLICIT_SECONDS = 0.15
#: the compiled series (numba backend) runs a pass about 3× faster than the C interpreter but JIT-compiles first
SERIES_SPEEDUP, SERIES_JIT_SECONDS = 3.0, 0.1


@record(frozen=True, slots=True)
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


def estimate_stiffness(fun: Callable, t0: float, y0: np.ndarray, *, smooth: bool = False) -> Stiffness | None:
    r"""Eigenvalues of the finite-difference Jacobian of ``fun(t, y) -> (2n,)`` at ``(t0, y0)``.

    Column :math:`j` is the forward difference :math:`(f(y + h e_j) − f(y))/h` with
    :math:`h = \sqrt{\varepsilon}\max(1, |y_j|)` (:func:`difference_jacobian`; with ``smooth=False`` checked
    against a ``sign()`` switch at ``y``). Eigenvalues below 1e-8 × the spectral radius are not resolved: the
    stiffness ratio is at most 1e8.

    Returns None when ``fun`` fails (singular mass matrix, a domain error) or gives non-finite values: the
    caller then decides without the estimate and the run reports the fault.

    >>> st = estimate_stiffness(lambda t, y: np.array([y[1], -1e4 * y[0] - 1e3 * y[1]]), 0.0, np.zeros(2))
    >>> round(st.decay), round(st.ratio)
    (990, 98)
    """
    found = difference_jacobian(fun, t0, y0, smooth=smooth)
    return None if found is None else _eigen_estimate(*found)


def _eigen_estimate(J: np.ndarray, seconds: float) -> Stiffness | None:
    try:
        lam = np.linalg.eigvals(J)
    except np.linalg.LinAlgError:
        return None
    mags = np.abs(lam)
    radius = float(np.max(mags, initial=0.0))
    decay = float(np.max(-lam.real, initial=0.0)) + 0.0  # no -0.0
    # below about 1e-8 × radius an eigenvalue is not resolved by the differences: count it as that
    slow = max(float(np.min(mags)) if mags.size else 0.0, RESOLUTION * radius)
    return Stiffness(decay, radius, decay / slow if decay and slow else 1.0, seconds)


def difference_jacobian(fun: Callable, t0: float, y0, *, smooth: bool = False
                        ) -> tuple[np.ndarray, float] | None:
    r"""``(J, seconds per evaluation)``: the Jacobian :math:`\partial f/\partial y` of ``fun(t, y)`` at
    ``(t0, y0)`` by forward differences, 2n + 1 evaluations of ``fun`` (one call per column, each with its own
    state array; ``fun`` may return a list or an array of at least ``y0.size`` values).

    With ``smooth=False`` (``fun`` may hold ``sign()``/``Abs``) every column is also differenced over ``2h``;
    where the two disagree (a jump at ``y0``, e.g. ``sign(v)`` at v = 0, makes difference quotients scale as
    1/h) the differences are taken on each side of the jump (between ``y0 ± h`` and ``y0 ± 2h``), the smaller
    one kept: 4n + 1 evaluations, two more per switched column. ``smooth=True`` (the equations are analytic:
    their Taylor tape exists) skips that check.

    Returns None when ``fun`` raises a LagrangeError or an arithmetic error, or gives non-finite values.

    >>> J, _ = difference_jacobian(lambda t, y: [y[1], -4.0 * y[0] - 5.0 * y[1]], 0.0, np.zeros(2))
    >>> np.round(J, 6).tolist()
    [[0.0, 1.0], [-4.0, -5.0]]
    """
    y0 = np.array(y0, dtype=float)
    size = y0.size
    t0 = float(t0)
    steps = [_SQRT_EPS * (v if v > 1.0 else 1.0) for v in np.abs(y0).tolist()]  # plain floats: cheap per column
    start = time.perf_counter()
    try:
        f0 = np.array(fun(t0, y0)[:size], dtype=float)
        rows = []  # row j: f(y0 + h_j e_j)
        for j, hj in enumerate(steps):
            y = y0.copy()
            y[j] += hj
            rows.append(fun(t0, y)[:size])
        calls = 1 + size
        h = np.array(steps)
        F = np.array(rows, dtype=float).reshape(size, size)
        J = ((F - f0) / h[:, None]).T
        if not smooth:
            J, extra = _jumps_removed(fun, t0, y0, h, f0, F, J)
            calls += extra
    except (LagrangeError, ArithmeticError, ValueError, TypeError):
        return None
    seconds = (time.perf_counter() - start) / calls
    return (J, seconds) if np.isfinite(J).all() else None


def _jumps_removed(fun, t0, y0, h, f0, F, J) -> tuple[np.ndarray, int]:
    """``J`` with each column that jumps at ``y0`` replaced by the smaller one-sided difference, and the number
    of extra evaluations (see :func:`difference_jacobian`)."""
    size = y0.size
    E = np.diag(h)
    F2 = np.array([np.asarray(fun(t0, y), dtype=float)[:size] for y in y0 + 2 * E]).reshape(size, size)
    wide = ((F2 - f0) / (2 * h[:, None])).T
    scale = np.maximum(np.maximum(np.linalg.norm(J, axis=0), np.linalg.norm(wide, axis=0)), 1.0)
    jumps = np.flatnonzero(np.linalg.norm(J - wide, axis=0) > 1e-3 * scale)
    J = J.copy()
    for j in jumps:
        fm = np.asarray(fun(t0, y0 - E[j]), dtype=float)[:size]
        f_2 = np.asarray(fun(t0, y0 - 2 * E[j]), dtype=float)[:size]
        J[:, j] = min((F2[j] - F[j]) / h[j], (fm - f_2) / h[j], key=np.linalg.norm)
    return J, size + 2 * len(jumps)


def decay_bound(J: np.ndarray) -> float:
    r"""An upper bound of the fastest decay rate :math:`\max(-\operatorname{Re}\lambda)` of ``J`` without its
    eigenvalues: Gershgorin's discs of :math:`D^{-1} J D`, :math:`D = \operatorname{diag}(I, sI)` (the same
    eigenvalues), :math:`-\operatorname{Re}\lambda \le \max_i (-J'_{ii} + \sum_{j \ne i} |J'_{ij}|)`. For the
    state :math:`[q, \dot q]` the scale :math:`s = \sqrt{\lVert A\rVert_\infty}` (:math:`A = \partial\ddot q/
    \partial q`) balances the blocks: an undamped oscillator of frequency ω gets the bound ω, not ω².

    >>> round(decay_bound(np.array([[0.0, 1.0], [-100.0, 0.0]])), 6)
    10.0
    """
    J = np.asarray(J, dtype=float)
    n2 = J.shape[0]
    if n2 <= _SMALL:  # a few Python float operations beat a dozen numpy calls on a small matrix
        return _decay_bound_small(J.tolist())
    n = n2 // 2
    absJ = np.abs(J)
    s = _balance(float(absJ[:n, n:].sum(axis=1).max(initial=0.0)), float(absJ[n:, :n].sum(axis=1).max(initial=0.0)))
    if s != 1.0:
        absJ[:n, n:] *= s
        absJ[n:, :n] /= s
    diag = np.diagonal(J)
    radii = absJ.sum(axis=1) - np.abs(diag)
    return max(float(np.max(radii - diag)), 0.0)


#: matrices up to this size are bounded in plain Python (:func:`decay_bound`)
_SMALL = 12


def _balance(top: float, bottom: float) -> float:
    """The scale s of :func:`decay_bound`: sqrt(‖∂q̈/∂q‖ / ‖∂q̇/∂q̇‖) (1 when either block is zero)."""
    return math.sqrt(bottom / top) if top > 0 and bottom > 0 else 1.0


def _decay_bound_small(rows: list[list[float]]) -> float:
    n = len(rows) // 2
    sums = [(sum(map(abs, r[:n])), sum(map(abs, r[n:]))) for r in rows]
    s = _balance(max((b for _, b in sums[:n]), default=0.0), max((a for a, _ in sums[n:]), default=0.0))
    best = 0.0
    for i, (a, b) in enumerate(sums):
        d = rows[i][i]
        radius = (a + s * b if i < n else a / s + b) - abs(d)
        best = max(best, radius - d)
    return best


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
    return _candidates(frozenset(needs))


@lru_cache(maxsize=64)
def _candidates(features: frozenset) -> tuple[str, ...]:
    return tuple(m.name for m in registry.METHODS
                 if m.adaptive and m.name != "heyoka" and all(getattr(m, f) for f in features))


@record(frozen=True, slots=True)
class _Context:
    """What :func:`choose` knows about the request."""

    n: int
    horizon: float
    rtol: float
    backend: str
    projection: bool


def choose(eqs, fun: Callable | None, t0: float, y0, *, t_end: float, rtol: float, backend: str,
           needs: dict[str, str], projection: bool = False, taylor_equations=None,
           values: Mapping | None = None) -> tuple[str, str]:
    """The method for ``method="auto"`` and the reason (see the module docstring).

    Parameters
    ----------
    eqs : the derived Equations (friction treatment applied)
    fun : ``fun(t, y) -> dy/dt`` of the compiled model with the run's parameters (None: no stiffness estimate)
    t0, t_end : the horizon; y0 : the initial state, shape (2n,)
    rtol : the run's relative tolerance; backend : the model's backend
    needs : the registry features the request needs (:func:`lagrange.integrate.run._needs`)
    projection : holonomic constraints kept by projection (prefer a method that projects)
    taylor_equations : for structural ``eqs``, the same system's expanded equations when they are at hand
        (:meth:`lagrange.System.expanded_at_hand`): the Taylor tape is built from them. Without them a
        structural system is not offered the Taylor method (its tape needs the expanded equations, whose
        derivation grows about as n³) and the reason says so.
    values : ``{symbol: number}`` of the run's parameters (``eqs.numeric_parameters``): near-singularities are
        judged with them (:func:`lagrange.codegen.analyticity.obstacle`; without them only non-analytic
        functions and kinks exclude the Taylor method)

    Raises
    ------
    MethodError
        No adaptive method covers ``needs`` (the registry's message names the combination).
    """
    allowed = candidates(needs)
    if not allowed:  # cannot happen with today's table (DOP853 supports everything); refuse by the registry
        registry.check_supported(registry.get("DOP853"), needs)
    ctx = _Context(eqs.n, abs(float(t_end) - float(t0)), float(rtol), backend, projection)
    structural = "taylor" in allowed and eqs.is_structural
    blocked = _obstacle(taylor_equations if structural else eqs, allowed, fun, t0, y0, ctx, values)
    taylor = None if blocked is not None else _taylor_info(taylor_equations if structural else eqs, allowed, ctx)
    unweighed = ("; the Taylor method is not weighed: this structural system's expanded equations are not derived "
                 "yet (System.expanded derives them)") if structural and taylor_equations is None else ""
    if "varying_inputs" in needs:
        unweighed = "; the Taylor method is excluded: time-varying inputs (their smoothness is unknown)"
    if blocked is not None:
        unweighed = f"; the Taylor method is excluded (it needs analytic equations): {blocked.describe()}"
        probed = _stiff_at_probe(fun, t0, y0, blocked, allowed, ctx)
        if probed is not None:
            return probed[0], probed[1] + unweighed
    # analytic equations (their tape exists): no sign() jump to look for in the differences
    found = None if fun is None else difference_jacobian(fun, t0, y0, smooth=taylor is not None)
    estimate = ""
    if found is not None:
        bound = decay_bound(found[0])
        if bound * ctx.horizon > STIFF_STEPS:  # the bound cannot rule stiffness out: the eigenvalues decide
            stiffness = _eigen_estimate(*found)
            if stiffness is not None and stiffness.is_stiff(ctx.horizon):
                name, why = _stiff_choice(stiffness, taylor, allowed, ctx)
                return name, why + (unweighed if name != "taylor" else "")
            if stiffness is not None:
                estimate = f" (fastest decay {stiffness.decay:.3g}/time over {ctx.horizon:g}: not stiff)"
        else:
            estimate = f" (decay rates ≤ {bound:.3g}/time over {ctx.horizon:g}: not stiff)"
    if taylor is not None and (taylor[1] == "c" and backend in ("python", "reference") or ctx.rtol <= 1e-11):
        where = ("steps in the compiled tape interpreter, scipy's DOP853 in Python" if backend != "numba"
                 else "needs fewer operations than DOP853 at this tolerance")
        return "taylor", f"smooth{estimate}: the Taylor method (order {taylor[0]}) {where}"
    name = _first(("DOP853", "RK45", "LSODA", "Radau"), allowed)
    return name, f"non-stiff{estimate}: {name}, the most efficient explicit method the request allows{unweighed}"


def _obstacle(eqs, allowed, fun, t0, y0, ctx: _Context, values):
    """What makes the Taylor method untrustworthy on ``eqs`` (:func:`lagrange.codegen.analyticity.obstacle`),
    or None (also when it is not a candidate or its equations are not at hand)."""
    if "taylor" not in allowed or eqs is None or eqs.is_structural or eqs.m or y0 is None:
        return None
    from ..codegen.numeric import NumericModel

    rates = None
    if fun is not None:
        try:
            rates = np.asarray(fun(float(t0), np.asarray(y0, dtype=float)), dtype=float)
        except (LagrangeError, ArithmeticError, ValueError, TypeError):
            rates = None
    return NumericModel.taylor_obstacle(eqs, values, y0, rates, ctx.horizon, t0)


def _stiff_at_probe(fun, t0, y0, blocked, allowed, ctx: _Context) -> tuple[str, str] | None:
    """The stiff choice when the equations are stiff at the real state nearest a near-singularity (regularized
    friction sticks there: decay rate ~ friction / ε), else None. 2n + 1 more evaluations."""
    if fun is None or not blocked.probe:
        return None
    y = np.array(y0, dtype=float)
    for i, v in blocked.probe:
        y[i] = v
    found = difference_jacobian(fun, t0, y, smooth=True)
    if found is None or decay_bound(found[0]) * ctx.horizon <= STIFF_STEPS:
        return None
    stiffness = _eigen_estimate(*found)
    if stiffness is None or not stiffness.is_stiff(ctx.horizon):
        return None
    name, why = _stiff_choice(stiffness, None, allowed, ctx)
    return name, why.replace("stiff: ", "stiff at the near-singularity: ", 1)


def _first(preferred: tuple[str, ...], allowed: tuple[str, ...]) -> str:
    return next(m for m in preferred if m in allowed)


def _taylor_info(eqs, allowed: tuple[str, ...], ctx: _Context) -> tuple[int, str, int] | None:
    """``(order, interpreter, tape size)`` when the Taylor method may run this request on ``eqs`` (expanded
    equations, or None), else None."""
    if "taylor" not in allowed or eqs is None or eqs.is_structural:  # the tape needs the expanded equations
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
