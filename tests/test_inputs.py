"""Time-varying inputs (lagrange.inputs): declaration, values at simulate time on every route, refusals.

Truth: closed-form forced responses (linear oscillator, Coulomb block under a ramp force), a second formulation
(a feedback law against the same system with the feedback folded into its parameters; a constrained Cartesian
pendulum against its angle form), the power balance, and a cart-pole stabilized by an LQR gain computed from
its textbook linearization.
"""

import math
import re

import numpy as np
import pytest
import sympy as sp
from scipy.interpolate import CubicSpline
from scipy.linalg import solve_continuous_are

import lagrange as lg
from lagrange import t
from lagrange.errors import DeclarationError, InputError, IntegrationError, ParameterError

M_, K_, C_ = 1.0, 4.0, 0.3
F0, W = 0.7, 1.3


def oscillator(damped=True):
    x = lg.coordinates("x")
    m, k, c = lg.parameters("m k c")
    F = lg.inputs("F")
    extra = {"rayleigh": c * x.diff(t) ** 2 / 2} if damped else {}
    return lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: F}, **extra), x, F


def params(damped=True):
    return {"m": M_, "k": K_, "c": C_} if damped else {"m": M_, "k": K_}


def steady_state(m, k, c, f0, w):
    """x = A cos(ωt − φ) for m ẍ + c ẋ + k x = F0 cos ωt."""
    amp = f0 / math.hypot(k - m * w**2, c * w)
    return amp, math.atan2(c * w, k - m * w**2)


# --- declaration -------------------------------------------------------------------------------------------
def test_inputs_are_declared_symbols_detected_and_kept_apart_from_parameters():
    u, F = lg.inputs("u F")
    assert u.is_real and isinstance(F, sp.Symbol) and F != sp.Symbol("F", real=True)
    s, x, F = oscillator()
    assert s.derived.inputs == (F,) and s.inputs == (F,)
    assert F not in s.derived.parameters and [p.name for p in s.derived.parameters] == ["c", "k", "m"]
    assert s.derived.numeric_parameters[-1] == F and s.derived.input_offset == 3
    # strict parameter lists need not name the inputs
    m, k = lg.parameters("m k")
    strict = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, forces={x: F}, parameters=[m, k])
    assert strict.derived.inputs == (F,)
    # inputs reach forces through Force vectors, torques and P too
    y = lg.coordinates("y")
    s2 = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], forces=lg.Force((x, y), (F, 0)),
                   P=-sp.Symbol("b", positive=True) * (x.diff(t) - u) ** 2 / 2)
    assert set(s2.derived.inputs) == {u, F}
    assert sp.simplify(s2.derived.applied[0] - F) == 0


@pytest.mark.parametrize("where, fragment", [
    ("T", "T contains the input u"),
    ("V", "V contains the input u"),
    ("constraint", "constraint"),
    ("prescribed", "prescribed motion of s contains the input u"),
    ("coordinate", "u is an input (lagrange.inputs), not a coordinate"),
    ("name", "named like a coordinate"),
    ("clash", "share the name"),
])
def test_input_misuse_is_refused_at_declaration(where, fragment):
    x, s_ = lg.coordinates("x s")
    m = lg.parameters("m")
    u = lg.inputs("u")
    T = m * x.diff(t) ** 2 / 2
    kwargs = {"T": T}
    coords = [x]
    if where == "T":
        kwargs["T"] = T * (1 + u**2)
    elif where == "V":
        kwargs["V"] = u * x
    elif where == "constraint":
        y = lg.coordinates("y")
        coords, kwargs = [x, y], {"T": T + m * y.diff(t) ** 2 / 2, "constraints": [x - u * y]}
    elif where == "prescribed":
        kwargs.update(T=T + m * s_.diff(t) ** 2 / 2, prescribed={s_: u * t})
    elif where == "coordinate":
        coords = [x, u]
    elif where == "name":
        kwargs["forces"] = {x: lg.inputs("x_dot")}
    elif where == "clash":
        kwargs["forces"] = {x: u + sp.Symbol("u", real=True)}
    with pytest.raises(DeclarationError, match=re.escape(fragment)) as err:
        lg.System(coords, **kwargs)
    assert isinstance(err.value, ValueError)


