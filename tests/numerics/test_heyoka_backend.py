"""method="heyoka" (lagrange.integrate.heyoka_backend): the project's derived equations integrated by heyoka.py.

Independent truth: Kepler's equation, the damped oscillator's closed form and dissipated work; and the
project's own Taylor method at tight tolerance on the benchmark problems (pendulum, double pendulum, Kepler,
the heavy top). Refusals: constraints needing multipliers, dry friction, time-varying inputs, and heyoka
missing (named extra).
"""

import math

import numpy as np
import pytest
import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.bench.problems import get_problem, kepler_state, kepler_system
from lagrange.codegen.tape import TapeError
from lagrange.errors import BackendError, IntegrationError, LagrangeError
from lagrange.examples import n_link_pendulum
from lagrange.integrate.heyoka_backend import integrate_heyoka

KEPLER_IC = np.array(kepler_state([0.0])[0])


def _hy():
    return pytest.importorskip("heyoka")


def test_kepler_against_keplers_equation_forward_and_backward():
    _hy()
    model = kepler_system().compile({"m": 1.0, "mu": 1.0})
    for T in (6 * math.pi, -4 * math.pi):
        tt = np.linspace(0, T, 13)
        sol = integrate_heyoka(model, (0.0, T), KEPLER_IC, tt, rtol=1e-14, atol=1e-14)
        assert sol.success and sol.method.startswith("heyoka")
        assert np.max(np.abs(sol.y - kepler_state(tt))) < 1e-11


@pytest.mark.parametrize("name", ["pendulum", "double_pendulum", "kepler",
                                  pytest.param("top", marks=pytest.mark.slow)])
def test_agrees_with_the_projects_taylor_method_at_tight_tolerance(name):
    """Two Taylor integrators of the same equations (different code, LLVM vs the C interpreter) agree at
    rtol = 1e-14 on the benchmark problems, at every output time."""
    _hy()
    from lagrange.integrate.taylor import available_interpreter, integrate_taylor

    if available_interpreter() is None:
        pytest.skip("no way to run the project's Taylor method here")
    if name == "pendulum":
        s, params, y0, T = n_link_pendulum(1), {"g": 9.81}, np.array([1.2, 0.0]), 10.0
    else:
        p = get_problem(name, quick=True)
        s, params, y0, T = p.build(), p.params, np.array(list(p.initial.values()), float), p.t_end
    model = s.compile(params)
    tt = np.linspace(0, T, 11)
    ours = integrate_taylor(model, (0.0, T), y0, tt, rtol=1e-14, atol=1e-14)
    theirs = integrate_heyoka(model, (0.0, T), y0, tt, rtol=1e-14, atol=1e-14)
    scale = max(1.0, float(np.max(np.abs(ours.y))))
    assert np.max(np.abs(ours.y - theirs.y)) < 1e-10 * scale


def test_damped_oscillator_parameters_as_heyoka_pars_and_work():
    """Rayleigh damping: closed form and the dissipated work E(t) − E(0); a second run with other parameter
    values (runtime pars, same compiled code) matches its own closed form."""
    _hy()
    x = coordinates("x")
    m, k, c = parameters("m k c")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, rayleigh=c * x.diff(t) ** 2 / 2)
    tt = np.linspace(0, 8, 17)
    model = s.compile({"m": 1.0, "k": 4.0, "c": 0.4})
    for kk, cc in ((4.0, 0.4), (9.0, 1.0)):
        run_model = model.with_params({"k": kk, "c": cc})
        sol = integrate_heyoka(run_model, (0.0, 8.0), np.array([1.0, 0.0]), tt, rtol=1e-13, atol=1e-13)
        g, wd = cc / 2, math.sqrt(kk - cc**2 / 4)
        xe = np.exp(-g * tt) * (np.cos(wd * tt) + g / wd * np.sin(wd * tt))
        ve = -np.exp(-g * tt) * (wd + g * g / wd) * np.sin(wd * tt)
        assert np.max(np.abs(sol.y[:, 0] - xe)) < 1e-11 and np.max(np.abs(sol.y[:, 1] - ve)) < 1e-11
        assert np.max(np.abs(sol.work - (0.5 * ve**2 + kk / 2 * xe**2 - kk / 2))) < 1e-11


def test_explicit_time_and_t_eval_ending_before_the_span():
    """A forced oscillator x'' = −x + sin(2t): x = (2 sin t − sin 2t)/3 from rest; outputs stop before t1."""
    _hy()
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, forces={x: sp.sin(2 * t)})
    tt = np.linspace(0, 4, 9)
    sol = integrate_heyoka(s.compile({}), (0.0, 6.0), np.array([0.0, 0.0]), tt, rtol=1e-13, atol=1e-13)
    assert sol.success and np.max(np.abs(sol.y[:, 0] - (2 * np.sin(tt) - np.sin(2 * tt)) / 3)) < 1e-11


def test_blow_up_is_an_integration_error_with_partial():
    _hy()
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=-x**4 / 4)  # x → ∞ at t = √2
    with pytest.raises(IntegrationError) as info:
        integrate_heyoka(s.compile({}), (0.0, 3.0), np.array([1.0, math.sqrt(0.5)]), np.linspace(0, 3, 31),
                         rtol=1e-12, atol=1e-12)
    assert info.value.partial is not None and info.value.partial.t[-1] <= math.sqrt(2)
    assert len(info.value.partial.t) in (14, 15)


