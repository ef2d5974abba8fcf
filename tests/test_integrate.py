import numpy as np
import pytest
import sympy as sp

from lagrange import (
    InitialConditionError,
    IntegrationError,
    Particle,
    System,
    coordinates,
    parameters,
    t,
)


def _oscillator(P=0, rayleigh=0, forces=None):
    x = coordinates("x")
    m, k = parameters("m k")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=P, rayleigh=rayleigh, forces=forces), x


@pytest.mark.parametrize("method", ["DOP853", "RK45", "LSODA", "Radau", "BDF"])
def test_harmonic_oscillator_closed_form(method):
    s, x = _oscillator()
    rtol = 1e-10
    sol = s.simulate(10, {x: 1.0, x.diff(t): 0.0}, {"m": 2.0, "k": 8.0}, method=method, rtol=rtol, atol=1e-12)
    exact = np.cos(2.0 * sol.t)
    err = np.max(np.abs(sol[x] - exact))
    assert err < (1e-7 if method in ("DOP853", "Radau") else 1e-5)
    assert np.allclose(sol[x.diff(t)], -2 * np.sin(2 * sol.t), atol=1e-4)
    assert np.allclose(sol[x.diff(t, 2)], -4 * sol[x], atol=1e-9)


def test_damped_oscillator_power_function_wells_sign():
    """P = -b xdot^2/2 (Wells) damps: x = exp(-g t)(cos wd t + g/wd sin wd t)."""
    x = coordinates("x")
    m, k, b = parameters("m k b")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-b * x.diff(t) ** 2 / 2)
    p = {"m": 1.0, "k": 4.0, "b": 0.4}
    sol = s.simulate(8, {x: 1.0, "x_dot": 0.0}, p, rtol=1e-11, atol=1e-13)
    gam = 0.2
    wd = np.sqrt(4.0 - gam**2)
    exact = np.exp(-gam * sol.t) * (np.cos(wd * sol.t) + gam / wd * np.sin(wd * sol.t))
    assert np.max(np.abs(sol["x"] - exact)) < 1e-9
    # energy is lost, and the power balance accounts for exactly that
    assert sol.energy[-1] < 0.1 * sol.energy[0]
    assert sol.energy_error() < 1e-8


def test_power_balance_exposes_a_wrong_model():
    """The work integral uses the declared forces: if the integrator integrates other dynamics, the
    balance residual is large. Simulate with drag, then judge the trajectory against a model
    without it."""
    s, x = _oscillator(P=-parameters("b") * coordinates("x").diff(t) ** 2 / 2)
    sol = s.simulate(5, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "b": 0.3})
    assert sol.energy_error() < 1e-8
    conservative, _ = _oscillator()
    model = conservative.compile({"m": 1, "k": 1})
    h = model.diagnostics(sol.t, sol.y)["jacobi"]
    assert abs(h[-1] - h[0]) > 0.1  # a conservative model cannot explain this trajectory


def test_time_dependent_forcing_resonance_free_closed_form():
    x = coordinates("x")
    m, k, F0, w = parameters("m k F0 omega")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: F0 * sp.cos(w * t)})
    p = {"m": 1.0, "k": 4.0, "F0": 3.0, "omega": 1.0}
    sol = s.simulate(10, {x: 0.0, x.diff(t): 0.0}, p, rtol=1e-11, atol=1e-13)
    exact = 3.0 / (4.0 - 1.0) * (np.cos(sol.t) - np.cos(2 * sol.t))
    assert np.max(np.abs(sol["x"] - exact)) < 1e-8
    assert sol.energy_error() < 1e-8  # balance includes the work of the applied force


def test_initial_condition_errors_name_entries():
    s, x = _oscillator()
    with pytest.raises(InitialConditionError, match="x_dot"):
        s.simulate(1, {x: 1.0}, {"m": 1, "k": 1})
    with pytest.raises(InitialConditionError, match="not a coordinate"):
        s.simulate(1, {x: 1.0, "x_dot": 0, "y": 2}, {"m": 1, "k": 1})
    with pytest.raises(InitialConditionError, match="not finite"):
        s.simulate(1, {x: float("inf"), "x_dot": 0}, {"m": 1, "k": 1})


def test_non_finite_values_reported_with_time_and_state():
    """A particle falling into a 1/r singularity: the error gives the time and the state."""
    r = coordinates("r")
    m, c = parameters("m c")
    s = System([r], T=m * r.diff(t) ** 2 / 2, forces={r: -c / r**2})
    with pytest.raises(IntegrationError) as exc:
        s.simulate(5, {r: 1.0, r.diff(t): 0.0}, {"m": 1, "c": 1})
    msg = str(exc.value)
    assert "t=" in msg and "r=" in msg


