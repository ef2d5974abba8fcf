"""The compiled DOP853/RK45 loop: agreement with scipy and closed forms, work integral, outputs, failures,
fallbacks and the on-disk cache."""

import dataclasses
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

pytest.importorskip("numba")

from lagrange import BackendError, IntegrationError, System, coordinates, parameters, t  # noqa: E402
from lagrange.codegen.numeric import bind_parameters  # noqa: E402
from lagrange.examples import n_link_pendulum  # noqa: E402
from lagrange.integrate.compiled import LoopStatus, integrate_compiled, run_loop, unsupported  # noqa: E402


@pytest.fixture(scope="module")
def oscillator():
    """x'' = −ω² x, ω = 2: x = cos 2t + 0.5 sin 2t from x(0) = 1, ẋ(0) = 1."""
    x = coordinates("x")
    m, k = parameters("m k")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    p = {"m": 1.0, "k": 4.0}
    return s, s.compile(p, backend="numba"), p, {x: 1.0, x.diff(t): 1.0}


@pytest.fixture(scope="module")
def double_pendulum():
    s = n_link_pendulum(2)
    q1, q2 = s.coordinates
    ic = {q1: 1.2, q2: -0.7, q1.diff(t): 0.0, q2.diff(t): 0.5}
    return s, s.compile({"g": 9.81}, backend="numba"), ic


def _exact(tt):
    return np.cos(2 * tt) + 0.5 * np.sin(2 * tt), -2 * np.sin(2 * tt) + np.cos(2 * tt)


@pytest.mark.parametrize("method", ["DOP853", "RK45"])
def test_closed_form_and_scipy_agree(oscillator, method):
    s, model, p, ic = oscillator
    kw = dict(method=method, rtol=1e-10, atol=1e-12, model=model)
    comp = s.simulate(10, ic, p, loop="compiled", **kw)
    ref = s.simulate(10, ic, p, loop="scipy", **kw)
    assert comp.method == f"{method} (compiled loop)" and ref.method == f"{method} (scipy loop)"
    x, v = _exact(comp.t)
    err = max(np.max(np.abs(comp.y[:, 0] - x)), np.max(np.abs(comp.y[:, 1] - v)))
    assert err < (1e-8 if method == "DOP853" else 1e-7)
    assert np.max(np.abs(comp.y - ref.y)) < 1e-11  # the same algorithm: round-off-level differences only
    bare = solve_ivp(model.fun, (0, 10), [1.0, 1.0], method=method, rtol=1e-10, atol=1e-12, t_eval=comp.t)
    assert abs(comp.nfev - bare.nfev) <= 0.02 * bare.nfev  # same steps as scipy's own solver


@pytest.mark.parametrize("tol", [1e-6, 1e-9])
def test_double_pendulum_error_matches_scipy_at_equal_tolerance(double_pendulum, tol):
    s, model, ic = double_pendulum
    ref = s.simulate(3, ic, {"g": 9.81}, rtol=1e-13, atol=1e-13, t_eval=[3.0], model=model, loop="scipy").y[-1]
    comp = s.simulate(3, ic, {"g": 9.81}, rtol=tol, atol=tol, model=model, loop="compiled")
    scip = s.simulate(3, ic, {"g": 9.81}, rtol=tol, atol=tol, model=model, loop="scipy")
    e_comp = np.max(np.abs(comp.y[-1] - ref))
    e_scip = np.max(np.abs(scip.y[-1] - ref))
    assert e_comp < 1e3 * tol
    assert e_comp == pytest.approx(e_scip, rel=0.1, abs=10 * tol * 1e-3)
    bare = solve_ivp(model.fun, (0, 3), comp.initial[1], method="DOP853", rtol=tol, atol=tol, t_eval=comp.t)
    assert abs(comp.nfev - bare.nfev) <= 0.02 * bare.nfev
    assert comp.energy_error() < 1e3 * tol


