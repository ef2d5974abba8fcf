r"""The hard-case suite (``lagrange bench --hard``): mechanics problems that break integrators, each run by every
method of the registry, with its error against an independent reference and the run's own verdict.

================  =================================================================================
name              problem and reference
================  =================================================================================
squeezer          Andrews' seven-body squeezer (index 3); the published reference at t = 0.03
car_axis          car axis of the IVP test set with springs 10⁴× stiffer (index 3, stiff); a hand-written
                  index-1 formulation (KKT solve) by scipy DOP853 at rtol 1e-13
double_pendulum   double pendulum at high energy (chaotic); the Taylor method at rtol 1e-14, error over the
                  first second, and the horizon over which each run stays within 1e-2
kepler            Kepler orbit, e = 0.9, many periods; closed form through Kepler's equation
cone              V = k √(x² + ε²), ε = 1e-4 (a kink); Radau at rtol 1e-13 (the ε → 0 closed form is within
                  O(ε) of it)
stick_slip        block on a spring with Coulomb friction, ``friction="regularize"``; exact rest position
                  1.1 − √1.16 (the regularization creeps by ~2e-6: the reference's floor is 5e-6)
spherical_pole    spherical pendulum in (θ, φ) passing within ~2e-4 rad of the pole θ = 0; the same motion in
                  Cartesian coordinates with the constraint |r| = l (hand-written, DOP853 at rtol 1e-13)
================  =================================================================================

Each run records the relative error (max over the compared times and components of ``|y − y_ref|``, divided
by ``max|y_ref|``), the CPU time (``time.process_time`` around ``simulate``), the constraint drift of
constrained systems, and the verdict of the run. Its **outcome** is one of

* ``accurate`` — the verdict passed and the error is within :data:`SILENT_FACTOR` · rtol (+ the floor);
* ``flagged`` — the run's own checks failed, or it stopped (:attr:`~lagrange.RunStatus.STOPPED`);
* ``SILENTLY WRONG`` — the verdict says accurate but the error exceeds :data:`SILENT_FACTOR` · rtol + floor;
* ``refused`` — the method refuses the problem before running (a :class:`~lagrange.errors.LagrangeError` that
  is a ``TypeError``: :class:`~lagrange.errors.MethodError` and the like, naming what would work);
* ``ERRORED`` — any other exception (its class and first line are recorded).
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable
from dataclasses import field

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..conventions import t
from ..errors import LagrangeError, SpecError
from ..examples import SQUEEZER_DATA, SQUEEZER_INITIAL, SQUEEZER_REFERENCE, andrews_squeezer, n_link_pendulum
from ..model.bodies import Particle
from ..model.constraints import Holonomic
from ..model.coordinates import coordinates, parameters
from ..model.system import System
from ..records import record
from .horizon import divergence_time
from .problems import kepler_state, kepler_system

__all__ = ["HardProblem", "HardRun", "HARD_PROBLEMS", "SILENT_FACTOR", "HORIZON_THRESHOLD", "QUICK_METHODS",
           "FULL_METHODS", "COLUMNS", "get_hard_problem", "run_hard_case", "run_hard_suite", "render_hard_markdown",
           "write_hard_report"]

#: a run whose relative error exceeds this many times its rtol (plus the reference's floor) is wrong; wrong
#: and called accurate by its own verdict is *silently* wrong
SILENT_FACTOR = 1e3
#: chaotic problems: a run agrees with the reference until their separation (state units) first exceeds this
HORIZON_THRESHOLD = 1e-2
#: the methods of ``--quick``: one of each family of the registry, and ``auto``
QUICK_METHODS = ("DOP853", "Radau", "LSODA", "taylor", "gl4", "auto")
#: every method of the registry (heyoka when installed) and ``auto``
FULL_METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA", "taylor", "heyoka", "midpoint", "gl4", "gl6",
                "verlet", "dg", "auto")


@record(frozen=True)
class HardProblem:
    """One hard case.

    Attributes
    ----------
    name, title : identifier and one-line description
    build : () -> System
    params, initial : parameter and initial values by name (``"q"``, ``"q_dot"``)
    t_end : horizon (t0 = 0)
    observe : ``observe(trajectory) -> ndarray (k, m)``: the compared quantities at the trajectory's times
    reference : ``reference(times) -> ndarray (k, m)``: the truth of the same quantities
    reference_note : what the reference is (closed form, published values, which second formulation)
    tolerances : the rtols run (atol = ``atol_scale`` · rtol)
    at_end : compare the final time only (the reference is known there only)
    floor : relative error the reference itself carries (model error), added to the silent-wrong limit (the
        stick-slip block creeps after sticking, ~2.4e-7 per second with ε = 1e-6: 5e-6 absolute)
    error_until : chaotic problems: the error is measured over t ≤ error_until only
    horizon : report each run's agreement horizon with the reference (chaotic problems)
    step : fixed step h of the fixed-step methods
    options : extra ``simulate`` options
    """

    name: str
    title: str
    build: Callable[[], System]
    params: dict
    initial: dict
    t_end: float
    observe: Callable
    reference: Callable
    reference_note: str
    tolerances: tuple
    at_end: bool = False
    floor: float = 0.0
    error_until: float | None = None
    horizon: bool = False
    step: float = 1e-3
    atol_scale: float = 1.0
    n_points: int = 201
    options: dict = field(default_factory=dict)


@record(frozen=True)
class HardRun:
    """One method at one tolerance on one problem (see the module docstring for ``outcome``)."""

    problem: str
    method: str
    rtol: float
    outcome: str
    error: float = math.nan
    cpu: float = math.nan
    drift: float | None = None
    checks_failed: tuple = ()
    used: str = ""
    horizon: float | None = None
    detail: str = ""


def _names(*names):
    return lambda sol: np.column_stack([sol[n] for n in names])


# --- the problems -----------------------------------------------------------------------------------------------

def _squeezer(quick: bool) -> HardProblem:
    names = ("beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon")
    initial = dict(zip(names, SQUEEZER_INITIAL)) | {n + "_dot": 0.0 for n in names}
    return HardProblem(
        "squeezer", "Andrews' seven-body squeezer, index 3, t ∈ [0, 0.03]", andrews_squeezer,
        {k: float(v) for k, v in SQUEEZER_DATA.items()}, initial, 0.03, _names(*names),
        lambda times: np.array([SQUEEZER_REFERENCE[0]]),
        "published (test set for IVP solvers, PSIDE at 1e-14), the seven angles at t = 0.03",
        (1e-7,) if quick else (1e-6, 1e-9), at_end=True, n_points=11)


CAR = {"epsilon": 1e-2, "M": 10.0, "L": 1.0, "L_0": 0.5, "r": 0.1, "omega": 10.0, "k": 1e4}
CAR_IC = {"x_l": 0.0, "y_l": 0.5, "x_r": 1.0, "y_r": 0.5, "x_l_dot": -0.5, "y_l_dot": 0.0, "x_r_dot": -0.5,
          "y_r_dot": 0.0}


def car_axis() -> System:
    """The car axis of Mazzia & Magherini's test set (index-3 form: two wheels of mass ε²M/2 on springs, the
    axle's end on a support moving as y_b = r sin ωt), with its two holonomic constraints."""
    xl, yl, xr, yr = coordinates("x_l y_l x_r y_r")
    eps, M, L, L0, r, w, k = parameters("epsilon M L L_0 r omega k")
    m = eps**2 * M / 2
    yb = r * sp.sin(w * t)
    xb = sp.sqrt(L**2 - yb**2)
    Ll, Lr = sp.sqrt(xl**2 + yl**2), sp.sqrt((xr - xb) ** 2 + (yr - yb) ** 2)
    V = k * (Ll - L0) ** 2 / 2 + k * (Lr - L0) ** 2 / 2 + m * (yl + yr)  # gravity 1, as in the test set
    return System([xl, yl, xr, yr], bodies=[Particle(m, (xl, yl)), Particle(m, (xr, yr))], V=V,
                  constraints=[Holonomic(xl * xb + yl * yb, "support"),
                               Holonomic((xl - xr) ** 2 + (yl - yr) ** 2 - L**2, "axle")], name="car axis")


