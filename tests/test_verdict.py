"""The accuracy verdict every simulate run carries (lagrange.results.verdict, lagrange.integrate.checks): each
check on both sides — runs that must pass quietly and runs that must be flagged — against independent truth
(closed forms, a tighter run of another method)."""

import re
import warnings

import numpy as np
import pytest
import sympy as sp

from lagrange import AccuracyWarning, Holonomic, Particle, System, coordinates, parameters, t
from lagrange.cli import main
from lagrange.errors import NonAnalyticWarning, OptionError
from lagrange.integrate.options import StepOptions
from lagrange.results.verdict import RunStatus

m, k, g, l, mu, eps = parameters("m k g l mu eps")


def _quiet(run):
    """The run's result, failing the test on any AccuracyWarning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", AccuracyWarning)
        sol = run()
    assert sol.verdict is not None and sol.verdict.ok and sol.success and sol.status is RunStatus.SUCCESS
    return sol


def _flagged(run, check: str):
    """The run's result, which must warn naming ``check`` and be reported inaccurate with that check failed."""
    with pytest.warns(AccuracyWarning, match=re.escape(check)) as record:
        sol = run()
    accuracy = [w for w in record if issubclass(w.category, AccuracyWarning)]
    assert all("try " in str(w.message) for w in accuracy)
    assert not sol.success and sol.status is RunStatus.INACCURATE and not sol.verdict.ok
    assert check in [c.name for c in sol.verdict.failed]
    return sol


def spring():
    x = coordinates("x")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2), x


def pendulum():
    th = coordinates("theta")
    return System([th], T=m * l**2 * th.diff(t) ** 2 / 2, V=-m * g * l * sp.cos(th)), th


PEND = {"m": 1.0, "g": 9.81, "l": 1.0}


# --- fixed step: Richardson's step-doubling estimate -------------------------------------------------------------
def test_gl4_at_h_omega_10_is_flagged_by_step_doubling_though_energy_is_conserved():
    s, x = spring()
    w = 100.0
    sol = _flagged(lambda: s.simulate(1.0, {x: 1, x.diff(t): 0}, {"m": 1, "k": w**2}, method="gl4", step=0.1),
                   "step-doubling error")
    assert abs(sol[x][-1] - np.cos(w * sol.t[-1])) > 0.03  # the closed form: really wrong
    by_name = {c.name: c for c in sol.verdict.checks}
    assert by_name["energy drift"].passed and by_name["energy drift"].value < 1e-12  # GL conserves it anyway


def test_resolved_gl4_passes_quietly_and_the_estimate_tracks_the_true_error():
    s, x = spring()
    w = 100.0
    sol = _quiet(lambda: s.simulate(1.0, {x: 1, x.diff(t): 0}, {"m": 1, "k": w**2}, method="gl4", step=0.001))
    est = {c.name: c for c in sol.verdict.checks}["step-doubling error"].value
    true = max(np.max(np.abs(sol[x] - np.cos(w * sol.t))), np.max(np.abs(sol[x.diff(t)] / w + np.sin(w * sol.t))))
    assert 0.5 < est / true < 2.0  # Richardson is asymptotically exact (the scales are 1 and w)


def test_a_single_step_is_checked_against_two_half_steps():
    s, x = spring()
    sol = _flagged(lambda: s.simulate(1.0, {x: 1, x.diff(t): 0}, {"m": 1, "k": 100}, method="gl4", step=1.0),
                   "step-doubling error")
    assert abs(sol[x][-1] - np.cos(10.0)) > 0.5


def test_fixed_step_checks_the_rtol_given_and_the_estimate_can_be_skipped():
    s, x = spring()
    ic, p = {x: 1, x.diff(t): 0}, {"m": 1, "k": 1e4}
    _flagged(lambda: s.simulate(1.0, ic, p, method="gl4", step=0.001, rtol=1e-9), "step-doubling error")
    sol = _quiet(lambda: s.simulate(1.0, ic, p, method="gl4", step=StepOptions(0.1, estimate=False)))
    assert [c.name for c in sol.verdict.checks] == ["energy drift"]
    with pytest.raises(OptionError, match="estimate"):
        StepOptions(0.1, estimate="yes")


# --- energy / power balance -------------------------------------------------------------------------------------
def test_loose_rk23_pendulum_is_flagged_by_its_energy_drift():
    s, th = pendulum()
    sol = _flagged(lambda: s.simulate(300, {th: 2.5, th.diff(t): 0}, PEND, method="RK23", rtol=1e-3, atol=1e-6,
                                      n_points=101), "energy drift")
    assert sol.energy_error() > 1e-2
    _quiet(lambda: s.simulate(20, {th: 2.5, th.diff(t): 0}, PEND, method="RK23", rtol=1e-3, atol=1e-6))