def test_implicit_methods_use_generated_jacobian():
    from scipy.optimize import approx_fprime

    from lagrange.examples import n_link_pendulum
    from lagrange.integrate.scipy_ivp import jacobian_function

    s = n_link_pendulum(3)
    model = s.compile({"g": 9.81})
    jac = jacobian_function(model)
    y = np.array([0.3, -0.2, 0.5, 0.1, 0.4, -0.3])
    J = jac(0.0, y)
    Jfd = np.array([approx_fprime(y, lambda z, i=i: model.fun(0.0, z)[i], 1e-7) for i in range(6)])
    assert np.allclose(J, Jfd, atol=1e-5)


def test_auto_method_reports_choice():
    s, x = _oscillator(P=-parameters("b") * coordinates("x").diff(t) ** 2 / 2)
    sol = s.simulate(1, {x: 1.0, "x_dot": 0}, {"m": 1, "k": 1, "b": 1}, method="auto")
    # light damping is not stiff: a smooth problem (the Taylor tape, or DOP853 without a tape interpreter)
    assert sol.method.split(" ")[0] in ("taylor", "DOP853") and "auto: " in sol.method and "not stiff" in sol.method
    with pytest.raises(TypeError, match="unknown method"):
        s.simulate(1, {x: 1.0, "x_dot": 0}, {"m": 1, "k": 1, "b": 1}, method="Euler")


class TestCoulombFriction:
    """Block on a rough floor tied to a spring: each half period the amplitude drops by 2 mu m g / k,
    and the block sticks for good once |k x| <= mu m g (closed form)."""

    def _system(self):
        x = coordinates("x")
        m, k, mu, g = parameters("m k mu g")
        return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * g * sp.Abs(x.diff(t))), x

    def test_events_give_exact_stick_slip(self):
        s, x = self._system()
        times = np.pi * np.arange(1, 8)
        sol = s.simulate(25, {x: 1.05, x.diff(t): 0}, {"m": 1, "k": 1, "mu": 0.1, "g": 1}, t_eval=times)
        expected = [-0.85, 0.65, -0.45, 0.25, -0.05, -0.05, -0.05]
        assert np.allclose(sol["x"], expected, atol=1e-7)
        assert np.all(np.abs(sol["x_dot"][5:]) < 1e-9)  # stuck, no chatter
        assert np.allclose(sol.accelerations[5:], 0.0, atol=1e-9)  # static friction balances the spring
        assert sol.energy_error() < 1e-7

    def test_regularized_friction_approximates(self):
        s, x = self._system()
        sol = s.simulate(25, {x: 1.05, x.diff(t): 0}, {"m": 1, "k": 1, "mu": 0.1, "g": 1},
                         friction="regularize", method="LSODA", t_eval=np.pi * np.arange(1, 6))
        assert np.allclose(sol["x"], [-0.85, 0.65, -0.45, 0.25, -0.05], atol=1e-4)


def test_trajectory_lookup_csv_and_plot(tmp_path):
    x, y = coordinates("x y")
    m, g = parameters("m g")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y, name="projectile")
    sol = s.simulate(1, {x: 0, y: 0, x.diff(t): 1, y.diff(t): 2}, {"m": 1, "g": 9.81}, n_points=11)
    assert np.allclose(sol[y], 2 * sol.t - 9.81 * sol.t**2 / 2)
    assert np.allclose(sol["y_ddot"], -9.81)
    with pytest.raises(KeyError):
        sol["z"]
    path = sol.to_csv(tmp_path / "p.csv")
    lines = path.read_text().splitlines()
    assert lines[0].startswith("t,x,y,x_dot,y_dot,energy") and len(lines) == 12
    png = tmp_path / "p.png"
    sol.plot(png)
    assert png.stat().st_size > 10_000


def test_auto_detects_stiff_dissipation():
    """Double pendulum with strong joint damping (numerics.md hard case 2, c = 1e4): explicit methods
    need ~300,000 evaluations; auto picks an implicit method (the Taylor method's stability-limited steps
    would cost more here) and says why."""
    from lagrange.examples import n_link_pendulum

    base = n_link_pendulum(2)
    q1, q2 = base.coordinates
    c = parameters("c")
    s = System(base.coordinates, bodies=base.bodies, V=base.V,
               rayleigh=c * (q1.diff(t) ** 2 + (q2.diff(t) - q1.diff(t)) ** 2) / 2)
    ic = {q1: 0.3, q2: -0.2, q1.diff(t): 0, q2.diff(t): 0}
    sol = s.simulate(10, ic, {"g": 9.81, "c": 1e4}, method="auto", rtol=1e-6, atol=1e-8)
    assert sol.method.startswith("LSODA (auto: stiff") and "the Taylor method would take" in sol.method
    assert sol.nfev < 5_000
    soft = s.simulate(1, ic, {"g": 9.81, "c": 0.01}, method="auto")
    assert not soft.method.startswith("Radau")