def car_axis_reference(times: np.ndarray) -> np.ndarray:
    """Positions ``(k, 4)`` of the car axis from a hand-written index-1 formulation (Newton's law with the
    multipliers from a KKT solve in numpy), scipy DOP853 at rtol 1e-13."""
    eps, M, L, L0, r, w, k = (CAR[n] for n in ("epsilon", "M", "L", "L_0", "r", "omega", "k"))
    m = eps**2 * M / 2

    def rhs(t_, z):
        xl, yl, xr, yr, vxl, vyl, vxr, vyr = z
        yb, dyb, ddyb = r * np.sin(w * t_), r * w * np.cos(w * t_), -r * w**2 * np.sin(w * t_)
        xb = np.sqrt(L**2 - yb**2)
        dxb = -yb * dyb / xb
        ddxb = -(dyb**2 + yb * ddyb) / xb - dxb**2 / xb
        Ll, Lr = np.hypot(xl, yl), np.hypot(xr - xb, yr - yb)
        f = -np.array([k * (Ll - L0) * xl / Ll, k * (Ll - L0) * yl / Ll + m,
                       k * (Lr - L0) * (xr - xb) / Lr, k * (Lr - L0) * (yr - yb) / Lr + m])
        dx, dy, dvx, dvy = xl - xr, yl - yr, vxl - vxr, vyl - vyr
        A = np.array([[xb, yb, 0, 0], [2 * dx, 2 * dy, -2 * dx, -2 * dy]])
        c = -np.array([2 * vxl * dxb + xl * ddxb + 2 * vyl * dyb + yl * ddyb, 2 * (dvx**2 + dvy**2)])
        K = np.block([[m * np.eye(4), A.T], [A, np.zeros((2, 2))]])
        return np.concatenate([z[4:], np.linalg.solve(K, np.concatenate([f, c]))[:4]])

    z0 = [CAR_IC[n] for n in ("x_l", "y_l", "x_r", "y_r", "x_l_dot", "y_l_dot", "x_r_dot", "y_r_dot")]
    res = solve_ivp(rhs, (0.0, float(times[-1])), z0, method="DOP853", t_eval=times, rtol=1e-13, atol=1e-13)
    return res.y[:4].T


