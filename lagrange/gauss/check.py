r"""The Lagrange-vs-Gauss cross-check of a :class:`~lagrange.System` (reference test designs T-A, T-B).

Two independent routes to the accelerations at the same state ``(t, q, q̇)``:

* **Lagrange** — the engine's derived and generated ``M q̈ = f (+ Aᵀλ)`` (``system.compile``), mapped to
  Cartesian point accelerations ``ẍ = J q̈ + a0``;
* **Gauss** — the bodies as mass points (:mod:`lagrange.gauss.masspoints`; no ``d/dt ∂T/∂q̇``, no M or f of
  the derivation), and one least-constraint KKT solve in the redundant variables ``(ẍ, q̈)``:

  .. math:: \min\ \sum_k \tfrac12 m_k|\ddot x_k|^2 - Q\cdot\ddot q
            \quad\text{s.t.}\quad \ddot x - J\ddot q = a_0,\ \ A\ddot q = c ,

  which is Gauss' principle with the applied forces entering through their generalized components
  ``Q = −∂V/∂q + ∂P/∂q̇ − ∂D/∂q̇ + F_q`` (Gibbs–Appell form; Sonneveld eq. (64), recipe R7).

The two must agree to round-off at every state (T-A). The check also compares the kinetic energy of the
mass points with the engine's T and runs a short simulation to report balance laws: the power balance
``d(W + V)/dt = q̇·Q_nc + ∂V/∂t − λ·b + Σ m ẋ_t·ẍ`` (non-potential forces, explicitly time-dependent V,
moving q-constraints, moving frames/supports), and conservation of momentum and angular momentum when
the Gauss solve shows no external force or moment at any sampled state.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import field

import numpy as np
from scipy.integrate import cumulative_simpson

from ..errors import LagrangeError, ParameterError, SingularMassMatrixError
from ..model.coordinates import coordinate_name, key_name
from ..records import record
from .kkt import solve_least_constraint
from .masspoints import MassPointModel, NotApplicable, declared_symbols, mass_point_model

__all__ = ["GaussCheck", "SampleComparison", "BalanceDiagnostics", "check_gauss", "check_problem", "check_spec",
           "gauss_solve", "sample_parameters"]

DEFAULT_Q_RANGE = (0.15, 0.85)
DEFAULT_QD_RANGE = (-0.85, 0.85)


@record(frozen=True, slots=True)
class SampleComparison:
    """One sampled state: ``accel_error`` (Cartesian ẍ), ``qdd_error`` (q̈) and ``energy_error`` (T of the
    points vs the engine's T), each relative; the state ``t``, ``y = [q, q̇]``; ``redundant`` constraint rows."""

    t: float
    y: np.ndarray
    accel_error: float
    qdd_error: float
    energy_error: float
    redundant: int

    @property
    def max_error(self) -> float:
        return max(self.accel_error, self.qdd_error, self.energy_error)


@record(frozen=True, slots=True)
class BalanceDiagnostics:
    """Balance laws along a short run: ``power_residual`` (relative, ``None`` when the run failed),
    ``momentum_drift`` / ``angular_momentum_drift`` (relative; ``None`` when the system is not free of
    external force / moment), ``note`` (why something is missing)."""

    t_end: float
    power_residual: float | None
    momentum_drift: float | None
    angular_momentum_drift: float | None
    note: str = ""

    def ok(self, tol: float) -> bool:
        vals = [v for v in (self.power_residual, self.momentum_drift, self.angular_momentum_drift) if v is not None]
        return all(v < tol for v in vals)


@record(frozen=True)
class GaussCheck:
    """Outcome of :func:`check_gauss`; ``str()`` gives a readable report.

    Attributes
    ----------
    name : the system's name
    applicable : False when the system has no mass-point kinematics; ``reason`` says why
    samples : the compared states
    max_rel_error : worst relative difference over the samples (NaN when not applicable)
    rtol : tolerance of the verdict
    diagnostics : balance laws along a short run (None if not requested or not applicable)
    balance_tol : tolerance for the diagnostics
    """

    name: str
    applicable: bool
    reason: str = ""
    samples: tuple = ()
    max_rel_error: float = float("nan")
    rtol: float = 1e-8
    diagnostics: BalanceDiagnostics | None = None
    balance_tol: float = 1e-6
    n_points: int = 0
    skipped_states: int = 0
    filled_parameters: tuple = field(default=())
    signed_bodies: tuple = field(default=())

    @property
    def agrees(self) -> bool:
        """Lagrange and Gauss accelerations (and kinetic energies) agree at every sample."""
        return self.applicable and bool(self.samples) and self.max_rel_error <= self.rtol

    @property
    def ok(self) -> bool:
        """Agreement and, when available, balance laws within ``balance_tol``."""
        return self.agrees and (self.diagnostics is None or self.diagnostics.ok(self.balance_tol))

    def __str__(self) -> str:
        head = f"Lagrange vs Gauss check of {self.name or 'system'}"
        if not self.applicable:
            return f"{head}: not applicable ({self.reason})"
        lines = [f"{head}: {self.n_points} mass points, {len(self.samples)} random states"
                 + (f" ({self.skipped_states} singular states redrawn)" if self.skipped_states else "")]
        if self.signed_bodies:
            lines.append(f"  signed pseudo-masses for {', '.join(self.signed_bodies)} (inertia not realizable by "
                         "positive point masses; T and S are still exact)")
        if self.filled_parameters:
            lines.append(f"  random values for {', '.join(self.filled_parameters)} (absent from the equations of "
                         "motion; they must not change the accelerations)")
        for k, s in enumerate(self.samples):
            lines.append(f"  state {k + 1}: t={s.t:.4g}  max rel. diff: accelerations {s.accel_error:.2e}, "
                         f"q_ddot {s.qdd_error:.2e}, kinetic energy {s.energy_error:.2e}"
                         + (f"  [{s.redundant} redundant constraint(s)]" if s.redundant else ""))
        verdict = "AGREE" if self.agrees else "DISAGREE"
        lines.append(f"  verdict: {verdict} (max {self.max_rel_error:.2e}, tolerance {self.rtol:.0e})")
        d = self.diagnostics
        if d is not None:
            lines.append(f"  balance laws over t = 0 … {d.t_end:g}:")
            lines.append("    power balance d(T+V)/dt = P_nc + ∂V/∂t + constraint and driver power: "
                         + (f"residual {d.power_residual:.2e}" if d.power_residual is not None else "n/a"))
            for label, v in (("momentum", d.momentum_drift), ("angular momentum", d.angular_momentum_drift)):
                lines.append(f"    {label}: " + (f"conserved, drift {v:.2e}" if v is not None
                                                   else "external force/moment acts (not conserved)"))
            if d.note:
                lines.append(f"    note: {d.note}")
            lines.append(f"  balance laws: {'OK' if d.ok(self.balance_tol) else 'FAIL'} "
                         f"(tolerance {self.balance_tol:.0e})")
        return "\n".join(lines)


def gauss_solve(pm: MassPointModel, t: float, q, qd) -> dict[str, np.ndarray]:
    """The Gauss route at one state: one KKT solve in ``(ẍ, q̈)``.

    Non-physical data (an indefinite inertia from independently drawn moments and products) give a
    stationary point rather than a minimum; it is still the solution Lagrange's equations must match.

    Returns ``xdd`` (3K,), ``qdd`` (n,), ``lam`` (m,) (multipliers of ``A q̈ = c``, library sign
    ``M q̈ = f + Aᵀλ``), the kinematics ``J``, ``a0``, ``xdot``, ``x_t``, ``x`` and the force data.
    """
    x, J, a0, xdot, x_t = pm.kinematics(t, q, qd)
    fd = pm.forces(t, q, qd)
    K, n, m = J.shape[0], pm.n, pm.m
    H = np.zeros((K + n, K + n))
    H[:K, :K] = np.diag(pm.mass_vector)
    g = np.concatenate([np.zeros(K), fd["Q"]])
    C = np.block([[np.eye(K), -J], [np.zeros((m, K)), fd["A"]]])
    d = np.concatenate([a0, fd["c"]])
    names = [f"kinematics of point {i // 3 + 1}" for i in range(K)] + list(pm.constraint_names)
    sol = solve_least_constraint(H, g, C, d, names=names, require_minimum=False)
    return {"xdd": sol.z[:K], "qdd": sol.z[K:], "lam": sol.multipliers[K:], "redundant": sol.redundant,
            "J": J, "a0": a0, "xdot": xdot, "x_t": x_t, "x": x, **fd}


def _rel(a, b, *scales) -> float:
    scale = max([float(np.max(np.abs(v), initial=0.0)) for v in (a, b, *scales)] + [1e-300])
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b)), initial=0.0)) / scale


