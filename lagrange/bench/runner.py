r"""Timing and error measurement for work-precision diagrams.

* **Error** of a run: the max-norm over the measured times (:meth:`BenchProblem.times`) and over the state
  components of ``|y − y_ref|`` (absolute). ``y_ref`` is the problem's closed form, or a numerical reference
  (the problem's ``reference_method`` at rtol 1e-13) whose **self-consistency** — its distance from the
  same method at rtol 1e-12 — is reported with it; errors below it are not meaningful.
* **Wall time**: ``time.perf_counter`` around one call that produces the states (models are compiled
  beforehand and reported as setup), the **median** over repeats after a first run that serves as warm-up
  (for runs under 5 ms the fastest of 7 samples instead, a sample of a run under 2 ms being a batch's mean;
  one run when the first took more than ``budget`` seconds). A curve
  stops at the first tolerance whose run took longer than ``stop`` seconds.
* **nfev**: right-hand-side evaluations as reported by the integrator (None for heyoka's Taylor method
  and for the geometric methods, whose Newton iterations are not comparable).

Kinds of method (:class:`MethodSpec`): ``simulate`` (lagrange's :func:`~lagrange.integrate.run.simulate`:
scipy methods, ``backend`` python/numba, optionally ``loop="compiled"``), ``fixed`` (the geometric
fixed-step methods stepped on a prebuilt Hamiltonian model), ``sympy`` (the plain sympy.physics.mechanics
route, :mod:`lagrange.bench.sympy_route`) and ``heyoka`` (:mod:`lagrange.bench.heyoka_adapter`).
An entry whose keyword the installed lagrange does not accept (``TypeError``) is reported unavailable.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import field

import numpy as np
from scipy.integrate import solve_ivp

from ..errors import LagrangeError
from ..integrate.options import FrictionOptions
from ..records import record
from .common import EnergyRun, _numba_ok, initial_vector  # noqa: F401 (their home until they moved)
from .problems import BenchProblem

__all__ = ["TOLERANCES", "QUICK_TOLERANCES", "MethodSpec", "Point", "Curve", "Reference", "EnergyRun",
           "ProblemResult", "method_specs", "reference_solution", "measure", "run_curve",
           "run_problem", "initial_vector"]

TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
QUICK_TOLERANCES = (1e-5, 1e-8)


@record(frozen=True)
class MethodSpec:
    """One curve of a diagram: how to integrate (see the module docstring for ``kind``)."""

    label: str
    kind: str = "simulate"
    method: str = "DOP853"
    backend: str = "python"
    loop: str | None = None
    options: tuple = ()  # extra simulate options, (key, value) pairs


@record(frozen=True)
class Point:
    """One run: tolerance (or fixed step), median wall time [s], nfev, error, number of timed runs."""

    setting: float
    wall: float
    nfev: int | None
    error: float
    runs: int


@record
class Curve:
    """All runs of one method on one problem; ``note`` says why it is missing or stopped early."""

    spec: MethodSpec
    points: list = field(default_factory=list)
    setup: float | None = None
    note: str = ""


@record(frozen=True)
class Reference:
    """The truth the errors are measured against, at the problem's measured times."""

    states: np.ndarray
    description: str
    consistency: float | None  # distance between the two tightest reference runs (numerical reference)
    check: float | None = None  # closed form: distance of a DOP853 rtol 1e-13 run from it


@record
class ProblemResult:
    problem: BenchProblem
    reference: Reference
    curves: list
    derive_s: float
    energy: list = field(default_factory=list)
    first_result: list = field(default_factory=list)


