"""method="auto" never picks a Taylor-series method for equations that are not analytic, or nearly not; an explicit
method="taylor"/"heyoka" on them warns (lagrange.codegen.analyticity)."""

import dataclasses
import time
import warnings

import numpy as np
import pytest
import sympy as sp

from lagrange import NonAnalyticWarning, Particle, System, coordinates, parameters, t
from lagrange.codegen.analyticity import NEAR, obstacle
from lagrange.examples import n_link_pendulum
from lagrange.integrate.heyoka_run import heyoka_available
from lagrange.integrate.run import choose_method

x, y = coordinates("x y")
m, k, eps, mu, l = parameters("m k epsilon mu l")
T1 = m * x.diff(t) ** 2 / 2
T2 = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2


def judged(system, params, y0, horizon=20.0):
    """obstacle() with the run's values, the initial rates and the horizon, as simulate gives them."""
    eqs = system.derived
    model = system.compile(params)
    values = dict(zip(eqs.numeric_parameters, model.params))
    return obstacle(eqs, values, y0, model.fun(0.0, np.asarray(y0, dtype=float)), horizon)


def cone(epsilon, literal=False):
    """V = k sqrt(x² + ε²): a force −k x/sqrt(x² + ε²), ≈ −k sign(x) outside |x| ≲ ε."""
    e2 = sp.Float(epsilon) ** 2 if literal else eps**2
    return System([x], T=T1, V=k * sp.sqrt(x**2 + e2))


def cone_closed_form(t_end, x0=1.0):
    """ε → 0 (V = k|x|, k = m = 1) from rest at x0: x = x0 − t²/2 to the kink, period 4√(2 x0); O(ε) from it."""
    quarter = np.sqrt(2 * x0)
    s = t_end % (4 * quarter)
    if s <= 2 * quarter:
        return x0 - s**2 / 2 if s <= quarter else -x0 + (2 * quarter - s) ** 2 / 2
    return -cone_closed_form(s - 2 * quarter, x0)


@pytest.mark.parametrize("literal", [False, True], ids=["symbol", "number"])
def test_regularized_cone_auto_avoids_taylor_and_is_right(literal):
    """The reported case: ε = 1e-6, x(0) = 1, t = 20 (the Taylor method gave x = −21.9; the truth is −0.980)."""
    s = cone(1e-6, literal)
    params = {"m": 1, "k": 1} | ({} if literal else {"epsilon": 1e-6})
    sol = s.simulate(20, {x: 1.0, x.diff(t): 0.0}, params, method="auto")
    assert not sol.method.startswith("taylor")
    assert "near-singularity" in sol.method and "x**2" in sol.method  # the reason names the expression
    assert sol.y[-1, 0] == pytest.approx(cone_closed_form(20.0), abs=1e-5)


def test_auto_keeps_taylor_for_a_mild_regularization():
    """ε = 0.5 at the motion's scale 1 (ρ = 0.5 ≥ NEAR): analytic with a distant singularity, no exclusion."""
    s = cone(0.5)
    name, why = choose_method(s.derived, {"m": 1, "k": 1, "epsilon": 0.5}, (0, 20), np.array([1.0, 0.0]))
    assert "excluded" not in why
    assert judged(s, {"m": 1, "k": 1, "epsilon": 0.5}, [1.0, 0.0]) is None


def test_stick_slip_block_regularized_auto_right_at_every_tolerance():
    """Block on a spring (ω = 1) with Coulomb friction μg = 0.1, friction="regularize" (ε = 1e-6), from x = 0.3,
    v = 1: turning points alternate about ∓μg, each amplitude 2μg smaller; it sticks at x = 1.1 − √1.16 (the
    Taylor method gave −0.0043 and 0.0180 at rtol 1e-6 and 1e-9). Auto sees the stiff sticking phase at v = 0."""
    s = System([x], T=T1, V=k * x**2 / 2, P=-mu * m * sp.Abs(x.diff(t)))
    exact = 1.1 - np.sqrt(1.16)
    for rtol in (1e-6, 1e-9, 1e-12):
        sol = s.simulate(25, {x: 0.3, x.diff(t): 1.0}, {"m": 1, "k": 1, "mu": 0.1}, friction="regularize",
                         method="auto", rtol=rtol, atol=rtol * 1e-2)
        assert "stiff at the near-singularity" in sol.method and not sol.method.startswith("taylor")
        # the regularized block creeps by ~2e-6 after sticking; beyond that, the run's own accuracy
        assert abs(sol.y[-1, 0] - exact) < 5e-6 + 10 * rtol, (rtol, sol.y[-1, 0])


