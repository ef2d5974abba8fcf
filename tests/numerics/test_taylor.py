"""method="taylor": the adaptive Taylor integrator (C tape interpreter and compiled series).

Independent truth: closed forms (harmonic oscillator, Kepler's equation, the damped oscillator and its
dissipated work, where a blow-up or a vanishing mass matrix happens), DOP853 at a much tighter tolerance
for every operation the tape knows, the Taylor coefficients against the reference right-hand side and the
solution, energy over long runs, and the backward run returning to the start — for each engine on its own.
"""

import math

import numpy as np
import pytest
import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.bench.problems import kepler_state, kepler_system
from lagrange.codegen.tape import TapeError, build_tape
from lagrange.errors import IntegrationError
from lagrange.examples import n_link_pendulum
from lagrange.integrate.taylor import taylor_order

pytest.importorskip("numba")

KEPLER_IC = dict(zip(("x", "y", "x_dot", "y_dot"), kepler_state([0.0])[0]))


def _oscillator(**kw):
    x = coordinates("x")
    m, k = parameters("m k")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, **kw), x


def test_order_follows_jorba_zou():
    """p = ceil(−ln ε / 2 + 1): 20 at double precision (heyoka's default order), 13 at 1e-10."""
    assert taylor_order(np.finfo(float).eps) == 20 and taylor_order(1e-10) == 13 and taylor_order(0.5) == 2


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_harmonic_oscillator_closed_form(backend):
    s, _ = _oscillator()
    tt = np.linspace(0, 20, 41)
    sol = s.simulate((0, 20), {"x": 1.0, "x_dot": 0.0}, {"m": 2.0, "k": 8.0}, method="taylor", rtol=1e-13,
                     atol=1e-13, t_eval=tt, backend=backend)
    assert sol.success and sol.method.startswith("taylor")
    assert np.max(np.abs(sol.y[:, 0] - np.cos(2 * tt))) < 1e-11
    assert np.max(np.abs(sol.y[:, 1] + 2 * np.sin(2 * tt))) < 1e-11


@pytest.mark.parametrize("tol", [1e-6, 1e-9, 1e-12])
def test_kepler_against_keplers_equation(tol):
    """Eccentric orbit (e = 0.5), 3 revolutions: the error follows the tolerance (factor 1000 per row)."""
    T = 6 * math.pi
    tt = np.linspace(0, T, 13)
    sol = kepler_system().simulate((0, T), KEPLER_IC, {"m": 1.0, "mu": 1.0}, method="taylor", rtol=tol, atol=tol,
                                   t_eval=tt)
    err = np.max(np.abs(sol.y - kepler_state(tt)))
    assert err < 300 * tol


def _all_operations_system():
    """One coordinate with a position-dependent mass and a potential using every operation of the tape (and
    the half-integer powers ±1/2, ±3/2 that order 0 takes by a square root, besides the generic 5/2)."""
    x = coordinates("x")
    a = parameters("a")
    T = (1 + x**2 / 4) * x.diff(t) ** 2 / 2 + sp.exp(-x**2) * x.diff(t) ** 2 / 10 + x.diff(t) ** 2 / sp.sqrt(9 + x**2)
    V = (a * x**2 / 2 + sp.log(2 + x**2) + sp.cosh(x / 3) + sp.tan(x / 4) + sp.sqrt(1 + x**2)
         + (3 + x**2) ** sp.Rational(5, 2) / 50 + sp.sinh(x / 5) * sp.tanh(x / 2) + 1 / (2 + sp.cos(x)) + 2**x / 7
         + (1 + x**2) ** sp.Rational(3, 2) / 40 + 1 / sp.sqrt(5 + x**2) + (4 + x**2) ** sp.Rational(-3, 2))
    return System([x], T=T, V=V, forces={x: -sp.sin(t) * x.diff(t) / 10})


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
@pytest.mark.parametrize("backend", ["python", "numba"])
def test_every_operation_against_tight_dop853(backend):
    s = _all_operations_system()
    ic, p = {"x": 0.7, "x_dot": -0.4}, {"a": 3.0}
    tt = np.linspace(0, 8, 17)
    ref = s.simulate((0, 8), ic, p, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=tt)
    sol = s.simulate((0, 8), ic, p, method="taylor", rtol=1e-13, atol=1e-13, t_eval=tt, backend=backend)
    assert np.max(np.abs(sol.y - ref.y)) < 1e-10
    assert np.max(np.abs(sol.work - ref.work)) < 1e-10  # the forced, non-conservative system's work integral


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_c_interpreter_and_compiled_series_both_match_the_closed_form():
    """The two engines kept (C interpreter, compiled series) each against Kepler's equation at tight tolerance:
    backward over 2 revolutions, the labels saying which engine ran."""
    T = -4 * math.pi
    tt = np.linspace(0, T, 9)
    runs = [kepler_system().simulate((0, T), KEPLER_IC, {"m": 1.0, "mu": 1.0}, method="taylor", rtol=1e-13,
                                     atol=1e-13, t_eval=tt, backend=b) for b in ("python", "numba")]
    for run in runs:
        assert np.max(np.abs(run.y - kepler_state(tt))) < 2e-10
    assert "compiled series" in runs[1].method


