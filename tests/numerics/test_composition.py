"""Compositions of Störmer–Verlet (``verlet6``: Kahan–Li s9odr6a, ``verlet8``: McLachlan s15odr8): order against
a closed form, bounded energy over long runs, agreement with the Taylor method, both loops, refusals."""

import numpy as np
import pytest
import sympy as sp

from lagrange import LagrangeError, Particle, System, coordinates, parameters, t
from lagrange.errors import MethodError
from lagrange.examples import n_link_pendulum
from lagrange.integrate import registry
from lagrange.integrate.composition import COEFFICIENTS

LOOPS = ["scipy", "compiled"]
ORDERS = {"verlet6": 6, "verlet8": 8}


def oscillator():
    x = coordinates("x")
    return System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2), x


def pendulum():
    th = coordinates("theta")
    m, g, l = parameters("m g l")
    s = System([th], bodies=[Particle(m, (l * sp.sin(th), -l * sp.cos(th)))], V=-m * g * l * sp.cos(th))
    return s, th, {m: 1, g: 9.81, l: 1}


def test_coefficients_are_palindromic_and_consistent():
    """Σγ = 1 (consistency) and Σγ³ = 0 (the order-4 condition of a symmetric composition, HLW V.3.2)."""
    for g in COEFFICIENTS.values():
        assert np.array_equal(g, g[::-1])
        assert g.sum() == pytest.approx(1.0, abs=1e-15)
        assert (g**3).sum() == pytest.approx(0.0, abs=1e-15)
    assert len(COEFFICIENTS["verlet6"]) == 9 and len(COEFFICIENTS["verlet8"]) == 15


@pytest.mark.parametrize("loop", LOOPS)
@pytest.mark.parametrize("method, hs", [("verlet6", [0.4, 0.2, 0.1]), ("verlet8", [0.5, 0.25, 0.125])])
def test_convergence_order_on_the_harmonic_oscillator(method, hs, loop):
    """x = cos t: the slope of log error against log h is the claimed order (±0.2)."""
    s, x = oscillator()
    errs = [abs(s.simulate(10.0, {x: 1.0, x.diff(t): 0.0}, {}, method=method, step=h, loop=loop,
                           n_points=2).y[-1, 0] - np.cos(10.0)) for h in hs]
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert slope == pytest.approx(ORDERS[method], abs=0.2)


@pytest.mark.parametrize("method", ["verlet6", "verlet8"])
def test_agrees_with_taylor_on_a_nonlinear_pendulum(method):
    """A large-amplitude pendulum (θ0 = 2): close to the Taylor method at rtol 1e-15, and at least about 2^order
    times closer at h/2 (the exact order is fitted on the oscillator above)."""
    s, th, p = pendulum()
    ic = {th: 2.0, th.diff(t): 0.0}
    ref = s.simulate(8.0, ic, p, method="taylor", rtol=1e-15, atol=1e-15, t_eval=[8.0]).y[-1]
    hs = (0.05, 0.025) if method == "verlet6" else (0.1, 0.05)
    errs = [np.max(np.abs(s.simulate(8.0, ic, p, method=method, step=h, loop="compiled", n_points=2).y[-1] - ref))
            for h in hs]
    assert errs[1] < 1e-7
    assert np.log2(errs[0] / errs[1]) > ORDERS[method] - 1  # at least the order (pre-asymptotic: more)


@pytest.mark.slow  # 210,000 steps of 9 or 15 stages each
@pytest.mark.parametrize("method", ["verlet6", "verlet8"])
def test_energy_bounded_over_10000_periods(method):
    """Symplectic: the pendulum's energy error stays bounded over 10,000 periods, no secular drift."""
    s, th, p = pendulum()
    sol = s.simulate(2.1 * 10_000, {th: 1.0, th.diff(t): 0.0}, p, method=method, step=0.1, n_points=2001,
                     loop="compiled")
    E = sol.energy
    first, last = np.ptp(E[:200]), np.ptp(E[-200:])
    assert last < 1.2 * first
    assert np.ptp(E) < 1e-5 * abs(E[0])


@pytest.mark.parametrize("method", ["verlet6", "verlet8"])
def test_compiled_loop_agrees_with_python_loop_and_runs_backward(method):
    """A 2-D anharmonic well (separable, coupled): the two loops agree to round-off; running on from the end
    with the velocities reversed returns to the start (a symmetric method is time-reversible)."""
    x, y = coordinates("x y")
    s = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=(x**2 + 2 * y**2) / 2 + x**2 * y**2 / 3)
    ic = {x: 0.7, y: -0.4, x.diff(t): 0.2, y.diff(t): 0.5}
    py, comp = (s.simulate(5.0, ic, {}, method=method, step=0.05, n_points=11, loop=loop) for loop in LOOPS)
    assert "compiled loop" in comp.method and f"order {ORDERS[method]}" in comp.method
    assert np.array_equal(py.t, comp.t)
    assert np.allclose(comp.y, py.y, rtol=0, atol=1e-11)
    end = dict(zip([x, y, x.diff(t), y.diff(t)], comp.y[-1] * [1, 1, -1, -1]))
    back = s.simulate(5.0, end, {}, method=method, step=0.05, n_points=2, loop="compiled")
    assert np.allclose(back.y[-1], [0.7, -0.4, -0.2, -0.5], atol=1e-12)


@pytest.mark.parametrize("loop", LOOPS)
def test_non_separable_system_is_refused_in_both_loops(loop):
    """M(q) of the double pendulum: not separable, refused by name, with the methods that do apply."""
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    with pytest.raises(LagrangeError, match="verlet8 needs a separable Hamiltonian.*gl4"):
        s.simulate(1.0, {q1: 0.3, q2: 0.1, q1.diff(t): 0, q2.diff(t): 0}, {"g": 9.81}, method="verlet8", step=0.01,
                   loop=loop)


def test_unsupported_combinations_are_refused():
    """Dissipation (P), constraints and inputs: refused before running, naming the combination."""
    x = coordinates("x")
    c = parameters("c")
    damped = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, P=-c * x.diff(t) ** 2 / 2)
    with pytest.raises(MethodError, match="verlet6.*non-conservative"):
        damped.simulate(1.0, {x: 1.0, x.diff(t): 0.0}, {c: 0.1}, method="verlet6", step=0.01)
    x, y = coordinates("x y")
    ring = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=y, constraints=[x**2 + y**2 - 1])
    with pytest.raises(MethodError, match="verlet8.*holonomic constraints"):
        ring.simulate(1.0, {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}, {}, method="verlet8", step=0.01)


def test_registered_with_aliases_and_listed():
    assert registry.get("Kahan_Li6").name == "verlet6" and registry.get("mclachlan8").name == "verlet8"
    assert registry.get("verlet8").step_required and registry.get("verlet8").conservative_only
    table = registry.table()
    assert "verlet6" in table and "verlet8" in table