@pytest.mark.parametrize("name,system,params,y0", [
    ("tanh friction", System([x], T=T1, V=k * x**2 / 2, forces={x: -mu * sp.tanh(x.diff(t) / eps)}),
     {"m": 1, "k": 1, "mu": 0.1, "epsilon": 1e-3}, [0.3, 1.0]),
    ("atan friction", System([x], T=T1, V=k * x**2 / 2, forces={x: -mu * sp.atan(x.diff(t) / eps)}),
     {"m": 1, "k": 1, "mu": 0.1, "epsilon": 1e-3}, [0.3, 1.0]),
    ("x/sqrt(x²+ε²) at rest", System([x], T=T1, V=k * x**2 / 2,
                                     forces={x: -mu * x.diff(t) / sp.sqrt(x.diff(t) ** 2 + eps**2)}),
     {"m": 1, "k": 1, "mu": 0.1, "epsilon": 1e-6}, [1.05, 0.0]),
    ("softened 1/r, tiny ε", System([x, y], T=T2, V=-k / sp.sqrt(x**2 + y**2 + eps**2)),
     {"m": 1, "k": 1, "epsilon": 1e-3}, [1.0, 0.0, 0.0, 1.0]),
    ("(x + y)² + ε² written expanded", System([x, y], T=T2, V=k * sp.sqrt(x**2 + 2 * x * y + y**2 + eps**2)),
     {"m": 1, "k": 1, "epsilon": 1e-6}, [1.0, 0.0, 0.0, 0.0]),
])
def test_near_singularities_are_flagged(name, system, params, y0):
    found = judged(system, params, y0)
    assert found is not None and found.kind == "near", name
    rho = float(found.reason.rsplit(" ", 1)[1])
    assert rho < NEAR


@pytest.mark.parametrize("name,system,params,y0", [
    ("Kepler 1/r", System([x, y], T=T2, V=-k / sp.sqrt(x**2 + y**2)), {"m": 1, "k": 1}, [1.0, 0.0, 0.0, 1.0]),
    ("planar spring of length l", System([x, y], T=T2, V=k * (sp.sqrt(x**2 + y**2) - l) ** 2 / 2),
     {"m": 1, "k": 1, "l": 1}, [1.2, 0.0, 0.0, 0.5]),
    ("sqrt(x² + l²) at its scale", System([x], T=T1, V=k * sp.sqrt(x**2 + l**2)), {"m": 1, "k": 1, "l": 1},
     [1.0, 0.0]),
    ("tanh at its scale", System([x], T=T1, V=k * x**2 / 2, forces={x: -mu * sp.tanh(x.diff(t) / eps)}),
     {"m": 1, "k": 1, "mu": 0.1, "epsilon": 1.0}, [0.3, 1.0]),
    ("softened 1/r, ε comparable to r", System([x, y], T=T2, V=-k / sp.sqrt(x**2 + y**2 + eps**2)),
     {"m": 1, "k": 1, "epsilon": 0.5}, [1.0, 0.0, 0.0, 1.0]),
])
def test_genuine_or_mild_singularities_pass(name, system, params, y0):
    assert judged(system, params, y0) is None, name


def test_kepler_auto_and_explicit_taylor_quiet():
    """The distant singularity of 1/r: auto keeps the Taylor method when it is available, no warning either way."""
    s = System([x, y], bodies=[Particle(m, (x, y))], V=-k * m / sp.sqrt(x**2 + y**2))
    ic = {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 1.2}
    with warnings.catch_warnings():
        warnings.simplefilter("error", NonAnalyticWarning)
        sol = s.simulate(5, ic, {"m": 1, "k": 1}, method="auto")
        s.simulate(1, ic, {"m": 1, "k": 1}, method="taylor")
    assert "excluded" not in sol.method


@pytest.mark.parametrize("force,kind", [
    (sp.Abs(x), "Abs"), (sp.sign(x), "sign"), (sp.Piecewise((x, x > 0), (0, True)), "Piecewise"),
    (sp.Max(x, 0), "Max"), (sp.Min(x, 0), "Min"), (sp.Heaviside(x), "Heaviside"), (sp.floor(x), "floor"),
    (sp.ceiling(x), "ceiling")])
def test_non_smooth_functions_are_named(force, kind):
    eqs = System([x], T=T1, forces={x: -k * force}).derived
    found = obstacle(eqs)
    assert found is not None and found.kind == "function" and kind in found.describe()
    assert "generalized force of x" in found.where


