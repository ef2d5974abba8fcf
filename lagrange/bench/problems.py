r"""The benchmark problems: a :class:`~lagrange.System`, parameters, initial state, horizon and truth.

Each :class:`BenchProblem` says how its error is measured: against a closed form (Kepler orbit through
Kepler's equation; the mass on a moving belt, piecewise harmonic with a stick phase) or against a tight
numerical reference whose self-consistency the runner reports (:mod:`lagrange.bench.runner`).

=================  ==============================================================================
name               what
=================  ==============================================================================
double_pendulum    planar double pendulum, q = (0.6, −0.3), t ∈ [0, 10] (numerics.md "moderate")
nlink              planar 5-link pendulum, q_i = 0.6(−1)^i/(i+1), t ∈ [0, 10]
top                heavy symmetric top, :class:`~lagrange.RigidBody` with Wells' Euler angles
kepler             Kepler orbit, e = 0.5, ten revolutions; closed form via Kepler's equation
stiff              double pendulum with a strongly damped elbow (Rayleigh, c = 10³): stiff
stick_slip         mass on a spring on a moving belt, Coulomb friction; closed-form stick-slip cycle
greenspan          Greenspan's tetrahedral top (rigid model, 5 DOF), example 1
=================  ==============================================================================
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import field

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import SpecError
from ..examples import n_link_pendulum
from ..model.bodies import Particle
from ..model.coordinates import coordinates, parameters
from ..model.rigid_body import RigidBody
from ..model.rotations import EulerAngles
from ..model.system import System
from ..records import record

__all__ = ["BenchProblem", "PROBLEMS", "MAX_LINKS", "get_problem", "derivation_options", "kepler_state", "belt_state",
           "belt_stick_interval"]


@record(frozen=True)
class BenchProblem:
    """One benchmark problem.

    Attributes
    ----------
    name, title : identifier and one-line description
    build : () -> System (the derivation happens here, so timing it times the derivation)
    params : parameter values by name
    initial : initial values by name (``"q"``, ``"q_dot"``)
    t_end : horizon (t0 = 0)
    exact : ``exact(times) -> ndarray (k, 2n)`` closed form, or None (numerical reference)
    sample_times : error measured as the max over these times (default: the final state only)
    conservative : energy conserved (geometric methods and energy-vs-time runs apply)
    separable : constant mass matrix and V(q) (Störmer–Verlet applies)
    geometric : run the geometric fixed-step methods (conservative, unconstrained problems)
    pendulum_links : N for a planar N-link pendulum (the plain sympy.physics.mechanics route applies)
    reference_method : scipy method of the numerical reference
    atol_scale : atol = atol_scale · rtol in every tolerance sweep
    steps : fixed steps h for the geometric methods' sweep
    long_t_end, long_steps : long run for energy against time (conservative problems)
    options : extra ``simulate`` options (e.g. ``friction``)
    notes : printed under the problem's table
    """

    name: str
    title: str
    build: Callable[[], System]
    params: dict
    initial: dict
    t_end: float
    exact: Callable[[np.ndarray], np.ndarray] | None = None
    sample_times: tuple = ()
    conservative: bool = True
    separable: bool = False
    geometric: bool = True
    pendulum_links: int = 0
    reference_method: str = "DOP853"
    atol_scale: float = 1.0
    steps: tuple = ()
    long_t_end: float = 0.0
    long_steps: tuple = ()
    options: dict = field(default_factory=dict)
    notes: str = ""

    def times(self) -> np.ndarray:
        """Where the error is measured: ``sample_times`` or ``[t_end]``."""
        return np.asarray(self.sample_times if self.sample_times else (self.t_end,), dtype=float)


# --- closed forms ---------------------------------------------------------------------------------------
def kepler_state(times, *, a: float = 1.0, e: float = 0.5, mu: float = 1.0) -> np.ndarray:
    r"""Cartesian state ``[x, y, ẋ, ẏ]`` of a Kepler orbit starting at perihelion on the +x axis.

    Mean anomaly :math:`M = n t` with :math:`n = \sqrt{\mu/a^3}`; Kepler's equation :math:`E − e\sin E = M`
    solved by Newton's method to round-off; :math:`x = a(\cos E − e)`, :math:`y = b \sin E`,
    :math:`b = a\sqrt{1−e^2}`, :math:`\dot E = n/(1 − e\cos E)`.

    >>> [round(float(v), 6) + 0.0 for v in kepler_state([0.0])[0]]
    [0.5, 0.0, 0.0, 1.732051]
    """
    tt = np.asarray(times, dtype=float)
    n = math.sqrt(mu / a**3)
    M = n * tt
    E = M + e * np.sin(M)
    for _ in range(50):
        dE = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
        E = E - dE
        if np.max(np.abs(dE), initial=0.0) < 1e-15:
            break
    b = a * math.sqrt(1.0 - e * e)
    Ed = n / (1.0 - e * np.cos(E))
    return np.column_stack([a * (np.cos(E) - e), b * np.sin(E), -a * np.sin(E) * Ed, b * np.cos(E) * Ed])


def belt_stick_interval(*, v0: float = 0.5, mu_g: float = 0.5, omega: float = 1.0, belt: float = 0.2
                        ) -> tuple[float, float]:
    r"""(t1, t2): the stick phase of :func:`belt_state` (the block moves with the belt for t1 ≤ t ≤ t2).

    Slip with :math:`σ = \operatorname{sign}(v_0 − v_b)` (v0 ≠ vb):
    :math:`\dot x = −σcω\sin ωt + v_0\cos ωt = R\cos(ωt + φ)`, :math:`R = \sqrt{v_0^2 + c^2ω^2}`,
    :math:`φ = \operatorname{atan2}(σcω, v_0)`, so :math:`ωt_1 = σ\arccos(v_b/R) − φ`; then
    :math:`t_2 = t_1 + (c − x(t_1))/v_b`.

    >>> [round(v, 6) for v in belt_stick_interval(v0=0.0)]
    [0.411517, 2.702805]
    """
    c = mu_g / omega**2
    sigma = 1.0 if v0 > belt else -1.0
    R = math.hypot(v0, c * omega)
    phi = math.atan2(sigma * c * omega, v0)
    t1 = (sigma * math.acos(belt / R) - phi) / omega
    x1 = -sigma * c * (1 - math.cos(omega * t1)) + v0 / omega * math.sin(omega * t1)
    if not -c <= x1 <= c:  # pragma: no cover - outside the benchmark's settings
        raise ValueError("the block does not stick (|x1| > μg/ω²)")
    return t1, t1 + (c - x1) / belt


def belt_state(times, *, v0: float = 0.5, mu_g: float = 0.5, omega: float = 1.0, belt: float = 0.2) -> np.ndarray:
    r"""State ``[x, ẋ]`` of a mass on a spring (ω² = k/m) on a belt moving at ``belt`` with dry friction
    :math:`μ m g` (static = kinetic), starting at x = 0 with speed ``v0`` ≠ ``belt``.

    Slip: :math:`\ddot x = −ω^2 x − σμg`, :math:`σ = \operatorname{sign}(v_0 − v_b)`, until the block
    reaches the belt speed at t1 (:func:`belt_stick_interval`). Stick: :math:`x = x_1 + v_b(t − t_1)` until
    the spring force reaches μmg at x = c = μg/ω² (t2). Then the limit cycle
    :math:`x = c + (v_b/ω)\sin ω(t − t_2)`, whose velocity only touches the belt speed (no further sticking).
    """
    tt = np.asarray(times, dtype=float)
    c = mu_g / omega**2
    sigma = 1.0 if v0 > belt else -1.0
    t1, t2 = belt_stick_interval(v0=v0, mu_g=mu_g, omega=omega, belt=belt)
    x1 = -sigma * c * (1 - math.cos(omega * t1)) + v0 / omega * math.sin(omega * t1)
    ws = omega * tt
    x = np.where(tt < t1, -sigma * c * (1 - np.cos(ws)) + v0 / omega * np.sin(ws),
                 np.where(tt < t2, x1 + belt * (tt - t1), c + belt / omega * np.sin(omega * (tt - t2))))
    v = np.where(tt < t1, -sigma * c * omega * np.sin(ws) + v0 * np.cos(ws),
                 np.where(tt < t2, belt, belt * np.cos(omega * (tt - t2))))
    return np.column_stack([x, v])


# --- systems --------------------------------------------------------------------------------------------
def heavy_top() -> System:
    """Heavy symmetric top on a fixed tip: RigidBody(M, (I1, I1, I3)), Wells' Euler angles (ψ, θ, φ)."""
    psi, th, ph = coordinates("psi theta phi")
    M, g, l, I1, I3 = parameters("M g l I1 I3")
    top = RigidBody(M, (I1, I1, I3), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
    return System([psi, th, ph], bodies=[top], V=M * g * top.centre_of_mass[2], name="heavy symmetric top")


def kepler_system() -> System:
    """A particle of mass m in the potential −μ m / r, Cartesian coordinates (x, y)."""
    x, y = coordinates("x y")
    m, mu = parameters("m mu")
    return System([x, y], bodies=[Particle(m, (x, y))], V=-mu * m / sp.sqrt(x**2 + y**2), name="Kepler orbit")


def damped_double_pendulum() -> System:
    """Double pendulum with a damped elbow joint: Rayleigh ``c (q̇2 − q̇1)²/2``.

    For large ``c`` the relative motion decays fast (rate ≈ 3.9e3/s at c = 10³) while the pendulum as a whole
    keeps swinging undamped: a stiff problem whose slow motion still needs accuracy.
    """
    base = n_link_pendulum(2)
    q1, q2 = base.coordinates
    c = parameters("c")
    return System(base.coordinates, bodies=base.bodies, V=base.V,
                  rayleigh=c * (q2.diff(t) - q1.diff(t)) ** 2 / 2, name="damped double pendulum")


_BELT = sp.Rational(1, 5)


def belt_system(belt=_BELT) -> System:
    """Mass on a spring on a belt moving at speed ``belt``: Wells' power function ``P = −μmg|ẋ − belt|``.

    The belt speed is a number here so the closed form (:func:`belt_state`) matches it exactly; a parameter
    works too (tests/numerics/test_hard_cases.py).
    """
    x = coordinates("x")
    m, k, mu, g = parameters("m k mu g")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * g * sp.Abs(x.diff(t) - belt),
                  name="mass on a moving belt")


