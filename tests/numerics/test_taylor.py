"""method="taylor": the adaptive Taylor integrator (tape interpreter and compiled series).

Independent truth: closed forms (harmonic oscillator, Kepler's equation, the damped oscillator and its
dissipated work), DOP853 at a much tighter tolerance for every operation the tape knows, energy over
long runs, the interpreter against the compiled series (same arithmetic: equal results), and the
backward run returning to the start.
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


@pytest.mark.parametrize("backend", ["python", "numba"])
def test_every_operation_against_tight_dop853(backend):
    s = _all_operations_system()
    ic, p = {"x": 0.7, "x_dot": -0.4}, {"a": 3.0}
    tt = np.linspace(0, 8, 17)
    ref = s.simulate((0, 8), ic, p, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=tt)
    sol = s.simulate((0, 8), ic, p, method="taylor", rtol=1e-13, atol=1e-13, t_eval=tt, backend=backend)
    assert np.max(np.abs(sol.y - ref.y)) < 1e-10
    assert np.max(np.abs(sol.work - ref.work)) < 1e-10  # the forced, non-conservative system's work integral


def test_interpreter_and_compiled_series_agree_exactly():
    """Same arithmetic in the same order: identical states, steps and work."""
    s = n_link_pendulum(3)
    ic = {"q1": 0.6, "q2": -0.3, "q3": 0.2, "q1_dot": 0.0, "q2_dot": 0.5, "q3_dot": 0.0}
    runs = [s.simulate((0, 5), ic, {"g": 9.81}, method="taylor", rtol=1e-11, atol=1e-11, backend=b, n_points=11)
            for b in ("python", "numba")]
    np.testing.assert_array_equal(runs[0].y, runs[1].y)
    assert runs[0].nfev == runs[1].nfev
    assert "interpreted tape" in runs[0].method and "compiled series" in runs[1].method


def _forms(system, params, order):
    """The interpreter and both compiled forms of ``system``'s series (loop form, written out for ``order``)."""
    from lagrange.codegen.taylor_source import UNROLL_TERMS, unrolled_terms
    from lagrange.integrate.taylor import compiled_series, tape_of

    model = system.compile(params, backend="numba")
    tape = tape_of(model.equations)
    assert unrolled_terms(tape, order) <= UNROLL_TERMS  # the numba backend runs the written-out form
    return model, tape, compiled_series(tape), compiled_series(tape, order)


@pytest.mark.parametrize("case", ["every_operation", "double_pendulum", "kepler"])
def test_written_out_series_equals_the_loop_form_and_the_interpreter(case):
    """The series written out for one order (small systems, numba backend) does the interpreter's arithmetic
    in the interpreter's order: equal Taylor coefficients, hence equal states and steps."""
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
    z = np.zeros(tape.nz)
    z[: len(y0)] = y0
    coefficients = []
    for series in (loop_form, written):
        S, acc, L, d, Mk, r = k._constants(tape.const_code, tape.const_vals, tape.n_slots, tape.n, order,
                                           np.asarray(model.params, dtype=float))
        S[: tape.nz, 0] = z
        assert series(0.3, S, acc, L, d, Mk, r, order)
        coefficients.append(S[: tape.nz].copy())
    S, acc, L, d, Mk, r = k._constants(tape.const_code, tape.const_vals, tape.n_slots, tape.n, order,
                                       np.asarray(model.params, dtype=float))
    S[: tape.nz, 0] = z
    slot_w = 2 * tape.n if tape.nz > 2 * tape.n else -1
    assert k._series(tape.code, tape.consts, tape.n, tape.slot_t, slot_w, tape.mass, tape.force, tape.power, order,
                     0.3, S, acc, L, d, Mk, r)
    np.testing.assert_array_equal(coefficients[0], S[: tape.nz])
    np.testing.assert_array_equal(coefficients[1], S[: tape.nz])
    assert np.all(np.isfinite(S[: tape.nz])) and np.any(S[: tape.nz, order] != 0)
    names = [c.func.__name__ for c in s.derived.coordinates]
    ic = dict(zip(names + [nm + "_dot" for nm in names], y0))
    runs = [s.simulate((0, 4), ic, p, method="taylor", rtol=tol, atol=tol, backend=b, n_points=9)
            for b in ("python", "numba")]
    np.testing.assert_array_equal(runs[0].y, runs[1].y)
    assert runs[0].nfev == runs[1].nfev


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


