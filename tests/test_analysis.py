"""Analysis tools: small oscillations, steady motion, driving forces, statics, Hamilton, variational."""

import numpy as np
import pytest
import sympy as sp

from lagrange import (
    EulerAngles,
    LagrangeError,
    Particle,
    RigidBody,
    System,
    action,
    characteristic_roots,
    coordinates,
    driving_forces,
    equilibria,
    euler_lagrange,
    hamiltonian,
    linearize,
    normal_modes,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    static_equilibrium,
    steady_motion_conditions,
    t,
    variational_integrate,
)
from lagrange.examples import n_link_pendulum
from lagrange.simplification import is_zero


def two_masses():
    x1, x2 = coordinates("x1 x2")
    m1, m2, k1, k2 = parameters("m1 m2 k1 k2")
    T = m1 * x1.diff(t) ** 2 / 2 + m2 * x2.diff(t) ** 2 / 2
    s = System([x1, x2], T=T, V=k1 * x1**2 / 2 + k2 * (x2 - x1) ** 2 / 2)
    return s, (x1, x2)


def test_wells_sec_1_9_frequencies_and_mode_ratios():
    s, _ = two_masses()
    lin = linearize(s)
    vals = dict(zip(parameters("m1 m2 k1 k2"), (400, 300, 60000, 50000)))
    w2 = sorted(float(v.subs(vals)) for v in lin.squared_frequencies())
    assert w2 == pytest.approx([200 / 3, 375])
    modes = normal_modes(lin, {"m1": 400, "m2": 300, "k1": 6e4, "k2": 5e4})
    assert modes.omega**2 == pytest.approx([200 / 3, 375])
    assert modes.ratios(1)[0] == pytest.approx([0.6, -1.25])  # x1/x2 per mode (Wells: 0.6 and −1.25)
    # orthogonality (10.20) and diagonalization (10.24)
    assert np.allclose(modes.shapes.T @ modes.a @ modes.shapes, np.eye(2))
    assert np.allclose(modes.shapes.T @ modes.c @ modes.shapes, np.diag(modes.omega**2))


def test_linearized_motion_matches_nonlinear_at_small_amplitude():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    lin = linearize(s)
    modes = normal_modes(lin, {"g": 9.81})
    eps = 1e-3
    s0, v0 = np.array([eps, -0.5 * eps]), np.zeros(2)
    sol = s.simulate(10, {q1: s0[0], q2: s0[1], q1.diff(t): 0, q2.diff(t): 0}, {"g": 9.81}, n_points=201)
    linear = modes.motion(s0, v0, sol.t)
    err = np.max(np.abs(sol.y[:, :2] - linear))
    assert err < 5e-3 * eps  # nonlinear corrections are O(ε³)
    bigger = s.simulate(10, {q1: 0.3, q2: -0.15, q1.diff(t): 0, q2.diff(t): 0}, {"g": 9.81}, n_points=201)
    assert np.max(np.abs(bigger.y[:, :2] - modes.motion([0.3, -0.15], v0, bigger.t))) > 100 * err / eps * 0.3 * 1e-3


def test_zero_and_repeated_roots():
    s, (x1, x2) = two_masses()
    free = System(s.coordinates, T=s.T, V=s.V.subs(parameters("k1"), 0))  # no anchor: a rigid translation mode
    modes = normal_modes(linearize(free), {"m1": 1, "m2": 3, "k2": 2})
    assert modes.omega[0] == 0 and modes.omega[1] == pytest.approx(np.sqrt(2 * (1 + 1 / 3)))
    traj = modes.motion([0.1, 0.1], [1.0, 1.0], np.array([0.0, 2.0]))
    assert traj[1] == pytest.approx([2.1, 2.1])  # drift v t + b in the zero mode
    x, y = coordinates("x y")
    m, k = parameters("m k")
    iso = System([x, y], T=m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=k * (x**2 + y**2) / 2)
    modes = normal_modes(linearize(iso), {"m": 2, "k": 8})
    assert modes.omega == pytest.approx([2, 2])  # degenerate: eigen-solver, not cofactors


def test_equilibria_and_unstable_point():
    th = coordinates("theta")
    m, g, l = parameters("m g l")
    p = System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th))
    sols = equilibria(p)
    assert {s[th] for s in sols} == {0, sp.pi}
    assert equilibria(p, {"m": 1, "g": 9.81, "l": 1}, {th: 3.0})[th] == pytest.approx(np.pi)
    with pytest.raises(LagrangeError, match="unstable"):
        normal_modes(linearize(p, {th: sp.pi}), {"m": 1, "g": 9.81, "l": 1})