# --- closed forms ------------------------------------------------------------------------------------------
def test_driven_damped_oscillator_matches_the_closed_form_steady_state():
    s, x, F = oscillator()
    amp, phase = steady_state(M_, K_, C_, F0, W)
    # started on the steady state: the homogeneous part is zero, so x(t) = A cos(ωt − φ) exactly
    init = {x: amp * math.cos(phase), x.diff(t): amp * W * math.sin(phase)}
    sol = s.simulate(20, init, params(), inputs={F: lambda tt: F0 * math.cos(W * tt)}, rtol=1e-11, atol=1e-13)
    exact = amp * np.cos(W * sol.t - phase)
    assert np.max(np.abs(sol["x"] - exact)) < 1e-8 * amp
    # amplitude and phase by least squares on cos/sin
    a, b = np.linalg.lstsq(np.c_[np.cos(W * sol.t), np.sin(W * sol.t)], sol["x"], rcond=None)[0]
    assert math.hypot(a, b) == pytest.approx(amp, rel=1e-8)
    assert math.atan2(b, a) == pytest.approx(phase, abs=1e-8)
    assert np.allclose(sol[F], F0 * np.cos(W * sol.t)) and np.allclose(sol["F"], sol[F])
    # the input does work, and the power balance accounts for it
    assert np.max(np.abs(sol.work)) > 0.1 and sol.energy_error() < 1e-8


def test_small_amplitude_pendulum_follows_the_linear_forced_response():
    th = lg.coordinates("theta")
    m, g, l, c = lg.parameters("m g l c")
    tau = lg.inputs("tau")
    s = lg.System([th], T=m * l**2 * th.diff(t) ** 2 / 2, V=-m * g * l * sp.cos(th), forces={th: tau},
                  rayleigh=c * th.diff(t) ** 2 / 2)
    p = {"m": 1.0, "g": 9.81, "l": 1.0, "c": 0.5}
    w, f0 = 2.0, 1e-4
    amp, phase = steady_state(1.0, 9.81, 0.5, f0, w)
    init = {th: amp * math.cos(phase), th.diff(t): amp * w * math.sin(phase)}
    sol = s.simulate(15, init, p, inputs={"tau": lambda tt: f0 * np.cos(w * tt)}, rtol=1e-11, atol=1e-16)
    # sin θ = θ − θ³/6: a relative departure of order θ² ≈ 1e-10 from the linear response
    assert np.max(np.abs(sol["theta"] - amp * np.cos(w * sol.t - phase))) < 1e-6 * amp


# --- value forms agree -------------------------------------------------------------------------------------
def test_constant_callable_feedback_sampled_and_expression_values_agree():
    s, x, F = oscillator()
    init = {x: 0.1, x.diff(t): 0.0}
    ts = np.linspace(0, 10, 3)
    runs = {
        "constant": 0.5,
        "sympy number": sp.Rational(1, 2),
        "u(t)": lambda tt: 0.5,
        "u(t, y)": lambda tt, y: 0.5,
        "samples": (ts, np.full(3, 0.5)),
    }
    finals = {k: s.simulate(10, init, params(), inputs={F: v}, n_points=11).y[-1] for k, v in runs.items()}
    for k, v in finals.items():
        assert np.allclose(v, finals["constant"], rtol=0, atol=1e-9), k
    # time-varying: a callable, an expression of t and dense samples (linear interpolation, error ~ h²ω²F0/8)
    cos_fn = s.simulate(10, init, params(), inputs={F: lambda tt: F0 * np.cos(W * tt)}, n_points=101)
    expr = s.simulate(10, init, params(), inputs={F: F0 * sp.cos(W * t)}, n_points=101)
    # h = 0.25: the linear interpolant is off by at most h²ω²F0/8 ≈ 9e-3 between samples (each sample is a kink
    # of the force that the adaptive steps resolve: few samples keep this test cheap)
    samples = np.linspace(0, 10, 41)
    sampled = s.simulate(10, init, params(), inputs={F: (samples, F0 * np.cos(W * samples))}, n_points=101)
    assert np.max(np.abs(expr.y - cos_fn.y)) < 1e-9
    assert 1e-6 < np.max(np.abs(sampled.y - cos_fn.y)) < 1e-2
    assert np.allclose(sampled[F], F0 * np.cos(W * sampled.t), atol=9.3e-3)
    on_samples = np.isclose(sampled.t[:, None], samples[None, :], atol=1e-12).any(axis=1)
    assert np.allclose(sampled[F][on_samples], F0 * np.cos(W * sampled.t[on_samples]), atol=1e-12)  # exact there
    # cubic interpolation: a scipy CubicSpline is a callable of t
    spline = s.simulate(10, init, params(), inputs={F: CubicSpline(samples, F0 * np.cos(W * samples))}, n_points=101)
    assert np.max(np.abs(spline.y - cos_fn.y)) < 1e-4


