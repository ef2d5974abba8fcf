"""Structure-preserving fixed-step integrators: convergence order, invariants, requirements."""

import numpy as np
import pytest
import sympy as sp

from lagrange import LagrangeError, Particle, System, coordinates, parameters, t
from lagrange.examples import n_link_pendulum


def pendulum():
    th = coordinates("theta")
    m, g, l = parameters("m g l")
    s = System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th))
    return s, th, {m: 1, g: 9.81, l: 1}


@pytest.mark.parametrize("method, order", [("midpoint", 2), ("gl4", 4), ("gl6", 6), ("verlet", 2), ("dg", 2)])
def test_convergence_order(method, order):
    s, th, p = pendulum()
    ic = {th: 1.0, th.diff(t): 0.0}
    ref = s.simulate(5, ic, p, rtol=1e-13, atol=1e-14, t_eval=[5.0]).y[-1]
    hs = [0.05, 0.025, 0.0125] if order < 6 else [0.2, 0.1, 0.05]
    errs = [np.max(np.abs(s.simulate(5, ic, p, method=method, step=h).y[-1] - ref)) for h in hs]
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert slope == pytest.approx(order, abs=0.2)


def test_discrete_gradient_conserves_energy_of_a_nonseparable_system():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    sol = s.simulate(50, {q1: 2.0, q2: 2.3, q1.diff(t): 0, q2.diff(t): 0}, {"g": 9.81}, method="dg", step=0.01)
    assert sol.energy_error() < 1e-10  # chaotic, high energy: exact up to round-off accumulated over 5000 steps


def _bounded_energy(periods, method, step):
    s, th, p = pendulum()
    sol = s.simulate(2.1 * periods, {th: 1.0, th.diff(t): 0.0}, p, method=method, step=step, n_points=2001)
    E = sol.energy
    first, last = np.ptp(E[:200]), np.ptp(E[-200:])
    assert last < 1.2 * first  # no secular drift
    assert np.ptp(E) < 1e-2 * abs(E[0])


def test_symplectic_energy_bounded_1000_periods():
    _bounded_energy(1_000, "verlet", 0.05)


@pytest.mark.slow
@pytest.mark.parametrize("method, step", [("verlet", 0.05), ("gl4", 0.1)])
def test_symplectic_energy_bounded_10000_periods(method, step):
    """10,000 periods of the pendulum (T ≈ 2.1 s): the energy error stays bounded, no drift."""
    _bounded_energy(10_000, method, step)


def test_gauss_legendre_is_time_symmetric():
    s, th, p = pendulum()
    fwd = s.simulate(3, {th: 1.0, th.diff(t): 0.3}, p, method="gl4", step=0.05)
    back = s.simulate(3, {th: fwd.y[-1, 0], th.diff(t): -fwd.y[-1, 1]}, p, method="gl4", step=0.05)
    assert back.y[-1, 0] == pytest.approx(1.0, abs=1e-12) and back.y[-1, 1] == pytest.approx(-0.3, abs=1e-12)


def test_requirements_are_checked():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    ic = {q1: 0.1, q2: 0.1, q1.diff(t): 0, q2.diff(t): 0}
    with pytest.raises(LagrangeError, match="separable"):
        s.simulate(1, ic, {"g": 9.81}, method="verlet", step=0.01)
    x = coordinates("x")
    m, k, b = parameters("m k b")
    damped = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-b * x.diff(t) ** 2 / 2)
    with pytest.raises(LagrangeError, match="conservative"):
        damped.simulate(1, {x: 1, x.diff(t): 0}, {"m": 1, "k": 1, "b": 1}, method="gl4", step=0.01)
    with pytest.raises(TypeError, match="step"):
        n_link_pendulum(1).simulate(1, {"q1": 0.1, "q1_dot": 0}, {"g": 9.81}, method="gl4")