def test_damped_roots_and_stability():
    x = coordinates("x")
    m, k, b = parameters("m k b")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-b * x.diff(t) ** 2 / 2)
    lam = characteristic_roots(linearize(s), {"m": 1, "k": 4, "b": 0.4})
    wd = np.sqrt(4 - 0.04)
    assert lam == pytest.approx(np.sort_complex(np.array([-0.2 - 1j * wd, -0.2 + 1j * wd])))
    lin = linearize(s)
    lam_s = sp.Symbol("lambda")
    assert sp.expand(lin.characteristic_polynomial(lam_s) - (m * lam_s**2 + b * lam_s + k)) == 0


def test_hamiltonian_rotating_frame_and_energy_rate():
    """H = T2 − T0 + V differs from T + V in a rotating frame; dH/dt obeys Wells (16.11)."""
    x, y = coordinates("x y")
    m, w, k, b = parameters("m omega k b")
    c, s_ = sp.cos(w * t), sp.sin(w * t)
    sys_ = System([x, y], bodies=[Particle(m, (x * c - y * s_, x * s_ + y * c))], V=k * (x**2 + y**2) / 2,
                  P=-b * x.diff(t) ** 2 / 2)
    h = hamiltonian(sys_)
    X, Y = h.q
    px, py = h.p
    expected = ((px + m * w * Y) ** 2 + (py - m * w * X) ** 2) / (2 * m) - m * w**2 * (X**2 + Y**2) / 2 \
        + k * (X**2 + Y**2) / 2
    assert is_zero(h.H - expected)
    assert is_zero(h.energy_rate() - h.expected_energy_rate())


def test_canonical_equations_reproduce_lagrange_trajectory():
    r, th = coordinates("r theta")
    m, k = parameters("m k")
    s = System([r, th], bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)))], V=k * r**2 / 2 - 1 / r)
    h = hamiltonian(s)
    pars = {"m": 1.5, "k": 2.0}
    subs = {sym: pars[sym.name] for sym in s.parameters}
    f = sp.lambdify([list(h.q) + list(h.p)], [e.subs(subs) for e in list(h.qdot) + list(h.pdot)], "numpy")
    from scipy.integrate import solve_ivp

    ic = {r: 1.0, th: 0.0, r.diff(t): 0.1, th.diff(t): 0.8}
    lag = s.simulate(5, ic, pars, rtol=1e-11, atol=1e-12, t_eval=[5.0])
    p0 = [1.5 * 0.1, 1.5 * 1.0 * 0.8]
    ham = solve_ivp(lambda _, z: np.asarray(f(z), dtype=float), (0, 5), [1.0, 0.0, *p0], rtol=1e-11, atol=1e-12)
    assert ham.y[:2, -1] == pytest.approx(lag.y[-1, :2], rel=1e-8)


def test_top_steady_precession_two_rates_and_stability():
    """Wells Ex. 11.2: for a given tilt and spin momentum there are two steady precession rates."""
    psi, th, ph = coordinates("psi theta phi")
    M, g, l, I1, I3 = parameters("M g l I1 I3")
    top = RigidBody(M, (I1, I1, I3), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
    s = System([psi, th, ph], bodies=[top], V=M * g * top.centre_of_mass[2])
    R = routhian(s)
    assert set(R.ignorable) == {psi, ph}
    # steady precession at θ0 with spin rate n = ψ̇ cosθ + φ̇: M g l = ψ̇ (I3 n − I1 ψ̇ cosθ0) (two roots)
    vals = {M: 1.0, g: 9.81, l: 0.2, I1: 0.05, I3: 0.02}
    th0, n = 0.5, 40.0
    wpsi = sp.Symbol("wpsi")
    roots = sp.solve(wpsi * (0.02 * n - 0.05 * wpsi * np.cos(th0)) - 1.962, wpsi)
    assert len(roots) == 2
    for w in roots:
        w = float(w)
        fd = n - w * np.cos(th0)
        sol = s.simulate(1.0, {psi: 0, th: th0, ph: 0, psi.diff(t): w, th.diff(t): 0, ph.diff(t): fd}, vals,
                         rtol=1e-11, atol=1e-12)
        assert np.ptp(sol[th]) < 1e-7  # steady: θ stays put
    cond = steady_motion_conditions(R)[0]
    momenta = {p.name: p for p in R.momenta}
    p_phi, p_psi = momenta["p_phi"], momenta["p_psi"]
    w = float(roots[0])
    pphi = 0.02 * n
    ppsi = 0.05 * w * np.sin(th0) ** 2 + pphi * np.cos(th0)
    assert float(cond.subs({**vals, p_phi: pphi, p_psi: ppsi, th: th0})) == pytest.approx(0, abs=1e-9)


def test_oscillation_about_circular_orbit():
    """Small radial oscillation about a circular Kepler orbit has the orbital frequency (closed orbits)."""
    r, th = coordinates("r theta")
    m, k = parameters("m k")
    s = System([r, th], bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)))], V=-k / r)
    R = routhian(s)
    (p,) = R.momenta
    r0 = sp.Symbol("r0", positive=True)
    lin = oscillations_about_steady_motion(R, {r: r0})
    c = lin.c[0, 0].subs(p, sp.sqrt(k * m * r0))  # circular orbit: p² = k m r0
    w2 = sp.simplify(c / lin.a[0, 0])
    assert is_zero(w2 - k / (m * r0**3))  # = (orbital angular speed)²