def _greenspan_system() -> System:
    from ..discrete.greenspan import rigid_system

    return rigid_system()[0]


def _greenspan_initial() -> dict:
    from ..discrete.greenspan import EXAMPLES, rigid_initial

    ic = rigid_initial(EXAMPLES[1], coordinates("X Y psi theta phi"))
    return {_name(k): float(v) for k, v in ic.items()}


def _name(key) -> str:
    if isinstance(key, sp.Derivative):
        return key.expr.func.__name__ + "_dot"
    return key.func.__name__


def _pendulum_initial(n: int) -> dict:
    ic = {f"q{i + 1}": 0.6 * (-1) ** i / (i + 1) for i in range(n)}
    return ic | {f"q{i + 1}_dot": 0.0 for i in range(n)}


# --- the registry ---------------------------------------------------------------------------------------
def _double_pendulum(quick: bool) -> BenchProblem:
    return BenchProblem(
        "double_pendulum", "planar double pendulum (unit masses and rods), q = (0.6, −0.3), t ∈ [0, 10]",
        lambda: n_link_pendulum(2), {"g": 9.81}, _pendulum_initial(2), 10.0, pendulum_links=2,
        steps=(0.05, 0.02, 0.01) if not quick else (0.05,), long_t_end=20.0 if quick else 200.0,
        long_steps=(0.02,))