def _forms(system, params, order):
    """Both compiled forms of ``system``'s series (loop form, written out for ``order``)."""
    from lagrange.codegen.taylor_source import UNROLL_TERMS, unrolled_terms

    model = system.compile(params, backend="numba")
    tape = model.taylor_tape()
    assert unrolled_terms(tape, order) <= UNROLL_TERMS  # the numba backend runs the written-out form
    return model, tape, model.taylor_series(), model.taylor_series(order)


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
@pytest.mark.parametrize("case", ["every_operation", "double_pendulum", "kepler"])
def test_series_forms_give_the_taylor_polynomial_of_the_true_solution(case):
    """Both forms of the compiled series (loops; written out for one order) give Taylor coefficients whose
    polynomial, evaluated a short time ahead, is the solution (DOP853 at rtol 1e-13), and order 1 is the
    reference rhs: independent truth for the recurrences, not the engines against each other."""
    from lagrange.integrate.compiled import kernel

    tol = 1e-8
    if case == "every_operation":  # a long tape: written out at a lower order only
        s, p, y0, tol = _all_operations_system(), {"a": 3.0}, [0.7, -0.4], 1e-5
    elif case == "double_pendulum":
        s, p, y0 = n_link_pendulum(2), {"g": 9.81}, [0.6, -0.3, 0.0, 0.5]
    else:
        s, p, y0 = kepler_system(), {"m": 1.0, "mu": 1.0}, list(KEPLER_IC.values())
    order = taylor_order(tol)
    model, tape, loop_form, written = _forms(s, p, order)
    assert loop_form is not written
    k = kernel("_taylor_loop.py", "taylorloop", "method='taylor'")
    t0, h = 0.3, 0.02
    names = [c.func.__name__ for c in s.derived.coordinates]
    ic = dict(zip(names + [nm + "_dot" for nm in names], y0))
    ref = s.simulate((t0, t0 + h), ic, p, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=[t0 + h])
    reference_rhs = s.compile(p, backend="reference").rhs(t0, np.asarray(y0, float), s.compile(p).params)
    z = np.zeros(tape.nz)
    z[: len(y0)] = y0
    coefficients = []
    for series in (loop_form, written):
        S, acc, L, d, Mk, r = k._constants(tape.const_code, tape.const_vals, tape.n_slots, tape.n, order,
                                           np.asarray(model.params, dtype=float))
        S[: tape.nz, 0] = z
        assert series(t0, S, acc, L, d, Mk, r, order)
        C = S[: 2 * tape.n].copy()
        coefficients.append(C)
        np.testing.assert_allclose(C[:, 1], reference_rhs, rtol=1e-13, atol=1e-13)
        poly = sum(C[:, j] * h**j for j in range(order + 1))
        assert np.max(np.abs(poly - ref.y[-1])) < 1e-11
    np.testing.assert_allclose(coefficients[0], coefficients[1], rtol=1e-13, atol=1e-300)


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_written_out_series_refuses_another_order():
    s = n_link_pendulum(2)
    model, tape, _, written = _forms(s, {"g": 9.81}, 9)
    from lagrange.integrate.compiled import kernel

    k = kernel("_taylor_loop.py", "taylorloop", "method='taylor'")
    S, acc, L, d, Mk, r = k._constants(tape.const_code, tape.const_vals, tape.n_slots, tape.n, 12,
                                       np.asarray(model.params, dtype=float))
    assert not written(0.0, S, acc, L, d, Mk, r, 12)