def test_outputs_at_t_eval_are_as_accurate_as_steps(oscillator):
    """Irregular output times, including t0 and t1, come from the dense output (steps not clipped)."""
    s, model, p, ic = oscillator
    te = np.sort(np.concatenate([[0.0, 10.0], np.random.default_rng(1).uniform(0, 10, 37)]))
    sol = s.simulate(10, ic, p, t_eval=te, rtol=1e-10, atol=1e-12, model=model, loop="compiled")
    assert np.array_equal(sol.t, te)
    assert sol.y[0] == pytest.approx([1.0, 1.0], abs=1e-15)
    x, v = _exact(te)
    assert np.max(np.abs(sol.y[:, 0] - x)) < 1e-8 and np.max(np.abs(sol.y[:, 1] - v)) < 1e-8
    coarse = s.simulate(10, ic, p, t_eval=[10.0], rtol=1e-10, atol=1e-12, model=model, loop="compiled")
    assert coarse.nfev < sol.nfev  # no extra steps for outputs: only the 3 dense-output stages per output step
    assert coarse.y[-1] == pytest.approx(sol.y[-1], abs=1e-13)


def test_backward_in_time(oscillator):
    s, model, p, ic = oscillator
    sol = s.simulate((0.0, -3.0), ic, p, rtol=1e-10, atol=1e-12, model=model, loop="compiled")
    x, v = _exact(sol.t)
    assert sol.t[-1] == -3.0 and np.max(np.abs(sol.y[:, 0] - x)) < 1e-8


def test_work_integral_of_a_damped_driven_oscillator():
    """Non-conservative: the compiled loop carries ∫ dh/dt dt; the power balance closes and matches scipy."""
    x = coordinates("x")
    m, k, b, F = parameters("m k b F")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-b * x.diff(t) ** 2 / 2,
               forces={x: F * sp.cos(t)})
    p = {"m": 1.0, "k": 4.0, "b": 0.3, "F": 0.7}
    model = s.compile(p, backend="numba")
    ic = {x: 1.0, x.diff(t): 0.0}
    kw = dict(method="RK45", rtol=1e-10, atol=1e-12, model=model)  # the work state does not depend on the method
    comp = s.simulate(8, ic, p, loop="compiled", **kw)
    scip = s.simulate(8, ic, p, loop="scipy", **kw)
    assert comp.work is not None and abs(comp.work[-1]) > 0.1
    assert np.max(np.abs(comp.power_balance())) < 1e-8
    assert np.max(np.abs(comp.work - scip.work)) < 1e-10


@pytest.fixture(scope="module")
def blowup():
    """ẍ = x³ with zero energy (ẋ = x²/√2): x = 1/(1 − t/√2) blows up at t* = √2."""
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=-(x**4) / 4)
    return s, s.compile({}, backend="numba"), {x: 1.0, x.diff(t): 1 / np.sqrt(2)}


def test_blow_up_raises_with_partial_results(blowup):
    s, model, ic = blowup
    with pytest.raises(IntegrationError, match="stopped at t=1.41") as exc:
        s.simulate(3, ic, {}, method="RK45", rtol=1e-10, atol=1e-12, model=model, loop="compiled")
    err = exc.value
    assert err.t == pytest.approx(np.sqrt(2), abs=1e-3)
    part = err.partial
    assert part is not None and not part.success and part.t[-1] < np.sqrt(2) and len(part.t) > 400
    assert np.allclose(part.y[:, 0], 1 / (1 - part.t / np.sqrt(2)), rtol=1e-6)
    assert err.state[s.coordinates[0]] > 1e3


def test_max_steps_status(blowup):
    s, model, ic = blowup
    with pytest.raises(IntegrationError, match="maximum number of steps") as exc:
        integrate_compiled(model, "RK45", (0.0, 1.0), [1.0, 1 / np.sqrt(2)], np.linspace(0, 1, 11),
                           rtol=1e-10, atol=1e-12, max_steps=5)
    assert exc.value.t < 1.0 and exc.value.partial.t[-1] <= exc.value.t


def test_division_by_zero_status(oscillator):
    """m = 0 makes the mass matrix singular: the loop reports it instead of crashing."""
    model = oscillator[1]
    model = dataclasses.replace(model, params=bind_parameters(model.equations, {"m": 0.0, "k": 4.0}))
    res = run_loop(model, "DOP853", (0.0, 1.0), [1.0, 0.0], [0.0, 1.0], rtol=1e-8, atol=1e-8)
    assert res.status is LoopStatus.DIVISION_BY_ZERO and res.t_reached == 0.0 and len(res.t) == 0