def _car_axis(quick: bool) -> HardProblem:
    return HardProblem(
        "car_axis", "car axis (test set), springs k = 10⁴, index 3 and stiff, t ∈ [0, 0.05]", car_axis, CAR, CAR_IC,
        0.05, _names("x_l", "y_l", "x_r", "y_r"), car_axis_reference,
        "hand-written index-1 formulation (KKT solve), scipy DOP853 rtol 1e-13", (1e-6,) if quick else (1e-6, 1e-9),
        atol_scale=1e-2, n_points=11, step=1e-5)


def _double_pendulum_reference(times: np.ndarray) -> np.ndarray:
    sol = n_link_pendulum(2).simulate((0.0, float(times[-1])), _DP_IC, {"g": 9.81}, method="taylor", rtol=1e-14,
                                      atol=1e-14, t_eval=times)
    return sol.y


_DP_IC = {"q1": 2.5, "q2": -2.0, "q1_dot": 0.0, "q2_dot": 0.0}


def _double_pendulum(quick: bool) -> HardProblem:
    t_end = 10.0 if quick else 30.0
    return HardProblem(
        "double_pendulum", f"double pendulum at high energy, q = (2.5, −2.0), t ∈ [0, {t_end:g}]: chaotic",
        lambda: n_link_pendulum(2), {"g": 9.81}, _DP_IC, t_end, lambda sol: sol.y, _double_pendulum_reference,
        "the Taylor method at rtol 1e-14 (a second method); error over t ≤ 1 (before the "
        "chaos amplifies every local error), then each run's horizon of agreement",
        (1e-6,) if quick else (1e-6, 1e-10), error_until=1.0, horizon=True, n_points=501,
        step=1e-2 if quick else 2e-3)


_KEPLER_E = 0.9


def _kepler(quick: bool) -> HardProblem:
    y0 = kepler_state([0.0], e=_KEPLER_E)[0]
    revs = 3 if quick else 10
    return HardProblem(
        "kepler", f"Kepler orbit, e = 0.9, a = μ = 1, {revs} periods", kepler_system, {"m": 1.0, "mu": 1.0},
        {"x": y0[0], "y": y0[1], "x_dot": y0[2], "y_dot": y0[3]}, 2 * math.pi * revs, _names("x", "y"),
        lambda times: kepler_state(times, e=_KEPLER_E)[:, :2], "closed form through Kepler's equation",
        (1e-6,) if quick else (1e-6, 1e-10), n_points=10 * revs + 1, step=5e-3)