def test_damped_oscillator_closed_form_and_dissipated_work():
    """P = −b ẋ²/2 (Wells): x = e^{−γt}(cos ωd t + γ/ωd sin ωd t); work = E(t) − E(0) ≤ 0."""
    b_ = parameters("b")
    x_ = coordinates("x")
    s, x = _oscillator(P=-b_ * x_.diff(t) ** 2 / 2)
    m, k, b = 1.0, 4.0, 0.4
    g, wd = b / (2 * m), math.sqrt(k / m - (b / (2 * m)) ** 2)
    tt = np.linspace(0, 10, 21)
    sol = s.simulate((0, 10), {"x": 1.0, "x_dot": 0.0}, {"m": m, "k": k, "b": b}, method="taylor", rtol=1e-12,
                     atol=1e-12, t_eval=tt)
    exact = np.exp(-g * tt) * (np.cos(wd * tt) + g / wd * np.sin(wd * tt))
    assert np.max(np.abs(sol.y[:, 0] - exact)) < 1e-10
    energy = 0.5 * m * sol.y[:, 1] ** 2 + 0.5 * k * sol.y[:, 0] ** 2
    assert np.max(np.abs(sol.work - (energy - energy[0]))) < 1e-10 and sol.work[-1] < -1.0


def test_backward_run_returns_to_the_start():
    s = n_link_pendulum(2)
    ic = {"q1": 0.6, "q2": -0.3, "q1_dot": 0.0, "q2_dot": 0.0}
    fwd = s.simulate((0, 3), ic, {"g": 9.81}, method="taylor", rtol=1e-13, atol=1e-13, t_eval=[3.0])
    end = dict(zip(("q1", "q2", "q1_dot", "q2_dot"), fwd.y[-1]))
    back = s.simulate((3, 0), end, {"g": 9.81}, method="taylor", rtol=1e-13, atol=1e-13, t_eval=[0.0])
    assert np.max(np.abs(back.y[-1] - [0.6, -0.3, 0.0, 0.0])) < 1e-10


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_energy_bounded_over_many_periods():
    """Kepler, 200 revolutions at rtol 1e-14: relative energy error stays at the round-off level."""
    T = 400 * math.pi
    sol = kepler_system().simulate((0, T), KEPLER_IC, {"m": 1.0, "mu": 1.0}, method="taylor", rtol=1e-15,
                                   atol=1e-15, n_points=201, backend="numba")
    E = 0.5 * (sol.y[:, 2] ** 2 + sol.y[:, 3] ** 2) - 1 / np.hypot(sol.y[:, 0], sol.y[:, 1])
    assert np.max(np.abs(E / E[0] - 1)) < 1e-12


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_auto_picks_taylor_at_tight_tolerance_or_when_the_c_interpreter_runs_a_python_model(monkeypatch):
    """numba models: Taylor only at rtol ≤ 1e-11 (their compiled DOP853 loop is as fast at loose tolerance);
    python models: Taylor at any tolerance when the C interpreter is here (scipy's loop steps in Python), but
    not with events, and not without C (the compiled series JIT-compiles per model)."""
    from lagrange.integrate.taylor import available_interpreter

    s = n_link_pendulum(2)
    ic = {"q1": 0.6, "q2": -0.3, "q1_dot": 0.0, "q2_dot": 0.0}
    tight = s.simulate(1, ic, {"g": 9.81}, method="auto", rtol=1e-12, atol=1e-12, n_points=3, backend="numba")
    assert tight.method.startswith("taylor") and "auto: smooth" in tight.method
    default = s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3, backend="numba")
    assert default.method.startswith("DOP853")
    python = s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3)
    ref = s.simulate(1, ic, {"g": 9.81}, rtol=1e-12, atol=1e-12, n_points=3)
    assert np.max(np.abs(python.y - ref.y)) < 1e-7
    if available_interpreter() == "c":
        assert python.method.startswith("taylor (interpreted tape, c; auto: smooth")

        def event(t_, y):
            return y[0]

        with_events = s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3, events=[event])
        assert with_events.method.startswith("DOP853")
    monkeypatch.setenv("LAGRANGE_C_TAYLOR", "0")
    assert s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3).method.startswith("DOP853")