def method_specs(problem: BenchProblem, *, quick: bool = False, heyoka: bool = True) -> list[MethodSpec]:
    """The methods compared on ``problem``: scipy methods × backends through ``simulate`` (numba with
    ``loop="scipy"``), the compiled loop (DOP853, RK45), ``method="auto"`` on the stiff problem, the
    geometric methods (conservative problems; Python and compiled step loops), the plain sympy route
    (pendulums) and heyoka.

    ``quick``: the python backend only (no JIT), DOP853 and LSODA, GL4, the plain route's DOP853, heyoka.
    """
    scipy_methods = ("DOP853", "LSODA") if quick else ("DOP853", "RK45", "Radau", "LSODA")
    friction = problem.name == "stick_slip"
    specs = [MethodSpec(f"{m} python", method=m) for m in scipy_methods]
    if not quick and _numba_ok():
        specs += [MethodSpec(f"{m} numba scipy loop", method=m, backend="numba", loop="scipy") for m in scipy_methods]
        specs += [MethodSpec(f"{m} numba compiled loop", method=m, backend="numba", loop="compiled")
                  for m in ("DOP853", "RK45")]
    from ..integrate.taylor import available_interpreter

    engine = available_interpreter()
    if not friction and engine:  # dry friction (sign) is not analytic: no Taylor series
        specs.append(MethodSpec(f"taylor python ({'tape interpreted in C' if engine == 'c' else 'compiled series'})",
                                method="taylor"))
        if not quick and _numba_ok():
            specs.append(MethodSpec("taylor numba (compiled series)", method="taylor", backend="numba"))
    if problem.reference_method == "Radau":  # the stiff problem: what auto picks
        specs.append(MethodSpec("auto python", method="auto"))
    if friction:
        for eps in (1e-3, 1e-5):
            specs.append(MethodSpec(f"LSODA python regularized ε={eps:g}", method="LSODA",
                                    options=(("friction", FrictionOptions("regularize", eps)),)))
    if problem.conservative and problem.geometric:
        fixed = ["gl4"] if quick else ["midpoint", "gl4", "gl6", "dg"] + (["verlet"] if problem.separable else [])
        specs += [MethodSpec(f"{m} (fixed step)", kind="fixed", method=m, loop="scipy") for m in fixed]
        if not quick and _numba_ok():
            specs += [MethodSpec(f"{m} compiled loop (fixed step)", kind="fixed", method=m, loop="compiled")
                      for m in fixed]
    if problem.pendulum_links:
        specs += [MethodSpec(f"plain sympy {m}", kind="sympy", method=m) for m in scipy_methods if m != "Radau"]
    if heyoka and not friction:
        specs.append(MethodSpec("heyoka taylor_adaptive", kind="heyoka", method="taylor"))
    return specs


#: a run shorter than this is timed in batches lasting about this long (one sample = a batch's mean)
BATCH_S = 2e-3


def measure(run: Callable[[], object], *, repeats: int = 3, budget: float = 1.0) -> tuple[float, object, int]:
    """``(wall seconds, result, timed runs)`` of ``run()``; the first call is a warm-up. The wall time is the
    median of ``repeats`` samples — for runs under 5 ms the *fastest* of 7, as ``timeit`` advises: on a
    shared machine a sub-millisecond run is slowed by bursts of other work by up to 2× (measured: the same
    Taylor run 0.21 and 0.38 ms in two runs of the suite), and the minimum is what the code costs. A run
    under :data:`BATCH_S` is sampled as the mean of a batch of ``⌈BATCH_S / warm-up time⌉`` runs. The same
    rule for every method, heyoka's included."""
    t0 = time.perf_counter()
    result = run()
    first = time.perf_counter() - t0
    if first > budget:
        return first, result, 1
    k = repeats if first > 5e-3 else max(repeats, 7)
    batch = 1 if first >= BATCH_S else math.ceil(BATCH_S / max(first, 1e-7))
    times = []
    for _ in range(k):
        t0 = time.perf_counter()
        for _ in range(batch):
            result = run()
        times.append((time.perf_counter() - t0) / batch)
    return (min(times) if first <= 5e-3 else statistics.median(times)), result, k * batch


def reference_solution(problem: BenchProblem, system, *, backend: str | None = None) -> Reference:
    """Closed form, or the problem's reference method at rtol 1e-13 checked against rtol 1e-12
    (``backend``: numba when installed, by default)."""
    times = problem.times()
    backend = backend or ("numba" if _numba_ok() else "python")

    def run(tol):
        sol = system.simulate((0.0, problem.t_end), problem.initial, problem.params, method=problem.reference_method,
                              rtol=tol, atol=tol * problem.atol_scale, t_eval=times, backend=backend,
                              **problem.options)
        return sol.y

    if problem.exact is not None:
        exact = problem.exact(times)
        try:
            check = float(np.max(np.abs(run(1e-13) - exact)))
        except (LagrangeError, ValueError):
            check = None
        return Reference(exact, "closed form", None, check)
    tight = run(1e-13)
    return Reference(tight, f"{problem.reference_method} rtol 1e-13", float(np.max(np.abs(tight - run(1e-12)))))


