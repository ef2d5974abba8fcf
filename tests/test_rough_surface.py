"""Coulomb friction over a surface in any direction (Wells 12.5, rough constraints; ``Rough`` with sliding
components): friction −μN v/|v| with N from the constraint multiplier."""

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from lagrange import (
    DeclarationError,
    Force,
    Frame,
    Particle,
    Rough,
    System,
    coordinates,
    inputs,
    parameters,
    rot_z,
    t,
)

M_, G_, MU_ = 2.0, 9.81, 0.3


def _plane():
    x, y, z = coordinates("x y z")
    m, g, mu = parameters("m g mu")
    s = System([x, y, z], bodies=[Particle(m, (x, y, z))], V=m * g * z,
               constraints=[Rough(z, mu, (x.diff(t), y.diff(t)), "floor")])
    return s, (x, y, z), {m: M_, g: G_, mu: MU_}


def _plane_start(coords, v0, a):
    x, y, z = coords
    return {x: 0, y: 0, z: 0, x.diff(t): v0 * np.cos(a), y.diff(t): v0 * np.sin(a), z.diff(t): 0}


def test_plane_straight_line_deceleration_mu_g_and_stop():
    """Closed form: the particle decelerates at μg along its initial direction and stops at t = v0/(μg)."""
    s, coords, P = _plane()
    v0, a = 3.0, 0.7
    ts = v0 / (MU_ * G_)
    tr = s.simulate(2 * ts, _plane_start(coords, v0, a), P, n_points=101)
    assert "Sliding stopped on the rough constraint floor at t=" in tr.message
    assert abs(float(tr.message.split("t=")[1].split(";")[0]) - ts) < 1e-7
    d = v0 * tr.t - 0.5 * MU_ * G_ * tr.t**2
    assert np.max(np.abs(tr.y[:, 0] - d * np.cos(a))) < 1e-9
    assert np.max(np.abs(tr.y[:, 1] - d * np.sin(a))) < 1e-9
    assert np.allclose(tr.multiplier("floor"), M_ * G_, rtol=1e-12)   # N = mg


def test_plane_regularized_runs_through_the_stop():
    """friction='regularize' (|v| → sqrt(|v|² + ε²)): the same path, and it comes to rest at the stop point."""
    s, coords, P = _plane()
    v0, a = 3.0, -2.0
    ts = v0 / (MU_ * G_)
    tr = s.simulate(2 * ts, _plane_start(coords, v0, a), P, n_points=101, friction="regularize",
                    friction_epsilon=1e-6, method="LSODA", rtol=1e-10, atol=1e-12)
    assert tr.t[-1] == pytest.approx(2 * ts)
    d = v0 * ts - 0.5 * MU_ * G_ * ts**2
    assert np.hypot(tr.y[-1, 0] - d * np.cos(a), tr.y[-1, 1] - d * np.sin(a)) < 1e-5
    assert np.hypot(tr.y[-1, 3], tr.y[-1, 4]) < 1e-5


def test_plane_at_rest_ends_with_a_message():
    s, coords, P = _plane()
    tr = s.simulate(1.0, _plane_start(coords, 0.0, 0.0), P)
    assert "at rest at t=0 on a rough surface" in tr.message and len(tr.t) == 1


def _sphere():
    r, th, ph = coordinates("r theta phi")
    m, g, mu, a = parameters("m g mu a")
    pos = (r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th))
    s = System([r, th, ph], bodies=[Particle(m, pos)], V=m * g * r * sp.cos(th),
               constraints=[Rough(r - a, mu, (r * th.diff(t), r * sp.sin(th) * ph.diff(t)), "sphere")])
    return s, (r, th, ph), {m: M_, g: G_, mu: 0.2, a: 1.0}


def _newton_sphere(y0_cart, t_eval, mu, a=1.0):
    """m r̈ = −mg ẑ + N n − μN v/|v| with N = m(g n_z − |v|²/a) (outside of the sphere), Cartesian."""
    def f(_, s):
        X, V = s[:3], s[3:]
        n = X / np.linalg.norm(X)
        N = G_ * n[2] - V @ V / a  # per unit mass
        return np.concatenate([V, -G_ * np.array([0, 0, 1.0]) + N * n - mu * N * V / np.linalg.norm(V)])
    return solve_ivp(f, (t_eval[0], t_eval[-1]), y0_cart, t_eval=t_eval, rtol=1e-12, atol=1e-13, method="DOP853")


