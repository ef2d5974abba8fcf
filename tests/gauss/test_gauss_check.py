"""The Lagrange-vs-Gauss check of Systems (T-A, T-C): worked cases E22, E23, E25, rigid bodies,
constraints, and that a wrong model is caught."""

import types

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.gauss.appell import appell_identity
from lagrange.gauss.check import check_gauss, gauss_solve
from lagrange.gauss.masspoints import mass_point_model


def _double_pendulum(l1=None):
    th1, th2 = lg.coordinates("theta1 theta2")
    m1, m2, l1s, l2, g = lg.parameters("m1 m2 l1 l2 g")
    l1 = l1s if l1 is None else l1
    p1 = lg.Particle(m1, (l1 * sp.sin(th1), -l1 * sp.cos(th1)))
    p2 = lg.Particle(m2, (l1 * sp.sin(th1) + l2 * sp.sin(th2), -l1 * sp.cos(th1) - l2 * sp.cos(th2)))
    return lg.System([th1, th2], bodies=[p1, p2], V=g * (m1 * p1.position[1] + m2 * p2.position[1]),
                     name="double pendulum")


E22 = {"m1": 1.3, "m2": 0.7, "l1": 1.1, "l2": 0.8, "g": 9.81}


def test_e22_double_pendulum_both_routes():
    s = _double_pendulum()
    G = gauss_solve(mass_point_model(s, E22), 0.0, [0.7, -0.4], [1.2, -0.5])
    expected = [-6.96515996, -3.79565784, 0, 1.17885302, -7.02175041, 0]
    assert np.allclose(G["xdd"], expected, atol=5e-9)
    qdd_L = s.compile(E22).fun(0.0, np.array([0.7, -0.4, 1.2, -0.5]))[2:]
    assert np.allclose(G["J"] @ qdd_L + G["a0"], expected, atol=5e-9)
    res = lg.check_gauss(s, E22, samples=4, seed=1)
    assert res.applicable and res.agrees and res.ok and res.max_rel_error < 1e-12
    assert res.diagnostics.power_residual < 1e-9
    assert "verdict: AGREE" in str(res)


def test_e23_appell_identity_double_pendulum():
    r = appell_identity(_double_pendulum())
    assert r.status == "verified" and set(r.per_coordinate.values()) == {"verified"}


def test_appell_identity_catches_a_wrong_lagrange_operator():
    right = _double_pendulum()
    wrong = _double_pendulum(l1=sp.Symbol("l1", positive=True) * sp.Rational(11, 10))
    fake = types.SimpleNamespace(T_given=0, bodies=right.bodies, coordinates=right.coordinates,
                                 prescribed={}, derived=wrong.derived)
    r = appell_identity(fake)
    assert r.status == "failed" and "difference" in r.detail


def test_e25_moving_support_through_a_prescribed_coordinate():
    th, xs = lg.coordinates("theta x_s")
    m, l, g = lg.parameters("m l g")
    bob = lg.Particle(m, (xs + l * sp.sin(th), -l * sp.cos(th)))
    s = lg.System([th], bodies=[bob], V=m * g * bob.position[1], prescribed={xs: sp.Rational(1, 10) * sp.cos(5 * t)})
    params = {"m": 1, "l": 1, "g": 9.81}
    G = gauss_solve(mass_point_model(s, params), 0.3, [0.4], [-0.8])
    assert np.allclose(G["xdd"][:2], [-3.79467701, -0.83474485], atol=5e-9)
    assert G["qdd"][0] == pytest.approx(-3.65731074, abs=5e-9)
    res = check_gauss(s, params, samples=3)
    assert res.ok, str(res)  # the power balance includes the driver's power Σ m ẋ_t·ẍ


def test_rigid_body_euler_angles_torque_free():
    psi, theta, phi = lg.coordinates("psi theta phi")
    M, A, C = lg.parameters("M A C")
    body = lg.RigidBody(M, (A, A, C), orientation=lg.EulerAngles(psi, theta, phi), name="top")
    s = lg.System([psi, theta, phi], bodies=[body], name="free top")
    res = check_gauss(s, {"M": 2.0, "A": 1.0, "C": 1.5}, samples=4, ranges={"theta": (0.5, 1.2)})
    assert res.ok, str(res)
    assert res.diagnostics.momentum_drift is not None and res.diagnostics.angular_momentum_drift < 1e-8
    assert appell_identity(s).status in ("verified", "undecided")