def test_feedback_law_equals_the_system_with_the_feedback_folded_in():
    s, x, F = oscillator()
    kappa, gamma = 2.5, 0.4  # F = −κ x − γ ẋ: a stiffer, more damped oscillator
    init = {x: 0.3, x.diff(t): -0.2}
    fb = s.simulate(8, init, params(), inputs={F: lambda tt, y: -kappa * y[0] - gamma * y[1]})
    folded = s.simulate(8, init, {"m": M_, "k": K_ + kappa, "c": C_ + gamma}, inputs={F: 0})
    assert np.max(np.abs(fb.y - folded.y)) < 1e-8
    assert np.allclose(fb[F], -kappa * fb["x"] - gamma * fb["x_dot"])
    assert fb.energy_error() < 1e-8


# --- routes ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("method", ["RK45", "LSODA", "Radau"])
def test_scipy_methods_run_time_varying_inputs(method):
    s, x, F = oscillator(damped=False)
    sol = s.simulate(6, {x: 0, x.diff(t): 0}, params(False), inputs={F: lambda tt: F0 * math.cos(W * tt)},
                     method=method, rtol=1e-10, atol=1e-12, n_points=61)
    exact = F0 / (K_ - W**2) * (np.cos(W * sol.t) - np.cos(2 * sol.t))
    assert np.max(np.abs(sol["x"] - exact)) < 1e-6


def test_auto_never_picks_the_taylor_tape_for_varying_inputs_but_constants_run_there():
    from lagrange.integrate.taylor import available_interpreter

    s, x, F = oscillator(damped=False)
    init = {x: 0, x.diff(t): 0}
    varying = s.simulate(3, init, params(False), inputs={F: lambda tt: 2.0}, method="auto")
    assert "taylor" not in varying.method
    exact = 2.0 / K_ * (1 - np.cos(2 * varying.t))
    assert np.max(np.abs(varying["x"] - exact)) < 1e-7
    if available_interpreter() is None:
        pytest.skip("no Taylor interpreter (C compiler or numba) here")
    const = s.simulate(3, init, params(False), inputs={F: 2.0}, method="taylor")
    assert const.method.startswith("taylor") and np.max(np.abs(const["x"] - exact)) < 1e-9


@pytest.mark.slow
def test_compiled_numba_loop_runs_constant_inputs():
    pytest.importorskip("numba")
    s, x, F = oscillator(damped=False)
    sol = s.simulate(3, {x: 0, x.diff(t): 0}, params(False), inputs={F: 2.0}, backend="numba", loop="compiled",
                     method="RK45")
    assert "compiled loop" in sol.method
    assert np.max(np.abs(sol["x"] - 2.0 / K_ * (1 - np.cos(2 * sol.t)))) < 1e-6
    # auto falls back to the scipy loop for a callable, and says why
    sol = s.simulate(3, {x: 0, x.diff(t): 0}, params(False), inputs={F: lambda tt: 2.0}, backend="numba")
    assert "time-varying inputs" in sol.method
    assert np.max(np.abs(sol["x"] - 2.0 / K_ * (1 - np.cos(2 * sol.t)))) < 1e-7