def _nlink(quick: bool, n: int = 5, system_kwargs: dict | None = None) -> BenchProblem:
    kw = dict(system_kwargs or {})
    return BenchProblem(
        "nlink" if n == 5 else f"nlink{n}", f"planar {n}-link pendulum, q_i = 0.6(−1)^i/(i+1), t ∈ [0, 10]",
        lambda: n_link_pendulum(n, **kw), {"g": 9.81}, _pendulum_initial(n), 10.0, pendulum_links=n, geometric=False,
        notes="Sensitive dependence: errors grow ~1e5-fold over t = 10, so rtol is not the achieved accuracy. "
              "The geometric methods (which build in about a second here) are compared on the double pendulum, "
              "the top and Kepler, where fixed steps can reach the reference.")


def _top(quick: bool) -> BenchProblem:
    ic = {"psi": 0.0, "theta": 0.6, "phi": 0.0, "psi_dot": 1.0, "theta_dot": 0.0, "phi_dot": 60.0}
    return BenchProblem(
        "top", "heavy symmetric top (RigidBody, Wells' Euler angles), spin 60 rad/s, θ0 = 0.6, t ∈ [0, 5]",
        heavy_top, {"M": 1.0, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}, ic, 1.0 if quick else 5.0,
        steps=(0.005, 0.002) if not quick else (0.005,), long_t_end=2.0 if quick else 50.0,
        long_steps=(0.005,))


def _kepler(quick: bool) -> BenchProblem:
    y0 = kepler_state([0.0])[0]
    ic = {"x": y0[0], "y": y0[1], "x_dot": y0[2], "y_dot": y0[3]}
    revs = 2 if quick else 10
    return BenchProblem(
        "kepler", f"Kepler orbit, e = 0.5, a = μ = 1, {revs} revolutions; closed form via Kepler's equation",
        kepler_system, {"m": 1.0, "mu": 1.0}, ic, 2 * math.pi * revs, exact=kepler_state, separable=True,
        steps=(0.02, 0.01) if not quick else (0.01,), long_t_end=2 * math.pi * (3 if quick else 50),
        long_steps=(0.02,))