@pytest.mark.slow
def test_rk23_pendulum_to_2e4_that_ends_at_rest_is_flagged():
    s, th = pendulum()
    sol = _flagged(lambda: s.simulate(2e4, {th: 2.5, th.diff(t): 0}, PEND, method="RK23", rtol=1e-3),
                   "energy drift")
    assert sol.energy_error() > 0.5


def test_taylor_on_a_nearly_nonanalytic_potential_is_flagged():
    """V = k√(x² + ε²), ε = 1e-6: the Taylor steps reach past the series' radius near x = 0 (x = −21.9 at t =
    20); DOP853 agrees with a tight Radau run and passes quietly."""
    x = coordinates("x")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * sp.sqrt(x**2 + eps**2))
    ic, p = {x: 1, x.diff(t): 0}, {"m": 1, "k": 1, "eps": 1e-6}
    with pytest.warns(NonAnalyticWarning, match="near-singularity"):  # warned before the run, flagged after it
        sol = _flagged(lambda: s.simulate(20, ic, p, method="taylor"), "Taylor local error")
    assert "energy drift" in [c.name for c in sol.verdict.failed]
    good = _quiet(lambda: s.simulate(20, ic, p))
    ref = s.simulate(20, ic, p, method="Radau", rtol=1e-12, atol=1e-14, t_eval=[20.0])
    assert abs(good[x][-1] - ref[x][-1]) < 1e-5 and abs(sol[x][-1] - ref[x][-1]) > 1


# --- Taylor: the local error of its steps ----------------------------------------------------------------------
def _friction_block():
    x = coordinates("x")
    v = x.diff(t)
    return System([x], T=m * v**2 / 2, V=k * x**2 / 2, forces={x: -mu * m * g * sp.tanh(v / eps)}), x


@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_taylor_on_regularized_coulomb_stick_slip_is_flagged(rtol):
    """A block that sticks under regularized Coulomb friction (tanh(v/ε), ε = 1e-3): where the velocity turns,
    tanh(v/ε) has a radius of convergence of order ε/|v̇| that the Taylor steps reach past, and the block ends at
    the wrong rest position with a clean power balance. The local-error check flags it; Radau passes quietly and
    agrees with a tighter Radau run."""
    s, x = _friction_block()
    ic, p = {x: 1.0, x.diff(t): 0}, {"m": 1, "k": 1, "mu": 0.3, "g": 1, "eps": 1e-3}
    sol = _flagged(lambda: s.simulate(20, ic, p, method="taylor", rtol=rtol), "Taylor local error")
    assert {c.name: c for c in sol.verdict.checks}["power balance"].passed  # the energy cannot tell
    ref = s.simulate(20, ic, p, method="Radau", rtol=1e-11, atol=1e-13, t_eval=[20.0])
    assert abs(sol[x][-1] - ref[x][-1]) > 0.05
    good = _quiet(lambda: s.simulate(20, ic, p, method="Radau", rtol=rtol, atol=rtol * 1e-2))
    assert abs(good[x][-1] - ref[x][-1]) < 1e3 * rtol


@pytest.mark.parametrize("c", [10.0, 1000.0])
def test_taylor_on_a_stiff_damped_oscillator_passes_quietly(c):
    """Strong linear damping (decay rate up to 1000): the Taylor steps go past the stability limit of the
    stiff mode at rest, which the step rule holds at the tolerance — accurate, and not flagged."""
    x = coordinates("x")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, rayleigh=eps * x.diff(t) ** 2 / 2)
    sol = _quiet(lambda: s.simulate(10, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "eps": c}, method="taylor"))
    r = np.roots([1.0, c, 1.0])  # overdamped: x = A e^{r1 t} + B e^{r2 t}, x(0) = 1, x'(0) = 0
    A = -r[1] / (r[0] - r[1])
    exact = A * np.exp(r[0] * sol.t) + (1 - A) * np.exp(r[1] * sol.t)
    assert np.max(np.abs(sol[x] - exact)) < 1e-7


def test_taylor_on_an_analytic_pendulum_passes_quietly():
    s, th = pendulum()
    sol = _quiet(lambda: s.simulate(20, {th: 2.5, th.diff(t): 0}, PEND, method="taylor"))
    names = [c.name for c in sol.verdict.checks]
    assert names == ["energy drift", "Taylor local error"]
    ref = s.simulate(20, {th: 2.5, th.diff(t): 0}, PEND, method="DOP853", rtol=1e-12, atol=1e-14, t_eval=[20.0])
    assert abs(sol[th][-1] - ref[th][-1]) < 1e-6