def test_cart_pole_lqr_stabilizes_the_upright_pole():
    x, th = lg.coordinates("x theta")  # theta from the upward vertical
    M, m, l, g = lg.parameters("M m l g")
    u = lg.inputs("u")
    pole = (x + l * sp.sin(th), l * sp.cos(th))
    s = lg.System([x, th], T=M * x.diff(t) ** 2 / 2, bodies=[lg.Particle(m, pole)], V=m * g * l * sp.cos(th),
                  forces={x: u})
    p = {"M": 1.0, "m": 0.2, "l": 0.5, "g": 9.81}
    Mv, mv, lv, gv = p["M"], p["m"], p["l"], p["g"]
    # the textbook linearization about the upright pole, state [x, θ, ẋ, θ̇]
    A = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [0, -mv * gv / Mv, 0, 0], [0, (Mv + mv) * gv / (Mv * lv), 0, 0]])
    B = np.array([[0], [0], [1 / Mv], [-1 / (Mv * lv)]])
    P = solve_continuous_are(A, B, np.diag([1.0, 10.0, 1.0, 1.0]), np.array([[1.0]]))
    K = (B.T @ P).ravel()
    assert np.all(np.linalg.eigvals(A - B @ K[None, :]).real < 0)
    init = {x: 0.0, th: 0.2, x.diff(t): 0.0, th.diff(t): 0.0}
    sol = s.simulate(12, init, p, inputs={u: lambda tt, y: -float(K @ y)}, rtol=1e-9, atol=1e-11)
    assert abs(sol["theta"][-1]) < 1e-3 and abs(sol["x"][-1]) < 1e-2 and np.max(np.abs(sol["theta"])) <= 0.2 + 1e-9
    assert np.allclose(sol[u], -(np.c_[sol["x"], sol["theta"], sol["x_dot"], sol["theta_dot"]] @ K))
    assert sol.energy_error() < 1e-7
    # without the controller the pole falls
    free = s.simulate(3, init, p, inputs={u: 0.0})
    assert np.max(np.abs(free["theta"])) > 1.0


def test_input_on_a_holonomically_constrained_pendulum_matches_the_angle_form():
    xc, yc = lg.coordinates("x y")
    th = lg.coordinates("theta")
    m, g, l = lg.parameters("m g l")
    Fx = lg.inputs("Fx")  # a horizontal force on the bob
    cart = lg.System([xc, yc], bodies=[lg.Particle(m, (xc, yc))], V=m * g * yc, forces={xc: Fx},
                     constraints=[xc**2 + yc**2 - l**2])
    angle = lg.System([th], T=m * l**2 * th.diff(t) ** 2 / 2, V=-m * g * l * sp.cos(th),
                      forces={th: Fx * l * sp.cos(th)})
    p = {"m": 1.0, "g": 9.81, "l": 1.0}

    def push(tt):
        return 0.8 * math.sin(2.5 * tt)

    a = angle.simulate(5, {th: 0.3, th.diff(t): 0.0}, p, inputs={Fx: push}, rtol=1e-11, atol=1e-13, n_points=101)
    for method, tol in (("DOP853", 1e-11), ("LSODA", 1e-9)):  # drift control: projection, then Baumgarte
        c = cart.simulate(5, {xc: math.sin(0.3), yc: -math.cos(0.3), xc.diff(t): 0.0, yc.diff(t): 0.0}, p,
                          inputs={"Fx": push}, rtol=tol, atol=tol / 100, method=method, n_points=101)
        assert ("baumgarte" in c.method) == (method == "LSODA")
        assert np.max(np.abs(c["x"] - np.sin(a["theta"]))) < 1e4 * tol
        assert np.max(np.abs(c["y"] + np.cos(a["theta"]))) < 1e4 * tol
        assert c.max_constraint_violation() < 100 * tol and c.energy_error() < 1e3 * tol