def test_energy_bounded_over_many_periods():
    """Kepler, 200 revolutions at rtol 1e-14: relative energy error stays at the round-off level."""
    T = 400 * math.pi
    sol = kepler_system().simulate((0, T), KEPLER_IC, {"m": 1.0, "mu": 1.0}, method="taylor", rtol=1e-15,
                                   atol=1e-15, n_points=201, backend="numba")
    E = 0.5 * (sol.y[:, 2] ** 2 + sol.y[:, 3] ** 2) - 1 / np.hypot(sol.y[:, 0], sol.y[:, 1])
    assert np.max(np.abs(E / E[0] - 1)) < 1e-12


def test_auto_picks_taylor_at_tight_tolerance_or_when_the_c_interpreter_runs_a_python_model(monkeypatch):
    """numba models: Taylor only at rtol ≤ 1e-11 (their compiled DOP853 loop is as fast at loose tolerance);
    python models: Taylor at any tolerance when the C interpreter is here (scipy's loop steps in Python), but
    not with events, and not on the numba interpreter (its first call costs 0.2 s)."""
    from lagrange.integrate import c_taylor

    s = n_link_pendulum(2)
    ic = {"q1": 0.6, "q2": -0.3, "q1_dot": 0.0, "q2_dot": 0.0}
    tight = s.simulate(1, ic, {"g": 9.81}, method="auto", rtol=1e-12, atol=1e-12, n_points=3, backend="numba")
    assert tight.method.startswith("taylor") and "auto: no dissipation" in tight.method
    default = s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3, backend="numba")
    assert default.method.startswith("DOP853")
    python = s.simulate(1, ic, {"g": 9.81}, method="auto", n_points=3)
    ref = s.simulate(1, ic, {"g": 9.81}, rtol=1e-12, atol=1e-12, n_points=3)
    assert np.max(np.abs(python.y - ref.y)) < 1e-7
    if c_taylor.library() is not None:
        assert python.method.startswith("taylor (interpreted tape, c; auto: no dissipation, non-stiff, python")

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


# --- the interpreter built in C (lagrange.integrate.c_taylor) against the numba build -------------------------

def _c_or_skip():
    from lagrange.integrate import c_taylor

    if c_taylor.library() is None:  # optional: no C compiler here (the numba interpreter runs instead)
        pytest.skip(f"no C interpreter: {c_taylor.unavailable_reason()}")


def _both_engines(system, params, y0, t_span, t_eval, tol):
    from lagrange.integrate.taylor import integrate_taylor

    model = system.compile(params)  # python backend: the tape is interpreted
    out = []
    for engine in ("c", "numba"):
        try:
            out.append(integrate_taylor(model, t_span, np.array(y0, dtype=float), t_eval, rtol=tol, atol=tol,
                                        engine=engine))
        except IntegrationError as exc:
            out.append(exc)
    return out


@pytest.mark.parametrize("case", ["every_operation", "double_pendulum", "kepler_backward", "damped"])
def test_c_interpreter_equals_the_numba_interpreter_bit_for_bit(case):
    """A transcription kept honest: the same states, work integral and tape passes to the last bit (both
    builds do the same operations in the same order, without fused multiply-adds, with the same libm)."""
    _c_or_skip()
    span, tt, tol = (0.0, 6.0), np.linspace(0.0, 6.0, 13), 1e-12
    if case == "every_operation":
        s, p, y0 = _all_operations_system(), {"a": 3.0}, [0.7, -0.4]
    elif case == "double_pendulum":
        s, p, y0 = n_link_pendulum(2), {"g": 9.81}, [0.6, -0.3, 0.0, 0.5]
    elif case == "kepler_backward":
        s, p, y0 = kepler_system(), {"m": 1.0, "mu": 1.0}, list(KEPLER_IC.values())
        span, tt, tol = (0.0, -6.0), np.linspace(0.0, -6.0, 13), 1e-9
    else:
        s, x = _oscillator(rayleigh=parameters("c") * coordinates("x").diff(t) ** 2 / 2)
        p, y0 = {"m": 1.0, "k": 4.0, "c": 0.3}, [1.0, 0.0]
    c_run, numba_run = _both_engines(s, p, y0, span, tt, tol)
    np.testing.assert_array_equal(c_run.y, numba_run.y)
    np.testing.assert_array_equal(c_run.t, numba_run.t)
    assert c_run.nfev == numba_run.nfev and c_run.message == numba_run.message
    if case in ("every_operation", "damped"):
        assert c_run.work is not None
        np.testing.assert_array_equal(c_run.work, numba_run.work)