def cone_system() -> System:
    """V = k √(x² + ε²) on a mass m: a force ≈ −k sign(x) outside |x| ≲ ε."""
    x = coordinates("x")
    m, k, eps = parameters("m k epsilon")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * sp.sqrt(x**2 + eps**2), name="regularized cone")


_CONE = {"m": 1.0, "k": 1.0, "epsilon": 1e-4}


def _cone_reference(times: np.ndarray) -> np.ndarray:
    sol = cone_system().simulate((0.0, float(times[-1])), {"x": 1.0, "x_dot": 0.0}, _CONE, method="Radau",
                                 rtol=1e-13, atol=1e-13, t_eval=times)
    return sol.y[:, :1]


def _cone(quick: bool) -> HardProblem:
    t_end = 10.0 if quick else 20.0
    return HardProblem(
        "cone", f"V = k √(x² + ε²), ε = 1e-4, x(0) = 1, t ∈ [0, {t_end:g}]: a kink", cone_system, _CONE,
        {"x": 1.0, "x_dot": 0.0}, t_end, _names("x"), _cone_reference,
        "Radau rtol 1e-13 (within O(ε) of the ε → 0 closed form)", (1e-6,) if quick else (1e-6, 1e-9),
        n_points=101, step=5e-3 if quick else 1e-3)


def stick_slip_system() -> System:
    """Block on a spring with Coulomb friction, Wells' power function P = −μ m |ẋ| (μg in one parameter)."""
    x = coordinates("x")
    m, k, mu = parameters("m k mu")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * sp.Abs(x.diff(t)), name="stick-slip")


#: where the block (ω = 1, μg = 0.1, x(0) = 0.3, v(0) = 1) comes to rest: turning points alternate about ∓μg,
#: each amplitude 2μg smaller
STICK_REST = 1.1 - math.sqrt(1.16)


def _stick_slip(quick: bool) -> HardProblem:
    return HardProblem(
        "stick_slip", "block on a spring, Coulomb friction regularized (ε = 1e-6), at rest from t ≈ 17 at 1.1 − √1.16",
        stick_slip_system, {"m": 1.0, "k": 1.0, "mu": 0.1}, {"x": 0.3, "x_dot": 1.0}, 18.0 if quick else 25.0,
        _names("x"),
        lambda times: np.array([[STICK_REST]]), "exact rest position 1.1 − √1.16 (regularization creep ~2e-6)",
        (1e-6,) if quick else (1e-6, 1e-9), at_end=True, floor=5e-6 / STICK_REST, atol_scale=1e-2, n_points=11,
        step=1e-3, options={"friction": "regularize"})


def spherical_system() -> System:
    """Spherical pendulum in (θ, φ), θ from the downward vertical: the coordinates are singular at θ = 0."""
    th, ph = coordinates("theta phi")
    m, g, l = parameters("m g l")
    T = m * l**2 * (th.diff(t) ** 2 + sp.sin(th) ** 2 * ph.diff(t) ** 2) / 2
    return System([th, ph], T=T, V=-m * g * l * sp.cos(th), name="spherical pendulum")


_SPH = {"m": 1.0, "g": 9.81, "l": 1.0}
_SPH_IC = {"theta": 1.0, "phi": 0.0, "theta_dot": 0.0, "phi_dot": 1e-3}


def _cartesian(th, ph, l=1.0):
    return np.column_stack([l * np.sin(th) * np.cos(ph), l * np.sin(th) * np.sin(ph), -l * np.cos(th)])


def spherical_reference(times: np.ndarray) -> np.ndarray:
    """Positions ``(k, 3)`` of the same motion as a particle on |r| = l in Cartesian coordinates:
    ``r̈ = g + λ r`` with ``λ = −(|ṙ|² + g·r)/l²`` (hand-written, scipy DOP853 at rtol 1e-13)."""
    g, l = np.array([0.0, 0.0, -_SPH["g"]]), _SPH["l"]
    th0, w0 = _SPH_IC["theta"], _SPH_IC["phi_dot"]
    r0 = _cartesian(np.array([th0]), np.array([0.0]), l)[0]
    v0 = np.array([0.0, l * np.sin(th0) * w0, 0.0])

    def rhs(_t, z):
        r, v = z[:3], z[3:]
        lam = -(v @ v + g @ r) / l**2
        return np.concatenate([v, g + lam * r])

    res = solve_ivp(rhs, (0.0, float(times[-1])), np.concatenate([r0, v0]), method="DOP853", t_eval=times,
                    rtol=1e-13, atol=1e-13)
    return res.y[:3].T