def test_coulomb_block_under_a_ramp_force_sticks_then_slips_as_the_closed_form():
    x = lg.coordinates("x")
    m, g, mu = lg.parameters("m g mu")
    u = lg.inputs("u")
    s = lg.System([x], T=m * x.diff(t) ** 2 / 2, forces={x: u - mu * m * g * sp.sign(x.diff(t))})
    p = {"m": 2.0, "g": 9.81, "mu": 0.3}
    a = 3.0  # u = a t: held by static friction until a t* = μ m g, then m ẍ = a t − μ m g
    t_star = 0.3 * 2.0 * 9.81 / a
    sol = s.simulate(4, {x: 0, x.diff(t): 0}, p, inputs={u: lambda tt: a * tt}, friction="events",
                     rtol=1e-10, atol=1e-12)
    exact = np.where(sol.t > t_star, a * np.clip(sol.t - t_star, 0, None) ** 3 / (6 * 2.0), 0.0)
    assert np.max(np.abs(sol["x"] - exact)) < 1e-6
    assert [tr.after for tr in sol.switches[2]] == ["stick", "slip+"] and np.allclose(sol[u], a * sol.t)
    assert sol.switches[2][-1].t == pytest.approx(t_star, abs=1e-7)
    assert sol.energy_error() < 1e-6


# --- refusals ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("value, error, fragment", [
    (None, ParameterError, "missing value(s) for input(s) F"),
    ("cos(t)", ParameterError, "strings are never evaluated"),
    (lambda: 1.0, InputError, "must take (t) or (t, y)"),
    (lambda tt, y, z: 1.0, InputError, "must take (t) or (t, y)"),
    (lambda tt: [1.0, 2.0], ParameterError, "must give one real number"),
    (lambda tt: math.inf, ParameterError, "must be finite"),
    ((np.array([0.0, 1.0]), np.array([0.0, 1.0])), ParameterError, "not extrapolated"),
    (sp.Symbol("w") * t, ParameterError, "may contain lagrange.t only"),
])
def test_bad_input_values_are_refused_before_integrating(value, error, fragment):
    s, x, F = oscillator()
    inputs = {} if value is None else {F: value}
    with pytest.raises(error, match=re.escape(fragment)):
        s.simulate(3, {x: 0, x.diff(t): 0}, params(), inputs=inputs)


def test_inputs_given_wrongly_or_to_routes_that_cannot_take_them_are_refused():
    s, x, F = oscillator(damped=False)
    init = {x: 0, x.diff(t): 0}
    with pytest.raises(ParameterError, match="F is an input, not parameter"):
        s.simulate(3, init, {**params(False), "F": 1.0})
    with pytest.raises(ParameterError, match="G is not an input of this system"):
        s.simulate(3, init, params(False), inputs={"F": 1.0, "G": 1.0})
    with pytest.raises(ParameterError, match="missing value"):
        s.compile(params(False))
    with pytest.raises(InputError, match="method='taylor'.*scipy methods") as err:
        s.simulate(3, init, params(False), inputs={F: lambda tt: 1.0}, method="taylor")
    assert isinstance(err.value, lg.LagrangeError) and isinstance(err.value, TypeError)
    with pytest.raises(InputError, match="loop='compiled'.*constant inputs only"):
        s.simulate(3, init, params(False), inputs={F: lambda tt, y: 1.0}, loop="compiled")
    with pytest.raises(InputError, match="geometric integrator"):
        s.simulate(3, init, params(False), inputs={F: 0.0}, method="gl4", step=0.01)
    with pytest.raises(ParameterError, match="is not an input"):  # a system without inputs
        lg.System([x], T=x.diff(t) ** 2 / 2).simulate(1, init, {}, inputs={"F": 1.0})


def test_an_input_failing_mid_run_names_the_input_and_keeps_the_partial_trajectory():
    s, x, F = oscillator()

    def bad(tt):
        return math.nan if tt > 1.0 else 0.1

    with pytest.raises(IntegrationError, match="the input F is nan") as err:
        s.simulate(3, {x: 0, x.diff(t): 0}, params(), inputs={F: bad})
    assert err.value.partial is not None and err.value.partial.t[-1] <= 1.0 + 1e-9


