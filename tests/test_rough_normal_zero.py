"""Rough (Coulomb-friction) constraints when the normal force passes through zero (#24 item 2, #21: no hangs).

The constraints are bilateral: the friction μ|N| passes through zero continuously and the run steps through the
crossing. Truth: hand-written Newton formulations with |N| in the friction, integrated by scipy at tight tolerance
(split at N = 0), and the energy balance dE/dt = −μ|N||v|."""

import re

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import lagrange.integrate.rough as rough
from lagrange import IntegrationError, Particle, Rough, System, coordinates, parameters, t

G_ = 9.81


def _tight(f, span, y0, t_eval, n_event):
    """DOP853 at rtol 1e-12, restarted at every zero of n_event (where |N| has a kink); the state at t_eval."""
    def ev(tt, y):
        return n_event(y)

    ev.terminal = True
    pieces, t0, y = [], span[0], np.asarray(y0, float)
    ev.direction = -np.sign(n_event(y))  # the next crossing only (the restart point is a root)
    while len(pieces) < 10:
        r = solve_ivp(f, (t0, span[1]), y, events=ev, rtol=1e-12, atol=1e-13, method="DOP853", dense_output=True)
        pieces.append((t0, r.t[-1], r.sol))
        if r.status != 1:
            break
        t0, y = r.t_events[0][0], r.y_events[0][0]
        ev.direction = -ev.direction
    out = [next(sol for a, b, sol in pieces if a <= tt <= b)(tt) for tt in t_eval]
    return np.asarray(t_eval), np.array(out)


def _hoop():
    """A bead on a rough vertical hoop of radius 1 in Cartesian coordinates (φ = √(x²+y²) − 1, sliding x ẏ − y ẋ)."""
    x, y = coordinates("x y")
    m, g, mu = parameters("m g mu")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Rough(sp.sqrt(x**2 + y**2) - 1, mu, x * y.diff(t) - y * x.diff(t), "wire")])
    return s, (x, y), {m: 1.0, g: G_, mu: 0.2}


def test_bead_on_a_rough_hoop_steps_through_the_zeros_of_the_normal_force():
    """Newton in the angle θ from the bottom (unit mass, radius 1): λ = −(θ̇² + g cosθ) (outward),
    θ̈ = −g sinθ − μ|λ| sign(θ̇). Up the hoop (until it stops at about t = 0.57), λ changes sign."""
    s, (x, y), P = _hoop()
    mu, w0, T_END = 0.2, 6.5, 0.55
    te = np.linspace(0, T_END, 56)
    tr = s.simulate(T_END, {x: 0.0, y: -1.0, x.diff(t): w0, y.diff(t): 0.0}, P, t_eval=te, rtol=1e-11, atol=1e-12)
    assert tr.t[-1] == pytest.approx(T_END) and "successfully" in tr.message

    def f(_, u):
        TH, W = u
        return [W, -G_ * np.sin(TH) - mu * abs(W**2 + G_ * np.cos(TH)) * np.sign(W)]

    _, ry = _tight(f, (0, T_END), [0.0, w0], te, lambda u: u[1] ** 2 + G_ * np.cos(u[0]))
    assert np.max(np.abs(tr[x] - np.sin(ry[:, 0]))) < 1e-8
    assert np.max(np.abs(tr[y] + np.cos(ry[:, 0]))) < 1e-8
    lam = tr.multiplier("wire")
    assert np.max(np.abs(lam + ry[:, 1] ** 2 + G_ * np.cos(ry[:, 0]))) < 1e-6
    assert np.count_nonzero(np.diff(np.sign(lam))) >= 1  # it really crossed N = 0
    v = tr[x] * tr[y.diff(t)] - tr[y] * tr[x.diff(t)]
    E = 0.5 * v**2 + G_ * tr[y]
    loss = mu * np.abs(lam) * np.abs(v)
    lost = np.concatenate([[0.0], np.cumsum(0.5 * (loss[1:] + loss[:-1]) * np.diff(tr.t))])
    assert np.max(np.abs(E[0] - E - lost)) < 2e-3 * lost[-1]
    assert lost[-1] > 1.0


def _sphere():
    r, th, ph = coordinates("r theta phi")
    m, g, mu, a = parameters("m g mu a")
    pos = (r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th))
    s = System([r, th, ph], bodies=[Particle(m, pos)], V=m * g * r * sp.cos(th),
               constraints=[Rough(r - a, mu, (r * th.diff(t), r * sp.sin(th) * ph.diff(t)), "sphere")])
    return s, (r, th, ph), {m: 2.0, g: G_, mu: 0.2, a: 1.0}