def test_non_analytic_equations_are_refused_by_name():
    x = coordinates("x")
    m, mu = parameters("m mu")
    s = System([x], T=m * x.diff(t) ** 2 / 2, forces={x: -mu * sp.sign(x.diff(t)) - sp.Abs(x)})
    with pytest.raises(TypeError, match="sign|Abs"):
        s.simulate(1, {"x": 1, "x_dot": 1}, {"m": 1, "mu": 0.1}, method="taylor", friction="regularize")
    with pytest.raises(TapeError, match=r"cannot expand Abs\(x\) in the generalized force of x"):
        build_tape(System([x], T=m * x.diff(t) ** 2 / 2, forces={x: -sp.Abs(x)}).derived)


def test_constraints_and_events_are_refused():
    x, y = coordinates("x y")
    s = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=y, constraints=[x**2 + y**2 - 1])
    with pytest.raises(TapeError, match="constraint"):
        s.simulate(1, {"x": 1, "y": 0, "x_dot": 0, "y_dot": 0}, {}, method="taylor")
    osc, _ = _oscillator()

    def ev(t_, y_):
        return y_[0]

    with pytest.raises(TypeError, match="events"):
        osc.simulate(1, {"x": 1, "x_dot": 0}, {"m": 1, "k": 1}, method="taylor", events=[ev])


def test_blow_up_reports_where_with_partial():
    """V = −x⁴/4 sends x to infinity in finite time (t* = ∫dx/√(x⁴/2) from x=1: √2); the run stops there."""
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=-x**4 / 4)
    with pytest.raises(IntegrationError) as info:
        s.simulate((0, 3), {"x": 1.0, "x_dot": math.sqrt(0.5)}, {}, method="taylor", rtol=1e-10, atol=1e-10,
                   n_points=31)
    err = info.value
    assert abs(err.t - math.sqrt(2)) < 1e-3 and "Taylor method stopped" in str(err)
    assert err.partial is not None and len(err.partial.t) == 15 and err.partial.t[-1] == pytest.approx(1.4)


def test_fractional_power_of_a_negative_number_is_a_named_fault_not_a_scipy_typeerror():
    """Found while writing these tests: the python backend's (3 + x)**(5/2) turned complex at x < −3 and
    scipy raised a bare TypeError; now an IntegrationError with the time and the state (any method)."""
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=-(3 + x) ** sp.Rational(5, 2) / 10 + 2 * x)
    for method in ("DOP853", "taylor"):
        with pytest.raises(IntegrationError, match=r"t=.*x="):
            s.simulate(10, {"x": 0.0, "x_dot": -2.0}, {}, method=method)


# --- the two engines kept (C interpreter, compiled series), each against independent truth ------------------

def _c_or_skip():
    from lagrange.integrate.taylor import available_interpreter

    if available_interpreter() != "c":  # optional: no C compiler here (the compiled series runs instead)
        from lagrange.codegen.c_interpreter import library_path_or_reason

        pytest.skip(f"no C interpreter: {library_path_or_reason()[1]}")


def _run(engine, system, params, y0, t_span, t_eval, tol):
    from lagrange.integrate.taylor import integrate_taylor

    model = system.compile(params)  # python backend: the engine decides how the tape runs
    try:
        return integrate_taylor(model, t_span, np.array(y0, dtype=float), t_eval, rtol=tol, atol=tol,
                                engine=engine)
    except IntegrationError as exc:
        return exc


_SLOW_SERIES = pytest.param("series", marks=pytest.mark.slow)  # a JIT compile per model: in the slow set


@pytest.mark.parametrize(("engine", "case"), [
    ("c", "every_operation"), ("c", "kepler_backward"), ("c", "damped"), ("series", "damped"),
    pytest.param("series", "every_operation", marks=pytest.mark.slow),
    pytest.param("series", "kepler_backward", marks=pytest.mark.slow)])