def _consistent(pm: MassPointModel, t, q, qd) -> tuple[np.ndarray, np.ndarray]:
    """Project q onto the holonomic constraints (Gauss–Newton) and q̇ onto ``A q̇ + b = 0``."""
    for _ in range(30):
        fd = pm.forces(t, q, qd)
        hol = np.isfinite(fd["phi"])
        if not hol.any() or np.max(np.abs(fd["phi"][hol])) < 1e-14:
            break
        q = q - np.linalg.lstsq(fd["A"][hol], fd["phi"][hol], rcond=1e-12)[0]
    fd = pm.forces(t, q, qd)
    if pm.m:
        qd = qd - np.linalg.lstsq(fd["A"], fd["A"] @ qd + fd["b"], rcond=1e-12)[0]
    return q, qd


def _draw(rng, names, ranges) -> tuple[float, np.ndarray, np.ndarray]:
    def u(key, default):
        lo, hi = ranges.get(key, default)
        return rng.uniform(lo, hi)

    q = np.array([u(nm, DEFAULT_Q_RANGE) for nm in names])
    qd = np.array([u(nm + "_dot", DEFAULT_QD_RANGE) for nm in names])
    return float(u("t", DEFAULT_Q_RANGE)), q, qd


def _compare(pm, model, t, q, qd) -> SampleComparison:
    G = gauss_solve(pm, t, q, qd)
    y = np.concatenate([q, qd])
    qdd_L = np.asarray(model.fun(t, y), dtype=float)[pm.n:2 * pm.n]
    xdd_L = G["J"] @ qdd_L + G["a0"]
    if not (np.all(np.isfinite(xdd_L)) and np.all(np.isfinite(G["xdd"]))):
        raise SingularMassMatrixError("non-finite accelerations")
    W = 0.5 * G["xdot"] @ (pm.mass_vector * G["xdot"])
    T_L = float(model.diagnostics(np.array([t]), y[None, :])["T"][0])
    x_scale = max(float(np.max(np.abs(v), initial=0.0)) for v in (G["xdd"], xdd_L, G["a0"]))
    q_scale = x_scale / max(float(np.linalg.norm(G["J"], 2)), 1e-300)  # Cartesian scale in q units
    return SampleComparison(t, y, _rel(G["xdd"], xdd_L, G["a0"]), _rel(G["qdd"], qdd_L, [q_scale]),
                            abs(W - T_L) / max(abs(W), abs(T_L), 1e-300), G["redundant"])