# --- compile, sweeps, CLI ------------------------------------------------------------------------------------
def test_compile_binds_constant_inputs_and_reuse_of_the_model_takes_new_values():
    s, x, F = oscillator(damped=False)
    model = s.compile(params(False), inputs={F: 2.0})
    assert np.allclose(model.fun(0.0, np.array([0.5, 0.0])), [0.0, (2.0 - K_ * 0.5) / M_])
    sol = s.simulate(3, {x: 0, x.diff(t): 0}, params(False), model=model, inputs={F: lambda tt: 1.0})
    assert np.max(np.abs(sol["x"] - 1.0 / K_ * (1 - np.cos(2 * sol.t)))) < 1e-7
    assert model.schedule is None  # the given model is not changed


def test_sweep_varies_a_constant_input_and_a_parameter_of_an_input_function():
    pytest.importorskip("pandas")
    s, x, F = oscillator(damped=False)
    T = 3.0
    table = lg.sweep(s, {"F": [0.0, 1.0, 2.0]}, t_end=T, initial={"x": 0, "x_dot": 0}, params=params(False),
                     inputs={F: 0.0}, workers=0, progress=False)
    assert list(table["status"]) == ["ok"] * 3
    assert np.allclose(table["final_x"], table["F"] / K_ * (1 - math.cos(2 * T)), atol=1e-8)

    def setup(system, point):
        amp = point["A"]
        return {}, {}, {"F": lambda tt: amp * math.cos(tt)}

    table = lg.sweep(s, {"A": [0.5, 1.5]}, t_end=T, initial={"x": 0, "x_dot": 0}, params=params(False),
                     setup=setup, workers=0, progress=False)
    assert np.allclose(table["final_x"], table["A"] * (math.cos(T) - math.cos(2 * T)) / 3, atol=1e-8)


SPEC = """
name = "forced oscillator"
coordinates = ["x"]
parameters = ["m", "k", "F0", "w"]
inputs = ["F"]
T = "m*x_dot**2/2"
V = "k*x**2/2"
[forces]
x = "F"
[params]
m = 1
k = 4
F0 = 1
w = 1
[initial]
x = 0
x_dot = 0
[simulate]
t_end = 3
"""


def test_cli_simulates_a_spec_with_an_input_and_refuses_one_without_a_value(tmp_path, capsys):
    from lagrange.cli import main

    good = tmp_path / "forced.toml"
    good.write_text(SPEC + '[inputs_values]\nF = "F0*cos(w*t)"\n')
    assert main(["simulate", str(good), "-q"]) == 0
    out = capsys.readouterr().out
    x3 = float(out.split("state at t=3: x=")[1].split(",")[0])
    assert x3 == pytest.approx((math.cos(3) - math.cos(6)) / 3, abs=1e-7)
    bare = tmp_path / "bare.toml"
    bare.write_text(SPEC.replace('"m", "k", "F0", "w"', '"m", "k"').replace("F0 = 1\nw = 1\n", ""))
    assert main(["simulate", str(bare), "-q"]) == 2
    assert "missing value(s) for input(s) F" in capsys.readouterr().err
    assert main(["simulate", str(bare), "-q", "--input", "F=2"]) == 0
    x3 = float(capsys.readouterr().out.split("state at t=3: x=")[1].split(",")[0])
    assert x3 == pytest.approx(2 / 4 * (1 - math.cos(6)), abs=1e-7)
    wrong = tmp_path / "wrong.toml"
    wrong.write_text(SPEC + '[inputs_values]\nG = "1"\n')
    assert main(["simulate", str(wrong), "-q"]) == 2
    assert "[inputs_values] has unknown name(s) G" in capsys.readouterr().err


def test_csv_export_has_a_column_per_input(tmp_path):
    s, x, F = oscillator()
    sol = s.simulate(2, {x: 0, x.diff(t): 0}, params(), inputs={F: lambda tt: math.sin(tt)}, n_points=5)
    lines = sol.to_csv(tmp_path / "run.csv").read_text().splitlines()
    assert lines[0] == "t,x,x_dot,F,energy,jacobi,power_balance"
    rows = np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])
    assert np.allclose(rows[:, 3], np.sin(rows[:, 0]))