def test_rough_sphere_matches_a_newton_formulation_and_dissipates_mu_n_speed():
    s, (r, th, ph), P = _sphere()
    th0, ph0, thd0, phd0 = 0.3, 0.2, 0.5, 2.0
    T_END = 0.4
    te = np.linspace(0, T_END, 81)
    tr = s.simulate(T_END, {r: 1.0, th: th0, ph: ph0, r.diff(t): 0, th.diff(t): thd0, ph.diff(t): phd0}, P,
                    t_eval=te, rtol=1e-11, atol=1e-12)
    assert tr.t[-1] == pytest.approx(T_END)
    R, TH, PH = tr.y[:, 0], tr.y[:, 1], tr.y[:, 2]
    cart = np.stack([R * np.sin(TH) * np.cos(PH), R * np.sin(TH) * np.sin(PH), R * np.cos(TH)], axis=1)
    # independent Newton formulation from the same initial state
    st, ct, sp_, cp = np.sin(th0), np.cos(th0), np.sin(ph0), np.cos(ph0)
    e_th, e_ph = np.array([ct * cp, ct * sp_, -st]), np.array([-sp_, cp, 0.0])
    v0 = thd0 * e_th + st * phd0 * e_ph
    ref = _newton_sphere(np.concatenate([cart[0], v0]), te, 0.2)
    assert np.max(np.abs(cart - ref.y[:3].T)) < 1e-8
    # the normal force is the multiplier: N = m(g cosθ − |v|²/a) from the reference
    N_ref = M_ * (G_ * ref.y[2] - np.sum(ref.y[3:] ** 2, axis=0))
    assert np.max(np.abs(tr.multiplier("sphere") - N_ref)) < 1e-6
    # energy: dE/dt = −μ N |v|  (integrated over the run with the trapezoid rule on a fine grid)
    speed = np.hypot(tr.y[:, 4], np.sin(TH) * tr.y[:, 5])  # a = 1, r = 1
    E = 0.5 * M_ * speed**2 + M_ * G_ * R * np.cos(TH)
    power = -0.2 * tr.multiplier("sphere") * speed
    lost = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(tr.t))])
    assert np.max(np.abs(E - E[0] - lost)) < 2e-4 * abs(lost[-1])
    assert lost[-1] < -0.1  # it really dissipated


def test_sliding_components_must_be_linear_in_the_velocities():
    x, y, z = coordinates("x y z")
    m, mu = parameters("m mu")
    with pytest.raises(DeclarationError, match="sliding component .* must be linear in the velocities"):
        System([x, y, z], bodies=[Particle(m, (x, y, z))],
               constraints=[Rough(z, mu, (x.diff(t) ** 2, y.diff(t)), "floor")])
    with pytest.raises(DeclarationError, match="2 \\(or 3\\) components"):
        System([x, y, z], bodies=[Particle(m, (x, y, z))],
               constraints=[Rough(z, mu, (x.diff(t),), "floor")])


def test_rough_turntable_moving_frame_with_an_input_force():
    """A puck on a rough turntable turning at ω (coordinates in the table's frame, sliding velocity relative to
    the table) pushed by an input force u(t) along the table's X axis, against a Newton formulation in the
    rotating frame: Ẍ = 2ωẎ + ω²X + u/m − μg v_X/|v|, Ÿ = −2ωẊ + ω²Y − μg v_Y/|v|."""
    X, Y, Z = coordinates("X Y Z")
    m, g, mu = parameters("m g mu")
    u = inputs("u")
    w = 1.3
    frame = Frame(rotation=rot_z(w * t))
    puck = Particle(m, frame.point((X, Y, Z)))
    s = System([X, Y, Z], bodies=[puck], V=m * g * Z, forces=[Force(puck, frame.direction((u, 0, 0)))],
               constraints=[Rough(Z, mu, (X.diff(t), Y.diff(t)), "table")])
    push = lambda tt: 0.5 * np.cos(3 * tt)  # noqa: E731
    P = {m: M_, g: G_, mu: 0.1}
    start = {X: 0.4, Y: -0.2, Z: 0, X.diff(t): 0.3, Y.diff(t): 1.1, Z.diff(t): 0}
    te = np.linspace(0, 0.8, 41)
    tr = s.simulate(0.8, start, P, inputs={u: push}, t_eval=te, rtol=1e-11, atol=1e-12)
    assert tr.t[-1] == pytest.approx(0.8)

    def f(tt, y):
        x_, y_, vx, vy = y
        sp_ = np.hypot(vx, vy)
        return [vx, vy, 2 * w * vy + w**2 * x_ + push(tt) / M_ - 0.1 * G_ * vx / sp_,
                -2 * w * vx + w**2 * y_ - 0.1 * G_ * vy / sp_]
    ref = solve_ivp(f, (0, 0.8), [0.4, -0.2, 0.3, 1.1], t_eval=te, rtol=1e-12, atol=1e-13, method="DOP853")
    assert np.max(np.abs(tr.y[:, :2] - ref.y[:2].T)) < 1e-8