class _Runner:
    """Builds what a method needs once (setup, timed) and returns ``run(setting) -> (states, nfev)``."""

    def __init__(self, problem: BenchProblem, system, spec: MethodSpec):
        self.problem, self.system, self.spec = problem, system, spec
        self.times = problem.times()
        self.y0 = initial_vector(problem, system)
        t0 = time.perf_counter()
        self.setup = 0.0
        self._build = getattr(self, f"_setup_{spec.kind}")()
        self.setup = time.perf_counter() - t0  # grows when a setting needs its own compilation (Taylor order)

    # --- lagrange simulate ---
    def _setup_simulate(self):
        p, s = self.problem, self.spec
        model = self.system.compile(p.params, backend=s.backend)
        extra = dict(p.options) | dict(s.options) | ({"loop": s.loop} if s.loop else {})

        def make(tol):
            if s.method == "taylor" and model.backend == "numba":  # the series for this order: JIT is setup
                from ..integrate.taylor import taylor_order

                t0 = time.perf_counter()
                model.taylor_series(taylor_order(tol))
                self.setup += time.perf_counter() - t0

            def run():
                sol = self.system.simulate((0.0, p.t_end), p.initial, p.params, method=s.method, rtol=tol,
                                           atol=tol * p.atol_scale, backend=s.backend, model=model,
                                           t_eval=self.times, **extra)
                return sol.y, sol.nfev
            return run
        make(1e-3)()  # warm-up; raises TypeError when an option is not supported
        return make

    # --- geometric fixed-step methods (Python or compiled step loop) ---
    def _setup_fixed(self):
        p, s = self.problem, self.spec
        model = self.system.compile(p.params)  # the trajectory's model; the steps use the Hamiltonian pieces

        def make(h, t_end=p.t_end):
            def run():
                sol = self.system.simulate((0.0, t_end), p.initial, p.params, method=s.method, step=h, n_points=2,
                                           model=model, loop=s.loop)
                return sol.y[-1:], None
            return run
        make(1e-3, 1e-3)()  # warm-up: builds H (and, compiled, loads or JIT-compiles the pieces and the kernel)
        return make

    # --- the plain sympy route ---
    def _setup_sympy(self):
        from .sympy_route import plain_pendulum_route

        p = self.problem
        _, _, rhs = plain_pendulum_route(p.pendulum_links, float(p.params["g"]))

        def make(tol):
            def run():
                res = solve_ivp(rhs, (0.0, p.t_end), self.y0, method=self.spec.method, rtol=tol,
                                atol=tol * p.atol_scale, t_eval=self.times)
                return res.y.T, res.nfev
            return run
        return make

    # --- heyoka ---
    def _setup_heyoka(self):
        from .heyoka_adapter import heyoka_model

        hm = heyoka_model(self.system, self.problem.params)
        self.compile_times, self.compact = [], hm.compact

        def make(tol):
            ta, c = hm.integrator(self.y0, tol)
            self.compile_times.append(c)

            def run():
                return hm.propagate(ta, self.y0, self.times)[0], None
            return run
        return make


