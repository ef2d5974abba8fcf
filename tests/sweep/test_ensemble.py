"""integrate_ensemble: every member reproduces solve_ivp run alone (same steps), closed forms, failures."""

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import lagrange as lg
from lagrange.sweep import integrate_ensemble

r, th = lg.coordinates("r theta")
m, g, k, r0 = lg.parameters("m g k r0")
SPRING = lg.System([r, th], bodies=[lg.Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                   V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2)


def _members(K=8):
    rng = np.random.default_rng(0)
    Y0 = np.column_stack([1 + 0.3 * rng.random(K), rng.random(K), np.zeros(K), rng.normal(size=K)])
    P = np.column_stack([np.full(K, 9.81), 10 + 90 * rng.random(K), np.ones(K), np.ones(K)])  # g, k, m, r0
    return Y0, P


@pytest.mark.parametrize("method", ["RK45", "DOP853"])
@pytest.mark.parametrize("backend", ["python", "numba"])
def test_each_member_matches_solve_ivp_alone(method, backend):
    model = SPRING.compile({"m": 1, "g": 9.81, "k": 40, "r0": 1}, backend=backend)
    Y0, P = _members()
    te = np.linspace(0, 5, 51)
    res = integrate_ensemble(model, 5.0, Y0, P, method=method, rtol=1e-8, atol=1e-10, t_eval=te)
    assert res.success.all()
    for i in range(len(Y0)):
        alone = model.with_params(dict(zip(["g", "k", "m", "r0"], P[i])))
        sol = solve_ivp(alone.fun, (0, 5), Y0[i], method=method, rtol=1e-8, atol=1e-10, t_eval=te)
        assert res.nfev[i] == sol.nfev  # the same step sequence: its own error control
        assert np.max(np.abs(res.y[i] - sol.y.T)) < 1e-10
    assert len(set(res.nfev.tolist())) > 1  # stiffer springs took more steps: no shared step size


def test_harmonic_oscillators_closed_form():
    x = lg.coordinates("x")
    kk = lg.parameters("k")
    osc = lg.System([x], bodies=[lg.Particle(1, (x,))], V=kk * x**2 / 2).compile({"k": 1.0})
    ks = np.array([0.25, 1.0, 9.0, 100.0])
    te = np.linspace(0, 3, 31)
    res = integrate_ensemble(osc, 3.0, [[1.0, 0.0]], P=ks[:, None], t_eval=te, rtol=1e-10, atol=1e-12)
    exact = np.cos(np.sqrt(ks)[:, None] * te[None, :])
    assert np.max(np.abs(res.y[:, :, 0] - exact)) < 1e-8
    assert res.nfev[-1] > 3 * res.nfev[0]


def test_a_blowing_up_member_fails_alone():
    x = lg.coordinates("x")
    c = lg.parameters("c")
    model = lg.System([x], bodies=[lg.Particle(1, (x,))], V=-c * x**4 / 4).compile({"c": 0.0})
    # x'' = c x³ from x = 1 blows up in finite time (t ≈ 0.19 for c = 100); c = 0 is free motion
    res = integrate_ensemble(model, 1.0, [[1.0, 0.5]], P=[[0.0], [100.0], [0.0]], t_eval=[0.5, 1.0])
    assert res.status.tolist() == [0, -1, 0]
    assert "step size" in res.messages[1]
    assert np.allclose(res.y[0, :, 0], [1.25, 1.5]) and np.all(np.isnan(res.y[1, -1]))


def test_bad_input():
    model = SPRING.compile({"m": 1, "g": 9.81, "k": 40, "r0": 1})
    with pytest.raises(lg.MethodError, match="method"):
        integrate_ensemble(model, 1.0, [[1, 0, 0, 0]], method="Radau")
    with pytest.raises(ValueError, match="shape"):
        integrate_ensemble(model, 1.0, [[1, 0, 0]])
    x, y = lg.coordinates("x y")
    pend = lg.System([x, y], bodies=[lg.Particle(1, (x, y))], V=9.81 * y,
                     constraints=[lg.Holonomic(sp.sqrt(x**2 + y**2) - 1)]).compile({})
    with pytest.raises(lg.MethodError, match="unconstrained"):
        integrate_ensemble(pend, 1.0, [[0.6, -0.8, 0, 0]])
