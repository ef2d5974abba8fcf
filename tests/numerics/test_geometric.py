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


LOOPS = ["scipy", "compiled"]  # the step loop in Python, and the compiled one (lagrange.integrate._geometric_loops)


@pytest.mark.parametrize("loop", LOOPS)
@pytest.mark.parametrize("method, order", [("midpoint", 2), ("gl4", 4), ("gl6", 6), ("verlet", 2), ("dg", 2)])
def test_convergence_order(method, order, loop):
    s, th, p = pendulum()
    ic = {th: 1.0, th.diff(t): 0.0}
    ref = s.simulate(5, ic, p, rtol=1e-13, atol=1e-14, t_eval=[5.0]).y[-1]
    hs = [0.05, 0.025, 0.0125] if order < 6 else [0.2, 0.1, 0.05]
    errs = [np.max(np.abs(s.simulate(5, ic, p, method=method, step=h, loop=loop).y[-1] - ref)) for h in hs]
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert slope == pytest.approx(order, abs=0.2)


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_discrete_gradient_conserves_energy_of_a_nonseparable_system():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    sol = s.simulate(50, {q1: 2.0, q2: 2.3, q1.diff(t): 0, q2.diff(t): 0}, {"g": 9.81}, method="dg", step=0.01)
    assert sol.energy_error() < 1e-10  # chaotic, high energy: exact up to round-off accumulated over 5000 steps


def _bounded_energy(periods, method, step, loop="scipy"):
    s, th, p = pendulum()
    sol = s.simulate(2.1 * periods, {th: 1.0, th.diff(t): 0.0}, p, method=method, step=step, n_points=2001,
                     loop=loop)
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


@pytest.mark.parametrize("method, step", [("verlet", 0.05), ("midpoint", 0.05), ("gl4", 0.1), ("gl6", 0.2)])
def test_symplectic_energy_bounded_10000_periods_compiled(method, step):
    """The same 10,000 periods with the compiled loop (a second or less each)."""
    _bounded_energy(10_000, method, step, loop="compiled")


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


def shaken_pendulum():
    """A pendulum whose support moves up and down, a cos(Ωt): T has a term linear in θ̇ and depends on t."""
    th = coordinates("theta")
    m, g, l, a, w = parameters("m g l a Omega")
    y = a * sp.cos(w * t) - l * sp.cos(th)
    s = System([th], bodies=[Particle(m, (l * sp.sin(th), y))], V=m * g * y)
    return s, {th: 0.4, th.diff(t): 0.1}, {m: 1.3, g: 9.81, l: 0.7, a: 0.05, w: 11.0}


def rotating_frame():
    """A particle in a frame rotating at rate ω, in an anharmonic well: gyroscopic terms (b ≠ 0), autonomous."""
    x, y = coordinates("x y")
    m, w, k = parameters("m omega k")
    T = m / 2 * ((x.diff(t) - w * y) ** 2 + (y.diff(t) + w * x) ** 2)
    s = System([x, y], T=T, V=k * (x**2 + 2 * y**2) / 2 + (x**4 + y**4) / 4)
    return s, {x: 0.5, y: -0.2, x.diff(t): 0.1, y.diff(t): 0.3}, {m: 1.5, w: 0.8, k: 2.0}


def double_pendulum():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    return s, {q1: 1.0, q2: 0.5, q1.diff(t): 0.0, q2.diff(t): 0.3}, {"g": 9.81}


CASES = {"shaken pendulum": shaken_pendulum, "rotating frame": rotating_frame, "double pendulum": double_pendulum}


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("method", ["midpoint", "gl4", "gl6", "dg", "verlet"])
def test_compiled_loop_agrees_with_python_loop(case, method):
    """The compiled schemes are transcriptions of the Python ones: same states (to round-off), same Newton
    iteration count, same refusals — on a non-autonomous system with b(t, q) ≠ 0, a gyroscopic one and one
    whose mass matrix depends on q."""
    s, ic, p = CASES[case]()
    runs = []
    for loop in LOOPS:
        try:
            runs.append(s.simulate(3.0, ic, p, method=method, step=0.01, n_points=101, loop=loop))
        except LagrangeError as exc:
            runs.append(str(exc))
    py, compiled = runs
    if isinstance(py, str):  # verlet needs a separable H; dg an autonomous one: both loops refuse alike
        assert compiled == py
        return
    assert "compiled loop" in compiled.method and "compiled" not in py.method
    assert py.message == compiled.message  # "300 steps, k Newton iterations"
    assert np.array_equal(py.t, compiled.t)
    assert np.allclose(compiled.y, py.y, rtol=0, atol=1e-11)
    assert compiled.energy_error() == pytest.approx(py.energy_error(), rel=1e-2, abs=1e-12)


@pytest.mark.parametrize("case", CASES)
def test_generated_hessian_is_the_derivative_of_the_gradient(case):
    """∇²H from the generated second derivatives of L (the Newton matrix) against central differences of
    ∇H, and ∇H against central differences of H, at random states."""
    from lagrange.integrate.hamiltonian_model import hamiltonian_model

    s, ic, p = CASES[case]()
    hm = hamiltonian_model(s, p)
    rng = np.random.default_rng(3)
    for _ in range(3):
        z, tt = rng.uniform(-1, 1, 2 * hm.n), rng.uniform(0, 2)
        H2 = hm.hess(tt, z)
        assert np.allclose(H2, H2.T, atol=1e-12)
        eps = 1e-6
        fd = np.column_stack([(hm.grad(tt, z + e) - hm.grad(tt, z - e)) / (2 * eps) for e in np.eye(2 * hm.n) * eps])
        assert np.allclose(H2, fd, rtol=1e-6, atol=1e-6)
        fdH = np.array([(hm.H(tt, z + e) - hm.H(tt, z - e)) / (2 * eps) for e in np.eye(2 * hm.n) * eps])
        assert np.allclose(hm.grad(tt, z), fdH, rtol=1e-6, atol=1e-6)


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_fixed_loop_choice():
    s, ic, p = double_pendulum()
    model = s.compile(p, backend="numba")
    auto = s.simulate(0.1, ic, p, method="gl4", step=0.01, model=model)
    assert "compiled loop" in auto.method  # auto: compiled for numba models
    assert "compiled loop" not in s.simulate(0.1, ic, p, method="gl4", step=0.01).method  # python backend
    with pytest.raises(TypeError, match="loop must be one of"):
        s.simulate(0.1, ic, p, method="gl4", step=0.01, loop="fortran")


@pytest.mark.parametrize(("method", "h"), [("midpoint", 5.0), ("gl4", 5.0), ("dg", 2.0)])
def test_failure_messages_agree_between_loops(method, h):
    """A failed step reads the same from both loops (one wording, lagrange.integrate.base); only the last
    residual's digits may differ by round-off."""
    import re

    from lagrange import IntegrationError

    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=-sp.cos(x))
    texts = []
    for loop in LOOPS:
        with pytest.raises(IntegrationError) as info:
            s.simulate(40.0, {x: 3.0, x.diff(t): 0.0}, {}, method=method, step=h, loop=loop)
        texts.append(re.sub(r"residual [-+.e\d]+", "residual R", str(info.value)))
    assert texts[0] == texts[1] and "Newton" in texts[0]