def test_fallbacks_and_their_reasons(double_pendulum, oscillator):
    s, model, ic = double_pendulum
    p = {"g": 9.81}

    def ev(t_, y):
        return y[0]

    sol = s.simulate(0.2, ic, p, model=model, events=[ev])
    assert sol.method == "DOP853 (scipy loop: events not supported by the compiled loop)"
    sol = s.simulate(0.2, ic, p, model=model, method="LSODA")
    assert "scipy loop: method 'LSODA'" in sol.method
    assert s.simulate(0.2, ic, p, model=model).method == "DOP853 (compiled loop)"  # auto + numba model
    assert s.simulate(0.2, ic, p).method == "DOP853"  # python backend: scipy, as always
    with pytest.raises(TypeError, match="does not support events"):
        s.simulate(0.2, ic, p, model=model, events=[ev], loop="compiled")
    with pytest.raises(TypeError, match="loop must be one of"):
        s.simulate(0.2, ic, p, model=model, loop="fortran")
    with pytest.raises(BackendError, match="backend='numba'"):
        s.simulate(0.2, ic, p, model=s.compile(p), loop="compiled")


def test_unsupported_features_are_named():
    from lagrange.integrate.switching import switching_functions

    x, y = coordinates("x y")
    m, g, l, mu, N = parameters("m g l mu N")
    rod = System([x, y], T=m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=m * g * y,
                 constraints=[x**2 + y**2 - l**2])
    assert unsupported(rod.derived, "DOP853", events=None, switches=[]) == "constraints"
    assert unsupported(rod.derived, "Radau", events=None, switches=[]).startswith("method 'Radau'")
    block = System([x], T=m * x.diff(t) ** 2 / 2, forces={x: -mu * N * sp.sign(x.diff(t))})
    sw = switching_functions(block.derived)
    assert sw and "friction" in unsupported(block.derived, "DOP853", events=None, switches=sw)
    with pytest.raises(TypeError, match="does not support constraints"):
        rod.simulate(1, {x: 1, y: 0, x.diff(t): 0, y.diff(t): 0}, {"m": 1, "g": 9.81, "l": 1}, loop="compiled")


def test_missing_numba_is_a_clear_error(oscillator, monkeypatch):
    import lagrange.integrate.compiled as compiled

    s, model, p, ic = oscillator
    monkeypatch.setattr(compiled, "_numba_available", lambda: False)
    with pytest.raises(BackendError, match=r"lagrange-dynamics\[fast\]"):
        s.simulate(1, ic, p, loop="compiled")


def test_two_models_share_one_compiled_loop(oscillator, double_pendulum):
    """The loops are generic: different models (sizes 2 and 4, conservative or not) run the one compiled
    signature of each loop, passing their own `field` as a first-class function."""
    from lagrange.integrate.compiled import loops

    s, model, p, ic = oscillator
    s2, model2, ic2 = double_pendulum
    for method in ("DOP853", "RK45"):
        s.simulate(1, ic, p, model=model, method=method, loop="compiled")
        s2.simulate(1, ic2, {"g": 9.81}, model=model2, method=method, loop="compiled")
        assert len(getattr(loops(), method.lower()).signatures) == 1
    fields = {m.dynamics.py_func.__globals__["field"] for m in (model, model2)}
    assert len(fields) == 2 and all(f.nopython_signatures == [loops().FIELD] for f in fields)


def test_loop_and_field_are_written_to_numba_cache(oscillator):
    """After a run, numba's on-disk index of the loops (a staged copy of _rk_loops.py) and of the model's
    eagerly compiled `field` exist, and are sealed into the cache directory's bundles."""
    from lagrange.codegen import numba_backend as nb
    from lagrange.codegen.cache import cache_dir, read_verified
    from lagrange.integrate.compiled import loops

    s, model, p, ic = oscillator
    s.simulate(1, ic, p, model=model, loop="compiled")
    module = Path(loops().__file__)
    assert module.parent != cache_dir() and module.read_text() == (
        Path(__file__).parents[2] / "lagrange" / "integrate" / "_rk_loops.py").read_text()
    nb.harvest(module)
    sealed = [name for name, _ in nb._unpack(read_verified(cache_dir() / f"{module.stem}.numba"), module.stem)]
    for name in ("dop853", "rk45"):
        assert list(Path(getattr(loops(), name).stats.cache_path).glob(f"{module.stem}.{name}-*.nbi"))
        assert any(n.startswith(f"{module.stem}.{name}-") and n.endswith(".nbi") for n in sealed)
    field = model.dynamics.py_func.__globals__["field"]
    rhs_module = Path(field.py_func.__code__.co_filename)
    assert "def dop853" not in rhs_module.read_text()  # the model module holds only the model
    assert list(Path(field.stats.cache_path).glob(f"{rhs_module.stem}.field-*.nbi"))