def test_c_interpreter_stops_like_the_numba_interpreter():
    """Faults: a finite-time blow-up and a mass matrix that vanishes — the same status, time, state and
    partial trajectory from both builds."""
    _c_or_skip()
    x = coordinates("x")
    blow_up = System([x], T=x.diff(t) ** 2 / 2, V=-x**4 / 4)
    vanishing = System([x], T=(1 - x) * x.diff(t) ** 2 / 2)  # M = 1 − x reaches 0 at x = 1
    for s, y0 in ((blow_up, [1.0, math.sqrt(0.5)]), (vanishing, [0.0, 1.0])):
        c_err, numba_err = _both_engines(s, {}, y0, (0.0, 3.0), np.linspace(0.0, 3.0, 31), 1e-10)
        assert isinstance(c_err, IntegrationError) and isinstance(numba_err, IntegrationError)
        assert str(c_err) == str(numba_err) and c_err.t == numba_err.t
        np.testing.assert_array_equal(c_err.partial.y, numba_err.partial.y)


def test_simulate_says_which_interpreter_ran_and_falls_back_without_a_compiler(monkeypatch):
    import os

    from lagrange.integrate import c_taylor

    s, _ = _oscillator()
    run = dict(t_span=(0, 1), initial={"x": 1.0, "x_dot": 0.0}, params={"m": 1.0, "k": 1.0}, method="taylor",
               n_points=3)
    if c_taylor.library() is not None:
        assert "interpreted tape, c" in s.simulate(**run).method
    key = os.environ.get("LAGRANGE_CACHE_DIR")
    for cc, reason in (("no-such-compiler-xyz", "no C compiler found"), ("false", "the C compiler failed")):
        monkeypatch.setenv("CC", cc)  # another compiler is another library key: nothing cached for it
        monkeypatch.delitem(c_taylor._LOADED, key, raising=False)  # restored after the test
        assert c_taylor.library() is None and reason in c_taylor.unavailable_reason()
        sol = s.simulate(**run)
        assert "interpreted tape, numba" in sol.method
        assert sol.y[-1, 0] == pytest.approx(math.cos(1.0), abs=1e-8)
    monkeypatch.setenv("LAGRANGE_C_TAYLOR", "0")
    assert c_taylor.library() is None and "LAGRANGE_C_TAYLOR=0" in c_taylor.unavailable_reason()


def test_a_damaged_c_library_is_rebuilt(monkeypatch, tmp_path):
    """A library file that does not load (truncated by a crash, say) is deleted and built again, once."""
    import os

    from lagrange.integrate import c_taylor

    _c_or_skip()
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))  # a cache of its own (the numba kernels stay put)
    monkeypatch.delitem(c_taylor._LOADED, str(tmp_path), raising=False)
    path = c_taylor.library_path(c_taylor.compiler())
    path.write_bytes(b"not a shared library")  # damaged before this process maps it
    rebuilt = c_taylor.library()
    assert rebuilt is not None and rebuilt.path == path and path.read_bytes()[:4] == b"\x7fELF"
    assert c_taylor.unavailable_reason() is None
    c_taylor._LOADED.pop(str(tmp_path))
    assert sorted(os.listdir(tmp_path)) == [path.name]  # no temporary files left