def test_each_engine_against_independent_truth(engine, case):
    """Kepler's equation (backward in time), the damped oscillator's closed form and its dissipated work, and
    every tape operation against DOP853 at rtol 1e-13 — for each engine on its own."""
    if engine == "c":
        _c_or_skip()
    if case == "every_operation":
        s, p, y0 = _all_operations_system(), {"a": 3.0}, [0.7, -0.4]
        span, tt = (0.0, 6.0), np.linspace(0.0, 6.0, 13)
        ref = s.simulate(span, {"x": 0.7, "x_dot": -0.4}, p, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=tt)
        truth, work = ref.y, ref.work
    elif case == "kepler_backward":
        s, p, y0 = kepler_system(), {"m": 1.0, "mu": 1.0}, list(KEPLER_IC.values())
        span, tt = (0.0, -6.0), np.linspace(0.0, -6.0, 13)
        truth, work = kepler_state(tt), None
    else:
        s, _ = _oscillator(rayleigh=parameters("c") * coordinates("x").diff(t) ** 2 / 2)
        p, y0, span, tt = {"m": 1.0, "k": 4.0, "c": 0.4}, [1.0, 0.0], (0.0, 6.0), np.linspace(0.0, 6.0, 13)
        g, wd = 0.2, math.sqrt(4.0 - 0.04)
        x = np.exp(-g * tt) * (np.cos(wd * tt) + g / wd * np.sin(wd * tt))
        v = -np.exp(-g * tt) * (wd + g * g / wd) * np.sin(wd * tt)
        truth = np.column_stack([x, v])
        work = 0.5 * v**2 + 2.0 * x**2 - 2.0  # E(t) − E(0)
    run = _run(engine, s, p, y0, span, tt, 1e-12)
    assert not isinstance(run, Exception), run
    assert np.max(np.abs(run.y - truth)) < 1e-9
    if work is not None:
        assert np.max(np.abs(run.work - work)) < 1e-9


@pytest.mark.parametrize("engine", ["c", _SLOW_SERIES])
def test_each_engine_stops_where_the_closed_form_says(engine):
    """Faults, located by the closed form: V = −x⁴/4 blows up at t = √2; with T = (1 − x)ẋ²/2 and energy 1/2
    the mass 1 − x vanishes at t = 2/3. The partial trajectory ends before it, and each output is exact."""
    if engine == "c":
        _c_or_skip()
    x = coordinates("x")
    blow_up = System([x], T=x.diff(t) ** 2 / 2, V=-x**4 / 4)
    vanishing = System([x], T=(1 - x) * x.diff(t) ** 2 / 2)
    tt = np.linspace(0.0, 3.0, 301)
    for s, y0, t_star in ((blow_up, [1.0, math.sqrt(0.5)], math.sqrt(2)), (vanishing, [0.0, 1.0], 2 / 3)):
        err = _run(engine, s, {}, y0, (0.0, 3.0), tt, 1e-10)
        assert isinstance(err, IntegrationError) and "Taylor method stopped" in str(err)
        assert abs(err.t - t_star) < 2e-3 and err.partial.t[-1] <= err.t
    err = _run(engine, vanishing, {}, [0.0, 1.0], (0.0, 3.0), tt, 1e-10)
    part = err.partial
    exact_x = 1 - (1 - 1.5 * part.t) ** (2 / 3)  # (1 − x)^{3/2} = 1 − 3t/2
    assert np.max(np.abs(part.y[:-5, 0] - exact_x[:-5])) < 1e-7


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_chunked_runs_equal_one_uninterrupted_run(monkeypatch):
    """Interrupt points cost nothing: chunks of 1 step (resuming from the exact state) give the same result
    as chunks of up to 10⁷ steps, for each engine."""
    from lagrange.integrate import taylor as tay

    s, p, y0 = n_link_pendulum(2), {"g": 9.81}, [0.6, -0.3, 0.0, 0.5]
    tt = np.linspace(0.0, 2.0, 7)
    for engine in ("c", "series"):
        if engine == "c" and tay.available_interpreter() != "c":
            continue
        monkeypatch.setattr(tay, "CHUNK_SECONDS", 1e-12)  # every chunk one step
        small = _run(engine, s, p, y0, (0.0, 2.0), tt, 1e-11)
        monkeypatch.setattr(tay, "CHUNK_SECONDS", 100.0)
        big = _run(engine, s, p, y0, (0.0, 2.0), tt, 1e-11)
        np.testing.assert_array_equal(small.y, big.y)
        assert small.nfev == big.nfev
    with pytest.raises(IntegrationError, match="maximum number of steps"):
        tay.integrate_taylor(s.compile(p), (0.0, 2.0), np.array(y0), tt, rtol=1e-11, atol=1e-11, max_steps=5)