def run_curve(problem: BenchProblem, system, spec: MethodSpec, reference: Reference, settings: Sequence[float], *,
              repeats: int = 3, budget: float = 1.0, stop: float = 4.0) -> Curve:
    """Every setting of one method: a :class:`Curve` (``note`` says what went wrong or was skipped)."""
    curve = Curve(spec)
    try:
        runner = _Runner(problem, system, spec)
    except TypeError as exc:
        curve.note = f"unavailable: {exc}"
        return curve
    except (LagrangeError, ImportError) as exc:
        curve.note = f"not applicable: {exc}"
        return curve
    except Exception as exc:  # noqa: BLE001 - a failing method is a result to report, not a crash
        curve.note = f"failed: {type(exc).__name__}: {str(exc)[:160]}"
        return curve
    curve.setup = runner.setup
    for s in settings:
        try:
            wall, (Y, nfev), k = measure(runner._build(s), repeats=repeats, budget=budget)
        except Exception as exc:  # noqa: BLE001 - reported in the table
            curve.note = f"failed at {s:g}: {type(exc).__name__}: {str(exc)[:160]}"
            break
        if Y.shape != reference.states.shape:
            curve.note = f"stopped early at {s:g} (returned {Y.shape[0]} of {reference.states.shape[0]} states)"
            break
        err = float(np.max(np.abs(Y - reference.states)))
        curve.points.append(Point(s, wall, None if nfev is None else int(nfev), err, k))
        if wall > stop:
            curve.note = f"sweep stopped after {s:g}: one run took {wall:.1f} s"
            break
    curve.setup = runner.setup  # with the compilations of each setting
    if spec.kind == "heyoka" and getattr(runner, "compile_times", None):
        curve.setup = runner.setup + runner.compile_times[0]
        curve.note = (curve.note + "; " if curve.note else "") + (
            f"setup = heyoka derivation + first LLVM compile{' (compact_mode)' if runner.compact else ''}")
    return curve


def run_problem(problem: BenchProblem, *, quick: bool = False, heyoka: bool = True, repeats: int | None = None,
                energy: bool = True, first_result: bool = True, log: Callable[[str], None] | None = None
                ) -> ProblemResult:
    """Everything for one problem: reference, one curve per method, long energy runs, time to first result.

    ``quick`` uses :data:`QUICK_TOLERANCES`, one timed repeat and short horizons (for tests and a first
    look); otherwise :data:`TOLERANCES` and the median of 3 runs.
    """
    from ..progress import note as progress_note
    from .first_result import first_result as run_first
    from .first_result import routes_for
    from .longrun import energy_runs

    say = log or (lambda s: None)
    progress_note(f"{problem.name}: deriving the equations and the reference solution")
    t0 = time.perf_counter()
    system = problem.build()
    derive_s = time.perf_counter() - t0
    ref = reference_solution(problem, system, backend="python" if quick else None)
    say(f"{problem.name}: derived in {derive_s:.2f} s; reference {ref.description}"
        + (f" (self-consistency {ref.consistency:.1e})" if ref.consistency is not None else ""))
    tols = QUICK_TOLERANCES if quick else TOLERANCES
    reps = repeats if repeats is not None else (1 if quick else 3)
    curves = []
    for spec in method_specs(problem, quick=quick, heyoka=heyoka):
        settings = problem.steps if spec.kind == "fixed" else tols
        if spec.method == "Radau" and problem.reference_method != "Radau":  # seconds per run below 1e-10
            settings = [v for v in settings if v >= 1e-10]
        progress_note(f"{problem.name}: {spec.label} at {len(settings)} settings")
        curve = run_curve(problem, system, spec, ref, settings, repeats=reps, budget=0.5, stop=1.0 if quick else 2.5)
        curves.append(curve)
        best = min((p.error for p in curve.points), default=float("nan"))
        say(f"  {spec.label:<40} {len(curve.points)} points, best error {best:.1e} {curve.note[:90]}")
    result = ProblemResult(problem, ref, curves, derive_s)
    if energy:
        progress_note(f"{problem.name}: long energy runs")
        result.energy, notes = energy_runs(problem, system, quick=quick, heyoka=heyoka)
        for run in result.energy:
            say(f"  long run {run.label:<36} max energy error {np.max(run.error):.1e} in {run.wall:.2f} s")
        for note in notes:
            say(f"  long run: {note}")
    if first_result:
        for route in routes_for(problem, heyoka=heyoka):
            progress_note(f"{problem.name}: time to first result, {route} (fresh processes)")
            fr = run_first(problem, route, ref.states, quick=quick)
            result.first_result.append(fr)
            say(f"  first result {route:<10} " + (f"{fr.total:.2f} s" if fr.total is not None else fr.note))
    return result