def test_heavy_top_offset_com_and_signed_pseudo_masses():
    psi, theta, phi = lg.coordinates("psi theta phi")
    M, A, C, h, g = lg.parameters("M A C h g")
    body = lg.RigidBody(M, (A, A, C), orientation=lg.EulerAngles(psi, theta, phi), com=(0, 0, h), name="top")
    s = lg.System([psi, theta, phi], bodies=[body], V=M * g * body.centre_of_mass[2])
    # inertia about the fixed point O; the central inertia A − M h² is positive: six positive points
    ok = check_gauss(s, {"M": 1.0, "A": 1.2, "C": 0.8, "h": 0.5, "g": 9.81}, samples=3, ranges={"theta": (0.4, 1.2)})
    assert ok.ok and not ok.signed_bodies, str(ok)
    # a massless flywheel declared with I_z only (I_x = I_y = 0): only signed pseudo-masses represent it
    th = lg.coordinates("alpha")
    I = lg.parameters("I")
    wheel = lg.RigidBody(0, (0, 0, I), orientation=lg.rot_z(th), name="flywheel")
    s2 = lg.System([th], bodies=[wheel], forces={th: sp.Integer(2)})
    res = check_gauss(s2, {"I": 0.5}, samples=2)
    assert res.ok and res.signed_bodies == ("flywheel",), str(res)


def test_superfluous_coordinates_and_nonholonomic_constraints():
    x, y = lg.coordinates("x y")
    m, g, l = lg.parameters("m g l")
    pend = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], V=m * g * y,
                     constraints=[lg.Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    assert check_gauss(pend, {"m": 1, "g": 9.81, "l": 1}, samples=3).ok
    # Chaplygin sled: a body sliding on a knife edge at its origin, centre of mass a ahead of it
    X, Y, th = lg.coordinates("X Y theta")
    M, J, a = lg.parameters("M J a")
    sled = lg.RigidBody(M, (J, J, J + M * a**2), origin=(X, Y), orientation=lg.rot_z(th), com=(a, 0, 0))
    s = lg.System([X, Y, th], bodies=[sled],
                  constraints=[lg.Nonholonomic(-X.diff(t) * sp.sin(th) + Y.diff(t) * sp.cos(th), "knife")])
    res = check_gauss(s, {"M": 1.0, "J": 0.3, "a": 0.4}, samples=3)
    assert res.ok, str(res)


def test_a_wrong_model_is_caught(monkeypatch):
    s = _double_pendulum()
    wrong = _double_pendulum(l1=sp.Symbol("l1", positive=True) * sp.Rational(21, 20))  # a 5 % chain-rule slip
    real_compile = lg.System.compile
    monkeypatch.setattr(lg.System, "compile", lambda self, params=None, **kw: real_compile(wrong, params, **kw))
    res = check_gauss(s, E22, samples=2, diagnostics=False)
    assert res.applicable and not res.agrees and not res.ok and res.max_rel_error > 1e-3
    assert "DISAGREE" in str(res)


def test_not_applicable_cases():
    x = lg.coordinates("x")
    m, k, mu, g = lg.parameters("m k mu g")
    given = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, name="T given")
    r = check_gauss(given, {"m": 1, "k": 1})
    assert not r.applicable and "T given directly" in r.reason and "not applicable" in str(r)
    assert not r.agrees and not r.ok
    X, Y = lg.coordinates("X Y")
    rough = lg.System([X, Y], bodies=[lg.Particle(m, (X, Y))], V=m * g * Y,
                      constraints=[lg.Rough(Y, mu, X.diff(t), "floor")])
    r = check_gauss(rough, {"m": 1, "g": 9.81, "mu": 0.2})
    assert not r.applicable and "rough" in r.reason


@pytest.mark.parametrize("pid", ["ex3.3", "p2.16-cm", "sec1.9", "p8.11"])
def test_appell_identity_on_corpus_problems(pid):
    from lagrange.corpus import get_problem

    r = appell_identity(get_problem(pid).system)
    assert r.status == "verified", str(r)  # p8.11: a rigid body (Euler angles) in a turning frame