_SPHERE_START = (0.3, 0.2, 0.5, 1.0)  # θ, φ, θ̇, φ̇: hung before the fix (restarts at the N = 0 instant)


def test_particle_over_a_rough_sphere_steps_through_n_zero_against_newton():
    """Friction over a surface: m r̈ = −mg ẑ + N n − μ|N| v/|v|, N = m(g n_z − |v|²/a), Cartesian (bilateral:
    the particle is held on the sphere after N < 0)."""
    s, (r, th, ph), P = _sphere()
    th0, ph0, thd0, phd0 = _SPHERE_START
    T_END, mu = 0.6, 0.2
    te = np.linspace(0, T_END, 61)
    tr = s.simulate(T_END, {r: 1.0, th: th0, ph: ph0, r.diff(t): 0, th.diff(t): thd0, ph.diff(t): phd0}, P,
                    t_eval=te, rtol=1e-11, atol=1e-12)
    assert tr.t[-1] == pytest.approx(T_END) and "successfully" in tr.message
    TH, PH = tr[th], tr[ph]
    cart = np.stack([np.sin(TH) * np.cos(PH), np.sin(TH) * np.sin(PH), np.cos(TH)], axis=1)
    st, ct, sp_, cp = np.sin(th0), np.cos(th0), np.sin(ph0), np.cos(ph0)
    v0 = thd0 * np.array([ct * cp, ct * sp_, -st]) + st * phd0 * np.array([-sp_, cp, 0.0])

    def f(_, u):
        X, V = u[:3], u[3:]
        n = X / np.linalg.norm(X)
        N = G_ * n[2] - V @ V
        return np.concatenate([V, -G_ * np.array([0, 0, 1.0]) + N * n - mu * abs(N) * V / np.linalg.norm(V)])

    rt, ry = _tight(f, (0, T_END), np.concatenate([cart[0], v0]), te,
                    lambda u: G_ * u[2] / np.linalg.norm(u[:3]) - u[3:] @ u[3:])
    assert np.max(np.abs(cart - ry[:, :3])) < 1e-8
    N = tr.multiplier("sphere")
    N_ref = 2.0 * (G_ * ry[:, 2] - np.sum(ry[:, 3:] ** 2, axis=1))
    assert np.max(np.abs(N - N_ref)) < 1e-6
    assert N[0] > 5 and N[-1] < -5  # through zero
    speed = np.hypot(tr[th.diff(t)], np.sin(TH) * tr[ph.diff(t)])
    E = 0.5 * 2.0 * speed**2 + 2.0 * G_ * np.cos(TH)
    loss = mu * np.abs(N) * speed
    lost = np.concatenate([[0.0], np.cumsum(0.5 * (loss[1:] + loss[:-1]) * np.diff(tr.t))])
    assert np.max(np.abs(E[0] - E - lost)) < 2e-3 * lost[-1]


def test_restart_cap_ends_a_chatter_with_a_clear_error(monkeypatch):
    """A chatter made deterministic: every segment's normal-force event fires at once (its function changes sign
    right after the segment's first instant, as a λ that flips with rounding noise would), so each segment ends
    where it started; the cap turns that former hang into an IntegrationError naming the constraint and the
    time. (Switching the crossing guard off no longer chatters reliably: whether rounding flips λ depends on
    the numerical libraries.)"""
    bind = rough._bind

    def chattering(fn, direction=0, **kw):
        if "k" not in kw:  # the sliding events are left as they are
            return bind(fn, direction=direction, **kw)
        start: list[float] = []

        def ev(t_, z):
            start.append(t_) if not start else None
            return 1.0 if t_ == start[0] else -1.0

        ev.terminal, ev.direction = True, 0
        return ev

    monkeypatch.setattr(rough, "_bind", chattering)
    s, (r, th, ph), P = _sphere()
    th0, ph0, thd0, phd0 = _SPHERE_START
    with pytest.raises(IntegrationError, match=r"rough constraint sphere: the normal force changed sign (\d+) "
                                               r"times at t=(\S+) without the integration advancing") as err:
        s.simulate(0.6, {r: 1.0, th: th0, ph: ph0, r.diff(t): 0, th.diff(t): thd0, ph.diff(t): phd0}, P)
    count, when = re.search(r"changed sign (\d+) times at t=(\S+) ", str(err.value)).groups()
    assert int(count) == rough._MAX_RESTARTS_AT_ONE_INSTANT + 1 and float(when) < 1e-9  # at the first instant