def test_motor_torque_input_on_a_rigid_body_spins_it_up_as_the_closed_form():
    phi = lg.coordinates("phi")
    I = lg.parameters("I")  # noqa: E741 - the moment of inertia
    tau = lg.inputs("tau")
    wheel = lg.RigidBody(1, (I, I, I), orientation=lg.rot_z(phi))
    s = lg.System([phi], bodies=[wheel], forces=[lg.Torque(wheel, (0, 0, tau))])
    assert s.derived.inputs == (tau,)
    # τ = a t: φ = a t³ / (6 I)
    sol = s.simulate(2, {phi: 0, phi.diff(t): 0}, {"I": 0.5}, inputs={tau: lambda tt: 3 * tt}, n_points=21)
    assert np.max(np.abs(sol["phi"] - 3 * sol.t**3 / (6 * 0.5))) < 1e-8
    assert sol.energy_error() < 1e-8


def test_cli_sweeps_an_input_constant_and_a_parameter_of_an_input_expression(tmp_path, capsys):
    pytest.importorskip("pandas")
    import pandas as pd

    from lagrange.cli import main

    spec = tmp_path / "forced.toml"
    spec.write_text(SPEC + '[inputs_values]\nF = "F0*cos(w*t)"\n')
    out = tmp_path / "f0.csv"
    assert main(["sweep", str(spec), "--over", "F0=0.5,1.5", "--workers", "0", "--no-progress", "--out", str(out)]) == 0
    table = pd.read_csv(out)
    assert np.allclose(table["final_x"], table["F0"] * (math.cos(3) - math.cos(6)) / 3, atol=1e-7)
    out = tmp_path / "f.csv"
    assert main(["sweep", str(spec), "--over", "F=1,2", "--workers", "0", "--no-progress", "--out", str(out)]) == 0
    table = pd.read_csv(out)
    assert np.allclose(table["final_x"], table["F"] / 4 * (1 - math.cos(6)), atol=1e-7)
    capsys.readouterr()