def _spherical(quick: bool) -> HardProblem:
    t_end = 2.0 if quick else 10.0
    return HardProblem(
        "spherical_pole", f"spherical pendulum (θ, φ) passing ~2e-4 rad from the pole θ = 0, t ∈ [0, {t_end:g}]",
        spherical_system, _SPH, _SPH_IC, t_end, lambda sol: _cartesian(sol["theta"], sol["phi"], _SPH["l"]),
        spherical_reference, "the same motion in Cartesian coordinates with |r| = l, DOP853 rtol 1e-13",
        (1e-6,) if quick else (1e-6, 1e-9), n_points=101, step=5e-3 if quick else 1e-3)


HARD_PROBLEMS: dict[str, Callable[[bool], HardProblem]] = {
    "squeezer": _squeezer, "car_axis": _car_axis, "double_pendulum": _double_pendulum, "kepler": _kepler,
    "cone": _cone, "stick_slip": _stick_slip, "spherical_pole": _spherical,
}


def get_hard_problem(name: str, *, quick: bool = False) -> HardProblem:
    """The hard case ``name``; :class:`~lagrange.errors.SpecError` naming the choices when unknown."""
    if name not in HARD_PROBLEMS:
        raise SpecError(f"unknown hard case {name!r}; choose from {', '.join(HARD_PROBLEMS)}")
    return HARD_PROBLEMS[name](quick)


# --- running ----------------------------------------------------------------------------------------------------