def _external(pm, states) -> tuple[bool, bool]:
    """(free of external force, free of external moment) judged by the Gauss solve at the states."""
    m, am = pm.masses, np.abs(pm.masses)
    free_p = free_b = True
    for t, q, qd in states:
        G = gauss_solve(pm, t, q, qd)
        a = G["xdd"].reshape(-1, 3)
        x = G["x"]
        scale = float(np.sum(am * np.linalg.norm(a, axis=1))) + 1e-300
        free_p &= bool(np.linalg.norm(m @ a) <= 1e-9 * scale)
        bscale = float(np.sum(am * np.linalg.norm(x, axis=1) * np.linalg.norm(a, axis=1))) + 1e-300
        free_b &= bool(np.linalg.norm((m[:, None] * np.cross(x, a)).sum(axis=0)) <= 1e-9 * bscale)
    return free_p, free_b


def _run_diagnostics(system, pm, params, initial, t_run, states) -> BalanceDiagnostics:
    try:
        sol = system.simulate(t_run, initial, params, rtol=1e-11, atol=1e-12, n_points=401)
    except LagrangeError as exc:
        return BalanceDiagnostics(t_run, None, None, None, f"run failed: {exc}")
    qdd = sol.accelerations
    n = pm.n
    W, V, P, Wt, p, b, ps, bs = ([] for _ in range(8))
    mv = pm.mass_vector
    for ti, yi, ai in zip(sol.t, sol.y, qdd):
        G = gauss_solve(pm, ti, yi[:n], yi[n:])
        xdd = G["J"] @ ai + G["a0"]
        W.append(0.5 * G["xdot"] @ (mv * G["xdot"]))
        V.append(G["V"])
        Wt.append(0.5 * G["x_t"] @ (mv * G["x_t"]))
        P.append(yi[n:] @ G["Q_nc"] + G["dV_dt"] - G["lam"] @ G["b"] + G["x_t"] @ (mv * xdd))
        v = G["xdot"].reshape(-1, 3)
        p.append(pm.masses @ v)
        b.append((pm.masses[:, None] * np.cross(G["x"], v)).sum(axis=0))
        speed = np.linalg.norm(v, axis=1)
        ps.append(np.abs(pm.masses) @ speed)
        bs.append(np.abs(pm.masses) @ (np.linalg.norm(G["x"], axis=1) * speed))
    W, V, P, p, b = map(np.array, (W, V, P, p, b))
    E = W + V
    work = cumulative_simpson(P, x=sol.t, initial=0.0)
    abs_work = cumulative_simpson(np.abs(P), x=sol.t, initial=0.0)
    scale = max(float(np.max(W)), float(np.max(np.abs(V - V[0]))), float(abs_work[-1]), max(Wt), 1e-300)
    power = float(np.max(np.abs(E - E[0] - work))) / scale
    free_p, free_b = _external(pm, states)
    drift = [float(np.max(np.abs(a - a[0]))) / max(max(sc), 1e-300) if free else None
             for a, sc, free in ((p, ps, free_p), (b, bs, free_b))]
    note = ("" if sol.success else f"the run failed its accuracy checks: {sol.verdict.summary()}"
            if sol.verdict is not None and not sol.verdict.ok else f"run stopped at t={sol.t[-1]:.4g}: {sol.message}")
    return BalanceDiagnostics(float(sol.t[-1]), power, drift[0], drift[1], note)