def test_driving_force_and_statics():
    x = coordinates("x")
    m, k, A, w = parameters("m k A omega")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    F = driving_forces(s, {x: A * sp.sin(w * t)})[x]
    assert is_zero(F - A * (k - m * w**2) * sp.sin(w * t))
    th = coordinates("theta")
    g, l, P = parameters("g l P")
    pend = System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th),
                  forces={th: P * l * sp.cos(th)})  # horizontal pull P
    sol = static_equilibrium(pend, [th], {"m": 1, "g": 9.81, "l": 1, "P": 2.0}, {th: 0.1})
    assert np.tan(sol[th]) == pytest.approx(2.0 / 9.81)


def test_euler_lagrange_of_functionals():
    x = sp.Symbol("x")
    y = sp.Function("y")(x)
    (geo,) = euler_lagrange(sp.sqrt(1 + y.diff(x) ** 2), [y], x)
    assert is_zero(geo.lhs * (1 + y.diff(x) ** 2) ** sp.Rational(3, 2) + y.diff(x, 2))  # straight line
    (beam,) = euler_lagrange(y.diff(x, 2) ** 2 / 2, [y], x)
    assert is_zero(beam.lhs - y.diff(x, 4))  # Euler–Poisson, fourth order


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_variational_integrator_order_momentum_and_energy():
    r, th = coordinates("r theta")
    m, k = parameters("m k")
    s = System([r, th], bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)))], V=-k / r)
    ic = {r: 1, th: 0, r.diff(t): 0, th.diff(t): 1.2}
    ref = s.simulate(5, ic, {m: 1, k: 1}, rtol=1e-12, atol=1e-13, t_eval=[5.0]).y[-1, :2]
    errs = []
    for h in (0.02, 0.01, 0.005):
        res = variational_integrate(s, 5, ic, {m: 1, k: 1}, h=h)
        errs.append(np.max(np.abs(res.q[-1] - ref)))
        assert np.ptp(res.p[:, 1]) < 1e-10  # p_θ conserved exactly (ignorable coordinate)
    order = np.polyfit(np.log([0.02, 0.01, 0.005]), np.log(errs), 1)[0]
    assert order == pytest.approx(2.0, abs=0.2)
    long = variational_integrate(s, 400, ic, {m: 1, k: 1}, h=0.02)
    E = long.p[:, 0] ** 2 / 2 + long.p[:, 1] ** 2 / (2 * long.q[:, 0] ** 2) - 1 / long.q[:, 0]
    first, last = np.ptp(E[: len(E) // 10]), np.ptp(E[-len(E) // 10 :])
    assert last < 1.5 * first  # bounded, no secular drift


def test_action_of_a_trajectory():
    x = coordinates("x")
    m, g = parameters("m g")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=m * g * x)
    sol = s.simulate(2, {x: 0, x.diff(t): 3}, {"m": 1, "g": 10}, n_points=2001)
    # closed form: S = ∫ (½ v² − g x) dt with v = 3 − 10t, x = 3t − 5t²
    tt = sp.Symbol("tt")
    exact = sp.integrate((3 - 10 * tt) ** 2 / 2 - 10 * (3 * tt - 5 * tt**2), (tt, 0, 2))
    assert action(sol) == pytest.approx(float(exact), rel=1e-8)