def test_non_finite_field_is_reported():
    """A division by an exact zero in the model (x = 0 here) gives inf in the compiled field (error_model='numpy',
    as sqrt of a negative number gives nan), which the loop reports as NON_FINITE at the start."""
    x = coordinates("x")
    k = parameters("k")
    s = System([x], T=x.diff(t) ** 2 / 2, V=k / x)
    model = s.compile({"k": 1.0}, backend="numba")
    res = run_loop(model, "RK45", (0.0, 1.0), [0.0, 1.0], [1.0], rtol=1e-8, atol=1e-8)
    assert res.status is LoopStatus.NON_FINITE and res.t_reached == 0.0 and len(res.t) == 0


@pytest.mark.slow
def test_loop_is_cached_on_disk_and_reused_by_a_fresh_process(tmp_path, monkeypatch):
    """A fresh process loads the loops and the model's field from the on-disk cache without compiling."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    model = n_link_pendulum(1).compile({"g": 9.81}, backend="numba")
    here = run_loop(model, "RK45", (0.0, 1.0), [0.5, 0.0], [1.0], rtol=1e-8, atol=1e-8)
    (bundle,) = tmp_path.glob("rkloops_*.numba")  # numba's cache of the loops, sealed (lagrange.codegen.cache)
    from lagrange.codegen.cache import read_verified

    assert read_verified(bundle)
    script = textwrap.dedent("""
        import json
        from lagrange.examples import n_link_pendulum
        from lagrange.integrate.compiled import loops, run_loop
        m = n_link_pendulum(1).compile({"g": 9.81}, backend="numba")
        r = run_loop(m, "RK45", (0.0, 1.0), [0.5, 0.0], [1.0], rtol=1e-8, atol=1e-8)
        stats = [loops().rk45.stats, loops().dop853.stats, m.dynamics.py_func.__globals__["field"].stats]
        print(json.dumps([[sum(s.cache_hits.values()) for s in stats], [sum(s.cache_misses.values()) for s in stats],
                          float(r.z[-1, 0])]))
    """)
    run = subprocess.run([sys.executable, "-c", script], env=dict(os.environ), capture_output=True, text=True,
                         check=True)
    hits, misses, value = json.loads(run.stdout.strip().splitlines()[-1])
    assert min(hits) >= 1 and max(misses) == 0, run.stdout + run.stderr  # loaded from the cache, not compiled
    assert value == float(here.z[-1, 0])


@pytest.mark.parametrize("t_eval, span, message", [
    ([0.5, 1.5], (0.0, 1.0), "not within"),
    ([-0.1], (0.0, 1.0), "not within"),
    ([0.2, float("nan")], (0.0, 1.0), "not within"),  # NaN is in no interval
    ([0.6, 0.4], (0.0, 1.0), "not properly sorted"),
    ([0.4, 0.4], (0.0, 1.0), "not properly sorted"),
    ([0.4, 0.6], (1.0, 0.0), "not properly sorted"),  # backward runs need descending times
    ([[0.5]], (0.0, 1.0), "1-dimensional"),
])
def test_output_times_are_checked_as_scipy_checks_them(t_eval, span, message):
    from lagrange.integrate.compiled import check_output_times

    with pytest.raises(ValueError, match=message):
        check_output_times(t_eval, *span)


def test_valid_output_times_pass_unchanged():
    from lagrange.integrate.compiled import check_output_times

    for t_eval, span in (([], (0, 1)), ([0.0, 0.5, 1.0], (0, 1)), ([1.0, 0.25, 0.0], (1, 0)), ([0.3], (1, 0))):
        out = check_output_times(t_eval, *span)
        assert out.dtype == float and out.flags.c_contiguous and np.array_equal(out, np.asarray(t_eval, float))