# --- constraints ------------------------------------------------------------------------------------------------
def test_constraint_drift_both_sides():
    """The Cartesian pendulum without stabilization at rtol 1e-3 drifts off its circle by 2 % of its length while
    its energy stays within 0.1 %; with projection (the default) it passes quietly."""
    x, y = coordinates("x y")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    ic = {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}
    opts = dict(rtol=1e-3, atol=1e-5, n_points=101)
    sol = _flagged(lambda: s.simulate(300, ic, PEND, stabilization="none", **opts), "constraint drift (position)")
    assert {c.name: c for c in sol.verdict.checks}["power balance"].passed
    assert np.max(np.abs(np.hypot(sol[x], sol[y]) - 1.0)) > 1e-2  # the radius itself: really off
    good = _quiet(lambda: s.simulate(300, ic, PEND, **opts))
    assert np.max(np.abs(np.hypot(good[x], good[y]) - 1.0)) < 1e-9


# --- every family passes quietly on a resolved run --------------------------------------------------------------
@pytest.mark.parametrize(("method", "opts"), [
    ("DOP853", {}), ("RK45", {}), ("Radau", {}), ("LSODA", {}), ("BDF", {}), ("taylor", {}),
    ("gl4", {"step": 0.01}), ("gl6", {"step": 0.02}), ("verlet", {"step": 0.001}), ("dg", {"step": 0.004}),
    ("midpoint", {"step": 0.004})])
def test_resolved_runs_of_every_family_pass_quietly(method, opts):
    s, th = pendulum()
    sol = _quiet(lambda: s.simulate(5, {th: 1.0, th.diff(t): 0}, PEND, method=method, **opts))
    ref = s.simulate(5, {th: 1.0, th.diff(t): 0}, PEND, rtol=1e-12, atol=1e-14, t_eval=[5.0])
    assert abs(sol[th][-1] - ref[th][-1]) < 1e-3


# --- display and command line -----------------------------------------------------------------------------------
def test_the_verdict_shows_in_repr_html_and_str():
    s, x = spring()
    with pytest.warns(AccuracyWarning):
        bad = s.simulate(1.0, {x: 1, x.diff(t): 0}, {"m": 1, "k": 1e4}, method="gl4", step=0.1)
    assert "INACCURATE: step-doubling error" in repr(bad)
    assert "INACCURATE" in bad._repr_html_() and "step-doubling error" in bad._repr_html_()
    assert str(bad.verdict).startswith("verdict: INACCURATE")
    good = _quiet(lambda: s.simulate(1.0, {x: 1, x.diff(t): 0}, {"m": 1, "k": 1}))
    assert "verdict: accurate" in repr(good)


OSC = """\
name = "osc"
coordinates = ["x"]
parameters = ["m", "k"]
T = "m/2*x_dot**2"
V = "k/2*x**2"
[params]
m = 1.0
k = 10000.0
[initial]
x = 1.0
x_dot = 0.0
[simulate]
t_end = 1.0
"""


def test_cli_exits_4_on_a_run_that_fails_its_checks(tmp_path, capsys):
    spec = tmp_path / "osc.toml"
    spec.write_text(OSC)
    with pytest.warns(AccuracyWarning):
        status = main(["simulate", str(spec), "-q", "--method", "gl4", "--step", "0.1"])
    out = capsys.readouterr().out
    assert status == 4 and "verdict: INACCURATE" in out and "step-doubling error" in out
    with warnings.catch_warnings():
        warnings.simplefilter("error", AccuracyWarning)
        status = main(["simulate", str(spec), "-q", "--method", "gl4", "--step", "0.0005"])
    out = capsys.readouterr().out
    assert status == 0 and "verdict: accurate" in out


def test_fixed_step_run_with_explicit_time_has_no_energy_check_and_passes_quietly():
    """A pendulum on a shaken support (L depends on t): the Jacobi integral changes by the work of the support,
    which a fixed-step run does not integrate — no energy check; the step-doubling estimate still applies."""
    th = coordinates("theta")
    a, w = parameters("a Omega")
    y = a * sp.cos(w * t) - l * sp.cos(th)
    s = System([th], bodies=[Particle(m, (l * sp.sin(th), y))], V=m * g * y)
    ic, p = {th: 0.4, th.diff(t): 0.1}, {"m": 1.3, "g": 9.81, "l": 0.7, "a": 0.05, "Omega": 11.0}
    sol = _quiet(lambda: s.simulate(3.0, ic, p, method="gl4", step=0.01, n_points=101))
    assert [c.name for c in sol.verdict.checks] == ["step-doubling error"]
    ref = s.simulate(3.0, ic, p, rtol=1e-12, atol=1e-14, t_eval=[3.0])
    assert abs(sol[th][-1] - ref[th][-1]) < 1e-6