def _complete(system, params: Mapping, rng) -> tuple[dict, tuple]:
    """Parameters by name; symbols the kinematics need but the equations do not (a constant offset in a
    position, the mass of a particle at a fixed point) get random values from the corpus' parameter range
    — they must not change the accelerations."""
    from ..corpus.compare import PARAMETER_RANGE

    out = {str(getattr(k, "name", k)): v for k, v in params.items()}
    known = {s.name for s in declared_symbols(system)} | {s.name for s in system.parameters}
    unknown = sorted(set(out) - known)
    if unknown:
        raise ParameterError(f"unknown parameter(s) {', '.join(unknown)} (this system's parameters: "
                             f"{', '.join(sorted(known)) or 'none'})")
    engine = set(system.derived.parameters)  # a declared parameter may cancel out of the equations
    missing = sorted(s.name for s in declared_symbols(system) if s.name not in out and s not in engine)
    out.update({nm: float(rng.uniform(*PARAMETER_RANGE)) for nm in missing})
    return out, tuple(missing)


def check_gauss(system, params: Mapping, *, samples: int = 5, seed: int = 0, rtol: float = 1e-8,
                ranges: Mapping | None = None, initial: Mapping | None = None, diagnostics: bool = True,
                t_run: float = 1.0, balance_tol: float = 1e-6) -> GaussCheck:
    r"""Compare the accelerations of ``system`` from Lagrange's equations and from Gauss' principle.

    Parameters
    ----------
    system : :class:`~lagrange.System`
    params : parameter values (keys: symbols or names)
    samples : number of random states (seeded; singular states are redrawn)
    seed : seed of the ``numpy`` generator
    rtol : tolerance on the relative differences (Cartesian accelerations, q̈, kinetic energy)
    ranges : ``{name: (lo, hi)}`` for coordinates (``"x"``), velocities (``"x_dot"``) and ``"t"``; defaults
        q ∈ [0.15, 0.85], q̇ ∈ [−0.85, 0.85], t ∈ [0.15, 0.85]. States are projected onto the constraints.
    initial : a state for the first sample and for the diagnostics run (default: the first random state)
    diagnostics : run ``t_run`` time units and report the balance laws
    balance_tol : tolerance of the balance laws in :attr:`GaussCheck.ok`

    Returns
    -------
    GaussCheck
        ``applicable=False`` (with the reason) when T is given directly, a constraint is rough, a body is
        not a particle or rigid body, or no regular state is found.

    Examples
    --------
    >>> import sympy as sp, lagrange as lg
    >>> th = lg.coordinates("theta"); m, l, g = lg.parameters("m l g")
    >>> bob = lg.Particle(m, (l*sp.sin(th), -l*sp.cos(th)))
    >>> s = lg.System([th], bodies=[bob], V=m*g*bob.position[1])
    >>> check_gauss(s, {"m": 1, "l": 2, "g": 9.81}, diagnostics=False).agrees
    True
    """
    name = getattr(system, "name", "") or ""
    if system is None:
        return GaussCheck(name, False, "no dynamics (no system)")
    rng = np.random.default_rng(seed)
    params, filled = _complete(system, params, rng)
    try:
        pm = mass_point_model(system, params)
    except NotApplicable as exc:
        return GaussCheck(name, False, str(exc))
    wanted = {s.name for s in system.derived.parameters}
    lparams = {k: v for k, v in params.items() if k in wanted}
    model = system.compile(lparams)
    names = [coordinate_name(q) for q in system.coordinates]
    ranges = {key_name(k, system.coordinates): v for k, v in (ranges or {}).items()}  # velocities too
    first = None
    if initial is not None:
        from ..integrate.run import initial_state

        y0 = initial_state(system.coordinates, initial)
        first = (0.0, y0[:pm.n], y0[pm.n:])
    out, states, skipped, last = [], [], 0, ""
    while len(out) < samples and skipped < 20 * samples:
        t, q, qd = first if first is not None and not out and not skipped else _draw(rng, names, ranges)
        try:
            q, qd = _consistent(pm, t, q, qd)
            out.append(_compare(pm, model, t, q, qd))
            states.append((t, q, qd))
        except (SingularMassMatrixError, ZeroDivisionError, FloatingPointError, np.linalg.LinAlgError) as exc:
            skipped += 1
            last = str(exc).split(":")[0]
    if not out:
        return GaussCheck(name, False, f"singular at every sampled state: {last}", skipped_states=skipped)
    diag = None
    if diagnostics:
        t0, q0, qd0 = states[0]
        init = initial if initial is not None else {**dict(zip(names, q0)),
                                                   **{nm + "_dot": v for nm, v in zip(names, qd0)}}
        diag = _run_diagnostics(system, pm, lparams, init, t_run, states)
    return GaussCheck(name, True, "", tuple(out), max(s.max_error for s in out), rtol, diag, balance_tol,
                      len(pm.masses), skipped, filled, pm.signed_bodies)