def _first_line(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"


def run_hard_case(problem: HardProblem, system: System, method: str, rtol: float) -> HardRun:
    """Run ``method`` at ``rtol`` on ``problem`` and judge it (module docstring)."""
    options = dict(problem.options)
    fixed = method in ("midpoint", "gl4", "gl6", "verlet", "dg", "verlet6", "verlet8")
    if fixed:
        options["step"] = problem.step
    base = dict(problem=problem.name, method=method, rtol=rtol)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the verdict and the method line carry what the warnings say
            c0 = time.process_time()
            sol = system.simulate((0.0, problem.t_end), problem.initial, problem.params, method=method, rtol=rtol,
                                  atol=rtol * problem.atol_scale, n_points=problem.n_points, **options)
            cpu = time.process_time() - c0
    except LagrangeError as exc:
        if isinstance(exc, TypeError):  # MethodError, TapeError: the method refuses this kind of system
            return HardRun(**base, outcome="refused", detail=_first_line(exc))
        return HardRun(**base, outcome="ERRORED", detail=_first_line(exc))
    except Exception as exc:  # noqa: BLE001 — the suite records every failure, that is its purpose
        return HardRun(**base, outcome="ERRORED", detail=_first_line(exc))
    used = sol.method.split(";")[0].split(" (")[0]
    drift = float(sol.max_constraint_violation()) if system.constraints else None
    failed = tuple(c.name for c in sol.verdict.failed)
    stopped = sol.status.name == "STOPPED"
    if stopped or len(sol.t) < 2:
        return HardRun(**base, outcome="flagged", cpu=cpu, drift=drift, checks_failed=failed or ("stopped",),
                       used=used, detail=str(sol.message).splitlines()[0] if sol.message else "")
    times = np.asarray(sol.t)
    obs, ref = np.asarray(problem.observe(sol), dtype=float), np.asarray(problem.reference(times), dtype=float)
    if problem.at_end:
        obs = obs[-1:]
    scale = float(np.max(np.abs(ref))) or 1.0
    horizon = None
    if problem.horizon:
        tdiv = divergence_time(times, obs, ref, HORIZON_THRESHOLD)
        horizon = problem.t_end if tdiv is None else float(tdiv)
    if problem.error_until is not None:
        keep = times <= problem.error_until + 1e-12
        obs, ref = obs[keep], ref[keep]
    error = float(np.max(np.abs(obs - ref))) / scale if np.all(np.isfinite(obs)) else math.inf
    wrong = not error <= SILENT_FACTOR * rtol + problem.floor
    if not sol.verdict.ok:
        outcome = "flagged"
    else:
        outcome = "SILENTLY WRONG" if wrong else "accurate"
    return HardRun(**base, outcome=outcome, error=error, cpu=cpu, drift=drift, checks_failed=failed, used=used,
                   horizon=horizon)


def run_hard_suite(problems=None, *, quick: bool = False, methods=None, log: Callable[[str], None] | None = print
                   ) -> list[HardRun]:
    """Every method (``methods``, default :data:`QUICK_METHODS` or :data:`FULL_METHODS`) at every tolerance on
    every problem (default all of :data:`HARD_PROBLEMS`); returns the runs in order."""
    say = log or (lambda s: None)
    chosen = [get_hard_problem(n, quick=quick) for n in (problems or HARD_PROBLEMS)]
    methods = tuple(methods or (QUICK_METHODS if quick else FULL_METHODS))
    runs = []
    for problem in chosen:
        system = problem.build()
        _ = system.derived  # derived before the timed runs: the first method is not charged for it
        for rtol in problem.tolerances:
            for method in methods:
                run = run_hard_case(problem, system, method, rtol)
                say(f"{problem.name:16s} {method:8s} rtol {rtol:.0e}: {run.outcome} "
                    f"(error {run.error:.2g}, CPU {run.cpu:.3g} s)")
                runs.append(run)
    return runs


# --- report -----------------------------------------------------------------------------------------------------

COLUMNS = ("problem", "method", "rtol", "outcome", "error", "CPU s", "constraint drift", "verdict", "failed checks",
           "used", "horizon", "detail")


def _fmt(v, spec=".2g"):
    return "" if v is None or (isinstance(v, float) and math.isnan(v)) else format(v, spec)


def render_hard_markdown(runs: list[HardRun], *, quick: bool = False) -> str:
    """The table of ``runs`` (one row per run, :data:`COLUMNS`) with the references and the legend."""
    mode = "quick" if quick else "full"
    lines = [f"# Hard cases ({mode} mode)", "",
             "Reproduce: `lagrange bench --hard" + (" --quick" if quick else "") + " --out benchmarks/results` "
             "(or `python benchmarks/hard_cases.py" + (" --quick" if quick else "") + "`).", "",
             f"error: relative (max |y − y_ref| / max |y_ref|); SILENTLY WRONG: error > {SILENT_FACTOR:g}·rtol "
             "(+ the reference's floor) while the run's verdict says accurate; flagged: the run's own checks "
             f"failed or it stopped; horizon (chaotic problems): time until the run departs from the reference by "
             f"{HORIZON_THRESHOLD:g}.", "", "References:", ""]
    for name in dict.fromkeys(r.problem for r in runs):
        p = get_hard_problem(name, quick=quick)
        lines.append(f"- **{name}**: {p.title}; reference: {p.reference_note}")
    lines += ["", "| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    for r in runs:
        verdict = "" if r.outcome in ("refused", "ERRORED") else ("accurate" if not r.checks_failed else "INACCURATE")
        cells = (r.problem, r.method, f"{r.rtol:.0e}", f"**{r.outcome}**" if r.outcome == "SILENTLY WRONG" else
                 r.outcome, _fmt(r.error), _fmt(r.cpu, ".3g"), _fmt(r.drift), verdict, ", ".join(r.checks_failed),
                 r.used, _fmt(r.horizon, ".3g"), r.detail.replace("|", "/")[:120])
        lines.append("| " + " | ".join(cells) + " |")
    silent = [r for r in runs if r.outcome == "SILENTLY WRONG"]
    lines += ["", f"Silently wrong runs: {len(silent)}."]
    return "\n".join(lines) + "\n"


def write_hard_report(runs: list[HardRun], out, *, quick: bool = False, name: str = "hard_cases") -> dict:
    """Write ``name.md`` (the table) and ``name_<problem>.png`` (error against CPU per method) into ``out``;
    returns their paths."""
    from pathlib import Path

    from ..plot.hard_cases import plot_hard_case

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"md": out / f"{name}.md", "png": []}
    paths["md"].write_text(render_hard_markdown(runs, quick=quick))
    for problem in dict.fromkeys(r.problem for r in runs):
        png = out / f"{name}_{problem}.png"
        plot_hard_case([r for r in runs if r.problem == problem], get_hard_problem(problem, quick=quick).title, png)
        paths["png"].append(png)
    return paths