def test_refusals_name_the_combination():
    _hy()
    x, y = coordinates("x y")
    constrained = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=y, constraints=[x**2 + y**2 - 1])
    with pytest.raises(TapeError, match="unconstrained.*1 constraint"):
        integrate_heyoka(constrained.compile({}), (0, 1), np.array([1.0, 0, 0, 0]), [1.0], rtol=1e-9, atol=1e-9)
    mu = parameters("mu")
    friction = System([x], T=x.diff(t) ** 2 / 2, forces={x: -mu * sp.sign(x.diff(t))})
    with pytest.raises(TapeError, match=r"sign\("):
        integrate_heyoka(friction.compile({"mu": 0.1}), (0, 1), np.array([1.0, 1.0]), [1.0], rtol=1e-9,
                         atol=1e-9)
    with pytest.raises(ValueError, match="rtol"):
        integrate_heyoka(kepler_system().compile({"m": 1.0, "mu": 1.0}), (0, 1), KEPLER_IC, [1.0], rtol=0.0,
                         atol=1e-9)


def test_missing_heyoka_names_the_extra(monkeypatch):
    from lagrange.codegen import heyoka_expr

    monkeypatch.setattr(heyoka_expr, "heyoka_available", lambda: False)
    s = n_link_pendulum(1)
    model = s.compile({"g": 9.81})
    heyoka_expr._ODES.pop(model.equations, None)
    with pytest.raises(BackendError, match=r'pip install "lagrange-dynamics\[heyoka\]"') as info:
        integrate_heyoka(model, (0, 1), np.array([0.1, 0.0]), [1.0], rtol=1e-9, atol=1e-9)
    assert isinstance(info.value, LagrangeError)


@pytest.mark.parametrize("which", ["heyoka", "taylor"])
def test_time_varying_inputs_are_refused_not_dropped(which):
    """A model driven by a schedule u(t): both Taylor routes hold inputs as constants, so they refuse it
    (InputError, a TypeError) instead of integrating as if the input were absent."""
    import lagrange as lg
    from lagrange.codegen.input_values import resolve_inputs
    from lagrange.errors import InputError
    from lagrange.integrate.taylor import integrate_taylor

    if which == "heyoka":
        _hy()
    x = coordinates("x")
    F = lg.inputs("F")
    s = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, forces={x: F})
    model = s.compile({}, inputs={F: 0.0})
    _, schedule = resolve_inputs(s.derived, {F: lambda tt: math.cos(tt)}, (0.0, 1.0), np.zeros(2))
    assert schedule is not None
    run = integrate_heyoka if which == "heyoka" else integrate_taylor
    with pytest.raises(InputError, match=f"method='{which}' cannot follow time-varying inputs"):
        run(model.with_schedule(schedule), (0.0, 1.0), np.zeros(2), [1.0], rtol=1e-9, atol=1e-9)


def _oscillator_run(**kw):
    x = coordinates("x")
    osc = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2)
    return osc, x, osc.simulate(20.0, {"x": 1.0, "x_dot": 0.0}, {}, method="heyoka", rtol=1e-12, atol=1e-12,
                                n_points=2001, max_step=0.01, **kw)


def _ticks_then(monkeypatch, n: int, action):
    """Make the heyoka step callback run ``action()`` at its ``n``-th call (then behave as before)."""
    from lagrange.integrate import heyoka_backend

    calls = {"n": 0}
    tick = heyoka_backend._Interrupt.tick

    def counting(self, ta):
        calls["n"] += 1
        if calls["n"] == n:
            action()
        return tick(self, ta)

    monkeypatch.setattr(heyoka_backend._Interrupt, "tick", counting)


def _check_partial(exc, full, x):
    p = exc.partial
    assert p is not None and not p.success and len(p.t) >= 2 and 0 < p.t[-1] < 20.0
    assert p.t[-1] == pytest.approx(exc.t) and p.y[-1, 0] == pytest.approx(exc.state[x])
    k = len(p.t) - 1  # the output times reached, as in the uninterrupted run; then the state reached
    np.testing.assert_array_equal(p.t[:k], full.t[:k])
    np.testing.assert_allclose(p.y[:k], full.y[:k], rtol=0, atol=1e-13)
    np.testing.assert_allclose(p[x], np.cos(p.t), atol=1e-9)  # the state reached too


def test_ctrl_c_keeps_the_output_points_reached(monkeypatch):
    """SIGINT during a heyoka run: heyoka stops after the step, and ``partial`` holds every output point
    reached (not only those of finished chunks) and the state reached."""
    import signal

    _hy()
    osc, x, full = _oscillator_run()
    _ticks_then(monkeypatch, 300, lambda: signal.raise_signal(signal.SIGINT))
    with pytest.raises(KeyboardInterrupt) as info:
        _oscillator_run()
    exc = info.value
    from lagrange.errors import IntegrationInterrupted

    assert isinstance(exc, IntegrationInterrupted)
    _check_partial(exc, full, x)
    assert len(exc.partial.t) > 2  # inside the first chunk of output points
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # restored


def test_keyboard_interrupt_raised_in_the_callback_keeps_a_partial_trajectory(monkeypatch):
    """A KeyboardInterrupt raised in the step callback itself propagates out of heyoka: the output points of
    the finished chunks and the state reached are kept (never a header-only partial)."""
    _hy()

    def interrupt():
        raise KeyboardInterrupt

    osc, x, full = _oscillator_run()
    for n in (5, 600):  # inside the first chunk, and after some chunks finished
        _ticks_then(monkeypatch, n, interrupt)
        with pytest.raises(KeyboardInterrupt) as info:
            _oscillator_run()
        monkeypatch.undo()
        _check_partial(info.value, full, x)