def _stiff(quick: bool) -> BenchProblem:
    return BenchProblem(
        "stiff", "double pendulum with a damped elbow c = 10³ (Rayleigh), q = (0.3, −0.2), t ∈ [0, 10]: stiff",
        damped_double_pendulum, {"g": 9.81, "c": 1e3}, {"q1": 0.3, "q2": -0.2, "q1_dot": 0.0, "q2_dot": 0.0},
        10.0, conservative=False, reference_method="Radau", atol_scale=1e-2,
        notes="Fastest decay rate ≈ 3.9e3/s while the pendulum swings on: explicit methods are limited by "
              "stability, not accuracy.")


def _stick_slip(quick: bool) -> BenchProblem:
    T = 15.0 if quick else 30.0
    return BenchProblem(
        "stick_slip", "mass on a spring thrown onto a moving belt (Coulomb friction μg = 0.5, belt 0.2, "
        "v0 = 0.5, ω = 1); closed-form slip, stick and limit cycle", belt_system,
        {"m": 1.0, "k": 1.0, "mu": 0.5, "g": 1.0},
        {"x": 0.0, "x_dot": 0.5}, T, exact=lambda tt: belt_state(tt), sample_times=tuple(np.linspace(0, T, 301)),
        conservative=False,
        notes="Error = max over 301 times of |state − closed form|. friction='events' switches exactly "
              "(Filippov sticking); friction='regularize' replaces sign(v) by v/√(v² + ε²).")


def _greenspan(quick: bool) -> BenchProblem:
    return BenchProblem(
        "greenspan", "Greenspan's tetrahedral top, example 1 (V = 4, α = 15°), rigid model (5 DOF), t ∈ [0, 10]",
        _greenspan_system, {"g": 0.980}, _greenspan_initial(), 2.0 if quick else 10.0, atol_scale=1e-2,
        geometric=False,
        notes="The molecular model (discrete gradient, dt = 1e-5) is measured by benchmarks/greenspan.py; that is "
              "the structure-preserving method for this problem, so no geometric rows here.")


PROBLEMS: dict[str, Callable[[bool], BenchProblem]] = {
    "double_pendulum": _double_pendulum, "nlink": _nlink, "top": _top, "kepler": _kepler, "stiff": _stiff,
    "stick_slip": _stick_slip, "greenspan": _greenspan,
}


#: the largest N of the ``"nlink<N>"`` problems
MAX_LINKS = 50


def get_problem(name: str, *, quick: bool = False, system_kwargs: dict | None = None) -> BenchProblem:
    """The problem called ``name`` (see :data:`PROBLEMS`; also ``"nlink<N>"``, the planar N-link pendulum for
    2 ≤ N ≤ :data:`MAX_LINKS`, outside the default suite); ``quick`` shortens horizons and sweeps.

    ``system_kwargs`` are passed to :class:`~lagrange.System` when an N-link pendulum is built (e.g.
    :func:`derivation_options`); the other problems refuse them (``SpecError``).

    >>> get_problem("kepler").t_end == 20 * math.pi
    True
    >>> get_problem("nlink10").pendulum_links
    10
    """
    m = re.fullmatch(r"nlink(\d+)", name)
    if m and 2 <= int(m.group(1)) <= MAX_LINKS:
        return _nlink(quick, int(m.group(1)), system_kwargs)
    if name not in PROBLEMS:
        raise SpecError(f"unknown benchmark problem {name!r}; choose from {', '.join(PROBLEMS)} or nlink<N> "
                        f"(2 ≤ N ≤ {MAX_LINKS})")
    if system_kwargs and name != "nlink":
        raise SpecError(f"System options ({', '.join(system_kwargs)}) are passed through for the N-link "
                        f"pendulums only, not for {name!r}")
    if name == "nlink":
        return _nlink(quick, 5, system_kwargs)
    return PROBLEMS[name](quick)


def derivation_options(derivation: str | None) -> dict:
    """``{"derivation": derivation}`` for :class:`~lagrange.System`, or ``{}`` for None (the default path).

    The benchmarks pass it through to the N-link pendulum (:func:`get_problem`) so they can be re-run with
    ``System(..., derivation="structural"|"expanded"|"auto")`` once that keyword exists; when the installed
    System does not take it, a :class:`~lagrange.errors.SpecError` (a ``ValueError``) says so instead of
    silently measuring the default path.

    >>> derivation_options(None)
    {}
    """
    if derivation is None:
        return {}
    import inspect

    if "derivation" not in inspect.signature(System.__init__).parameters:
        raise SpecError(f"derivation={derivation!r} was asked for, but this lagrange's System takes no "
                        "'derivation' keyword (the structural derivation is not in this version)")
    return {"derivation": derivation}