def test_user_function_and_kinks():
    f = sp.Function("f")
    eqs = System([x], T=T1, V=k * x**2 / 2).derived
    with_f = dataclasses.replace(eqs, forcing=sp.ImmutableMatrix([f(eqs.q[0])]))
    assert "user function" in obstacle(with_f).reason
    kinked = System([x, y], T=T2, V=k * sp.sqrt(x**2 + 2 * x * y + y**2)).derived  # |x + y| written expanded
    found = obstacle(kinked)
    assert found.kind == "kink" and "x + y" in found.reason
    assert obstacle(System([x, y], T=T2, V=k * sp.sqrt(x**2 + y**2)).derived) is None  # a cone point only
    unsupported = obstacle(System([x], T=T1, V=k * x**2 / 2, forces={x: -k * sp.asinh(x)}).derived)
    assert unsupported.kind == "function" and "does not expand (asinh)" in unsupported.reason


def test_auto_names_non_smooth_functions_in_the_method_line():
    s = System([x], T=T1, V=k * x**2 / 2, forces={x: -mu * sp.Max(x, 0)})
    sol = s.simulate(2, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "mu": 0.1}, method="auto")
    assert "excluded" in sol.method and "Max(0, x)" in sol.method and not sol.method.startswith("taylor")


def test_explicit_taylor_warns_and_names_the_expression():
    s = cone(1e-6)
    with pytest.warns(NonAnalyticWarning, match=r"sqrt\(epsilon\*\*2 \+ x\*\*2\).*DOP853.*Radau"):
        s.simulate(1, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "epsilon": 1e-6}, method="taylor")
    with warnings.catch_warnings():  # the same system with ε at the motion's scale: quiet
        warnings.simplefilter("error", NonAnalyticWarning)
        s.simulate(1, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "epsilon": 0.5}, method="taylor")


@pytest.mark.skipif(not heyoka_available(), reason="heyoka.py is not installed")
def test_explicit_heyoka_warns():
    with pytest.warns(NonAnalyticWarning, match="method='heyoka'"):
        cone(1e-6).simulate(1, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "epsilon": 1e-6}, method="heyoka")


def test_analysis_is_cheap_on_a_ten_link_chain():
    """One pass over the expression DAGs: milliseconds for the 10-link pendulum (no sites, nothing flagged)."""
    s = n_link_pendulum(10)
    eqs = s.derived
    assert eqs.forcing.shape == (10, 1) and eqs.mass_matrix.shape == (10, 10)  # derived before the clock starts
    values = {p: 1.0 for p in eqs.numeric_parameters}
    y0 = np.r_[np.full(10, 0.3), np.zeros(10)]
    start = time.perf_counter()
    assert obstacle(eqs, values, y0, None, 10.0) is None
    assert time.perf_counter() - start < 1.0


def _taylor_runs() -> bool:
    from lagrange.integrate.taylor import available_interpreter

    return available_interpreter() is not None


@pytest.mark.skipif(not _taylor_runs(), reason="no Taylor interpreter (C compiler or numba) here")
def test_threshold_on_both_sides_with_the_taylor_method():
    """The measurement behind NEAR: friction μ tanh(v/ε) from x = 0.3, v = 1 (ρ = (π/2)ε/|v|scale). At ε = 0.1
    (ρ ≈ 0.16, passes) the Taylor method is within a few tolerances of a tight DOP853 run; at ε = 0.03 (ρ ≈ 0.047,
    flagged) it is off by hundreds of tolerances or more."""
    s = System([x], T=T1, V=k * x**2 / 2, forces={x: -mu * sp.tanh(x.diff(t) / eps)})
    ic = {x: 0.3, x.diff(t): 1.0}
    rtol = 1e-9
    errors = {}
    for e in (0.1, 0.03):
        p = {"m": 1, "k": 1, "mu": 0.1, "epsilon": e}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", NonAnalyticWarning)
            got = s.simulate(20, ic, p, method="taylor", rtol=rtol, atol=rtol * 1e-3).y[-1, 0]
        ref = s.simulate(20, ic, p, method="DOP853", rtol=1e-13, atol=1e-15).y[-1, 0]
        errors[e] = abs(got - ref) / (rtol * 1e-3 + rtol * abs(ref))
        assert (judged(s, p, [0.3, 1.0]) is None) == (e == 0.1)
    assert errors[0.1] < 5 and errors[0.03] > 100, errors


def test_auto_names_time_varying_inputs_as_the_reason():
    """An input schedule's smoothness is unknown: the method line says why the Taylor method is not used."""
    from lagrange import inputs

    F = inputs("F")
    s = System([x], T=T1, V=k * x**2 / 2, forces={x: F})
    sol = s.simulate(1, {x: 0.0, x.diff(t): 0.0}, {"m": 1, "k": 4}, inputs={F: lambda tt: np.sin(tt)},
                     method="auto")
    assert not sol.method.startswith("taylor") and "time-varying inputs" in sol.method