def test_without_a_c_interpreter_the_compiled_series_runs(monkeypatch):
    """No compiler (or a failing one, or LAGRANGE_C_TAYLOR=0): the reason is named and the compiled series
    (numba) runs python models, still matching the closed form."""
    from lagrange.codegen import c_interpreter
    from lagrange.integrate.taylor import interpreter

    s, _ = _oscillator()
    run = dict(t_span=(0, 1), initial={"x": 1.0, "x_dot": 0.0}, params={"m": 1.0, "k": 1.0}, method="taylor",
               n_points=3)
    monkeypatch.setattr(c_interpreter, "extension_path", lambda: None)  # as in a source checkout
    for cc, reason in (("no-such-compiler-xyz", "no C compiler found"), ("false", "the C compiler failed")):
        monkeypatch.setenv("CC", cc)  # another compiler is another library key: nothing cached for it
        c_interpreter.forget()
        assert reason in c_interpreter.library_path_or_reason()[1]
        assert interpreter() == "series"
        with pytest.raises(Exception, match=reason):
            interpreter("c")
        sol = s.simulate(**run)
        assert sol.y[-1, 0] == pytest.approx(math.cos(1.0), abs=1e-8)
    c_interpreter.forget()
    monkeypatch.setenv("LAGRANGE_C_TAYLOR", "0")
    assert "LAGRANGE_C_TAYLOR=0" in c_interpreter.library_path_or_reason()[1]
    with pytest.raises(ValueError, match="retired"):
        interpreter("numba")
    monkeypatch.undo()
    c_interpreter.forget()


def test_an_interrupt_between_chunks_carries_the_exact_partial_trajectory(monkeypatch):
    """KeyboardInterrupt raised between chunks (where Ctrl-C's handler runs) reaches the caller with
    ``partial``: the outputs computed so far, each on Kepler's closed form; raised before anything was
    integrated (while an engine loads), an empty partial."""
    from lagrange.integrate import taylor as tay

    model = kepler_system().compile({"m": 1.0, "mu": 1.0})
    tt = np.linspace(0, 60.0, 121)
    calls = {"n": 0}
    record = tay._Chunks.record

    def interrupted_after_three(self, steps, seconds):
        record(self, steps, seconds)
        calls["n"] += 1
        if calls["n"] == 3:
            raise KeyboardInterrupt

    monkeypatch.setattr(tay, "CHUNK_SECONDS", 1e-12)  # one step per chunk
    monkeypatch.setattr(tay._Chunks, "record", interrupted_after_three)
    with pytest.raises(KeyboardInterrupt) as info:
        tay.integrate_taylor(model, (0, 60.0), kepler_state([0.0])[0], tt, rtol=1e-12, atol=1e-12)
    part = info.value.partial
    assert not part.success and "Ctrl-C" in part.message and 1 <= len(part.t) < len(tt)
    assert np.max(np.abs(part.y - kepler_state(part.t))) < 1e-9
    monkeypatch.setattr(tay, "_run", lambda *a: (_ for _ in ()).throw(KeyboardInterrupt()))
    with pytest.raises(KeyboardInterrupt) as info:
        tay.integrate_taylor(model, (0, 60.0), kepler_state([0.0])[0], tt, rtol=1e-12, atol=1e-12)
    assert len(info.value.partial.t) == 0


def test_a_ctrl_c_wrapped_by_numba_comes_back_as_keyboard_interrupt():
    """numba boxes a compiled call's results in Python code; Ctrl-C handled there surfaces as SystemError
    caused by KeyboardInterrupt (seen in the SIGINT test of the compiled series): unwrapped, other
    SystemErrors left alone."""
    from lagrange.integrate.taylor import _reraise_interrupt

    wrapped = SystemError("returned a result with an exception set")
    wrapped.__cause__ = SystemError("inner")
    wrapped.__cause__.__cause__ = KeyboardInterrupt()
    with pytest.raises(KeyboardInterrupt):
        _reraise_interrupt(wrapped)
    assert _reraise_interrupt(SystemError("unrelated")) is None