def test_linearize_gives_the_input_matrix_of_declared_inputs_and_its_lqr_gain_stabilizes_the_nonlinear_cart_pole():
    """Inputs × analysis × constraints: lg.linearize reads the declared input (system.derived.inputs) and
    returns ℬ beside 𝒜 — the textbook cart-pole matrices, both for the angle form and for the pole declared
    in Cartesian coordinates with a length constraint (linearized on the manifold) — and an LQR gain designed
    on the library's own (𝒜, ℬ) stabilizes the nonlinear simulation."""
    x, th = lg.coordinates("x theta")
    M, m, l, g = lg.parameters("M m l g")
    u = lg.inputs("u")
    s = lg.System([x, th], T=M * x.diff(t) ** 2 / 2, bodies=[lg.Particle(m, (x + l * sp.sin(th), l * sp.cos(th)))],
                  V=m * g * l * sp.cos(th), forces={x: u})
    p = {"M": 1.0, "m": 0.2, "l": 0.5, "g": 9.81}
    Mv, mv, lv, gv = p["M"], p["m"], p["l"], p["g"]
    A_book = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [0, -mv * gv / Mv, 0, 0], [0, (Mv + mv) * gv / (Mv * lv), 0, 0]])
    B_book = np.array([[0], [0], [1 / Mv], [-1 / (Mv * lv)]])
    lin = lg.linearize(s, {x: 0, th: 0}, params=p)
    assert tuple(lin.inputs) == (u,)
    A, B = lin.numeric_state(p)
    np.testing.assert_allclose(A, A_book, atol=1e-12)
    np.testing.assert_allclose(B, B_book, atol=1e-12)
    # the same cart-pole with the bob in Cartesian coordinates and a rod constraint: same roots and the same
    # input response in the independent states (x, theta-like) chosen on the manifold
    X, Y = lg.coordinates("X Y")
    cart = lg.System([x, X, Y], T=M * x.diff(t) ** 2 / 2, bodies=[lg.Particle(m, (X, Y))], V=m * g * Y,
                     forces={x: u}, constraints=[lg.Holonomic((X - x) ** 2 + Y**2 - l**2, "rod")])
    lin_c = lg.linearize(cart, {x: 0, X: 0, Y: 0.5}, params=p, independent=[x, X])
    Ac, Bc = lin_c.numeric_state(p)
    w = math.sqrt((Mv + mv) * gv / (Mv * lv))  # the falling pole's rate; the free cart gives a double zero
    # the double zero is defective (a Jordan block: the cart drifts at constant speed); on the manifold it is not
    # a zero row/column that could be split off exactly, so the eigen-solver gets it only to ~sqrt(eps)
    np.testing.assert_allclose(lg.characteristic_roots(lin_c), [-w, 0, 0, w], atol=1e-7)
    np.testing.assert_allclose(lg.characteristic_roots(lin), [-w, 0, 0, w], atol=1e-12)
    # controllability-invariant check: the transfer from u to the cart position is the same
    for sv in (0.7j, 1.3 + 0.4j):
        G_book = np.linalg.solve(sv * np.eye(4) - A_book, B_book)[0, 0]
        G_c = np.linalg.solve(sv * np.eye(4) - Ac, Bc)[list(lin_c.states).index(x), 0]
        assert abs(G_c - G_book) < 1e-9 * abs(G_book)
    P = solve_continuous_are(A, B, np.diag([1.0, 10.0, 1.0, 1.0]), np.array([[1.0]]))
    K = (B.T @ P).ravel()
    sol = s.simulate(12, {x: 0.0, th: 0.2, x.diff(t): 0.0, th.diff(t): 0.0}, p,
                     inputs={u: lambda tt, y: -float(K @ y)})
    assert abs(sol["theta"][-1]) < 1e-3 and abs(sol["x"][-1]) < 1e-2


def test_time_varying_input_drives_a_nonholonomic_skate():
    """Inputs × non-holonomic constraints: a skate (ẏ cosθ − ẋ sinθ = 0) pushed along its blade by
    F(t) = F0 cos Ωt. With θ̇ = ω constant, the speed along the blade is v = v0 + F0 sin(Ωt)/(mΩ) and the
    contact point follows x = ∫ v cos ωs ds, y = ∫ v sin ωs ds (evaluated by quadrature as the reference)."""
    from scipy.integrate import quad

    x, y, th = lg.coordinates("x y theta")
    m, I = lg.parameters("m I")
    F = lg.inputs("F")
    T = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2 + I * th.diff(t) ** 2 / 2
    s = lg.System([x, y, th], T=T, forces={x: F * sp.cos(th), y: F * sp.sin(th)},
                  constraints=[lg.Nonholonomic(y.diff(t) * sp.cos(th) - x.diff(t) * sp.sin(th), "blade")])
    mv, v0, w, F0, Om = 2.0, 1.0, 0.7, 0.9, 1.7
    sol = s.simulate(6, {x: 0, y: 0, th: 0, x.diff(t): v0, y.diff(t): 0, th.diff(t): w}, {"m": mv, "I": 0.4},
                     inputs={F: lambda tt: F0 * np.cos(Om * tt)}, rtol=1e-11, atol=1e-12)

    def v(s_):
        return v0 + F0 * np.sin(Om * s_) / (mv * Om)

    for i in range(0, len(sol.t), 37):
        tt = sol.t[i]
        assert sol[x][i] == pytest.approx(quad(lambda s_: v(s_) * np.cos(w * s_), 0, tt)[0], abs=1e-7)
        assert sol[y][i] == pytest.approx(quad(lambda s_: v(s_) * np.sin(w * s_), 0, tt)[0], abs=1e-7)
    assert np.allclose(sol[th], w * sol.t, atol=1e-8)
    assert sol.max_constraint_violation() < 1e-8
    assert np.allclose(sol[F], F0 * np.cos(Om * sol.t))