def sample_parameters(system, ranges: Mapping | None = None, seed: int = 0) -> dict[str, float]:
    """Random parameter values for a system that comes without numbers: each from ``ranges[name]`` or
    the corpus' default range [1.1, 2.3] (:data:`lagrange.corpus.compare.PARAMETER_RANGE`)."""
    from ..corpus.compare import PARAMETER_RANGE

    rng = np.random.default_rng(seed)
    ranges = {str(getattr(k, "name", k)): v for k, v in (ranges or {}).items()}
    return {s.name: float(rng.uniform(*ranges.get(s.name, PARAMETER_RANGE))) for s in system.parameters}


def check_problem(problem, *, samples: int = 5, seed: int = 0, params: Mapping | None = None,
                  **options) -> GaussCheck:
    """:func:`check_gauss` of a corpus problem with its default simulation numbers (parameters and
    initial state) when it has them, else random parameters in its sampling ranges; ``params``
    overrides single values."""
    system = problem.system
    if system is None:
        return GaussCheck(problem.id, False, "no dynamics (no system)")
    sim = problem.simulation
    initial = dict(sim.initial) if sim is not None and sim.initial else None
    # stay within the problem's own run (dry friction may stop the motion after it); a random state of a
    # problem without numbers may be near a singular configuration: run briefly
    options.setdefault("t_run", min(1.0, float(sim.t_end)) if sim is not None else 0.2)
    # random parameters can be unphysical (independently drawn moments and products of inertia give an
    # indefinite mass matrix, which the engine rejects too): redraw a few times
    for k in range(1 if sim is not None else 8):
        base = dict(sim.params) if sim is not None else sample_parameters(system, problem.ranges, seed + k)
        base.update(params or {})
        res = check_gauss(system, base, samples=samples, seed=seed, ranges=problem.ranges, initial=initial,
                          **options)
        if res.applicable or not res.reason.startswith("singular"):
            break
    return _renamed(res, f"{problem.id} ({res.name})" if res.name else problem.id)


def _renamed(res: GaussCheck, name: str) -> GaussCheck:
    import dataclasses

    return dataclasses.replace(res, name=name)


def check_spec(spec, *, samples: int = 5, seed: int = 0, params: Mapping | None = None) -> GaussCheck:
    """The check behind ``lagrange check SPEC``: ``spec`` is a :class:`~lagrange.spec.loader.LoadedSpec`
    (problem id, ``.py`` or ``.toml``). Corpus problems use :func:`check_problem`; other specs their own
    parameters and initial state, with ``params`` overriding single values.

    Raises
    ------
    SpecError
        The spec has no equations of motion.
    """
    from ..corpus.problem import Problem
    from ..errors import SpecError

    if spec.system is None:
        raise SpecError(f"{spec.label}: this problem has no equations of motion to check")
    if isinstance(spec.problem, Problem):
        return check_problem(spec.problem, samples=samples, seed=seed, params=params)
    res = check_gauss(spec.system, {**spec.params, **dict(params or {})}, samples=samples, seed=seed,
                      initial=spec.initial or None)
    return res if res.name else _renamed(res, spec.label)
