"""The N-link scaling benchmarks' pieces: System options passed through to the pendulum, the nlink<N> problems up
to N = 50, fresh-process first results (CPU columns, time-outs, medians) and the equal-error arithmetic and worker
protocol of ``benchmarks/nlink_integration.py``."""

import importlib.util
import inspect
import math
import os
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from lagrange.bench.first_result import FirstResult, first_result_once, median_by_total
from lagrange.bench.heyoka_adapter import heyoka_available
from lagrange.bench.problems import MAX_LINKS, derivation_options, get_problem
from lagrange.errors import LagrangeError, SpecError
from lagrange.examples import n_link_pendulum
from lagrange.model.system import System

_SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "nlink_integration.py"


def _nlink_integration():
    spec = importlib.util.spec_from_file_location("nlink_integration", _SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_pendulum_passes_system_options_through_and_derives_the_same_equations():
    plain = n_link_pendulum(3)
    named = n_link_pendulum(3, name="chain", description="three links")
    assert plain.name == "3-link pendulum" and named.name == "chain" and named.description == "three links"
    a, b = plain.derived, named.derived
    assert (a.mass_matrix - b.mass_matrix).applyfunc(sp.simplify) == sp.zeros(3, 3)
    assert (a.forcing - b.forcing).applyfunc(sp.simplify) == sp.zeros(3, 1)
    with pytest.raises(TypeError, match="no_such_option"):
        n_link_pendulum(2, no_such_option=1)


def test_nlink_problems_reach_fifty_links_and_refuse_what_they_cannot_pass_on():
    p = get_problem(f"nlink{MAX_LINKS}")
    assert MAX_LINKS == 50 and p.pendulum_links == 50 and len(p.initial) == 100
    assert get_problem("nlink3", system_kwargs={"description": "d"}).build().description == "d"
    assert get_problem("nlink", system_kwargs={"description": "d"}).build().description == "d"  # the 5-link
    with pytest.raises(SpecError, match="nlink51"):
        get_problem("nlink51")
    with pytest.raises(SpecError, match="N-link pendulums only.*kepler"):
        get_problem("kepler", system_kwargs={"description": "d"})


def test_derivation_option_is_passed_only_when_system_takes_it():
    assert derivation_options(None) == {}
    if "derivation" in inspect.signature(System.__init__).parameters:
        assert derivation_options("expanded") == {"derivation": "expanded"}
    else:
        with pytest.raises(SpecError, match="no 'derivation' keyword") as info:
            derivation_options("structural")
        assert isinstance(info.value, (LagrangeError, ValueError))


def test_kanes_method_route_is_the_same_pendulum():
    """sympy's KanesMethod (a second formulation) gives lagrange's accelerations at random states."""
    from lagrange.bench.sympy_route import kane_pendulum_route

    _, _, rhs = kane_pendulum_route(3)
    model = n_link_pendulum(3).compile({"g": 9.81})
    for y in np.random.default_rng(3).uniform(-2, 2, (4, 6)):
        assert np.allclose(rhs(0.0, y), model.fun(0.0, y), rtol=1e-12, atol=1e-12)


def test_median_by_total_skips_failed_runs():
    runs = [FirstResult("r", 1.0, 1.0, 1.0, 0.0), FirstResult("r", None, None, None, None, "timed out"),
            FirstResult("r", 0.5, 0.5, 0.5, 0.0), FirstResult("r", 2.0, 2.0, 2.0, 0.0)]
    assert median_by_total(runs).total == 3.0
    failed = [FirstResult("r", None, None, None, None, "timed out after 1 s")]
    assert median_by_total(failed).note == "timed out after 1 s"


def test_a_route_over_its_time_out_is_reported_as_timed_out():
    p = get_problem("nlink2")
    r = first_result_once(p, "python", np.zeros((1, 4)), timeout=0.05)
    assert r.total is None and r.cpu is None and r.note == "timed out after 0.05 s"


def test_first_result_reports_cpu_and_whole_process_times():
    p = get_problem("nlink2")
    ref = p.build().simulate((0.0, p.t_end), p.initial, p.params, method="DOP853", rtol=1e-12, atol=1e-12,
                             t_eval=p.times()).y
    r = first_result_once(p, "python", ref, timeout=120.0, system_kwargs={"description": "passed"})
    assert r.total is not None, r.note
    assert r.error < 1e-7  # rtol 1e-10 against a 1e-12 reference
    # the phases' CPU time is part of the whole process's, which also pays the interpreter start and imports
    assert 0 < r.cpu < r.process_cpu and r.process_wall > r.total


def test_equal_error_interpolation_follows_a_power_law_and_does_not_extrapolate():
    mod = _nlink_integration()
    law = lambda e: 2e-3 * e ** -0.25  # noqa: E731 - CPU time of a route against its error
    pts = [dict(error=e, cpu=law(e)) for e in (1e-4, 1e-7, 1e-10)]
    for e in (3e-5, 1e-6, 4e-9):
        assert math.isclose(mod._interp_cpu(pts, e), law(e), rel_tol=1e-12)
    assert mod._interp_cpu(pts, 1e-3) is None and mod._interp_cpu(pts, 1e-12) is None
    assert math.isclose(mod._interp_cpu(pts, 1.05e-4), law(1e-4), rel_tol=1e-12)  # within EQUAL_ERROR: the end


def test_ratio_takes_the_best_lagrange_route_at_each_heyoka_error():
    mod = _nlink_integration()
    slow = [dict(tol=t, error=t, cpu=10 * t ** -0.2, wall=0.0, work=0, samples=1) for t in (1e-6, 1e-10)]
    fast = [dict(tol=t, error=t, cpu=t ** -0.2, wall=0.0, work=0, samples=1) for t in (1e-6, 1e-10)]
    hey = [dict(tol=1e-8, error=1e-8, cpu=2 * 1e-8 ** -0.2, wall=0.0, work=0, samples=1),
           dict(tol=1e-12, error=1e-12, cpu=1.0, wall=0.0, work=0, samples=1)]
    out = mod.ratios(dict(points={"taylor_c": slow, "dop853_compiled": fast, "heyoka_compact": hey}))
    assert out[0]["best"] == "dop853_compiled" and math.isclose(out[0]["ratio"], 0.5, rel_tol=1e-12)
    assert out[1]["best"] is None and out[1]["ratio"] is None  # heyoka's error beyond the lagrange curves


def _measure(routes, tols, tmp_path):
    mod = _nlink_integration()
    env = dict(os.environ, LAGRANGE_DERIVATION_CACHE="0")  # the session's cache dir (conftest), lagrange importable
    return mod, mod.measure(2, routes, tols, repeats=2, system_kwargs={}, setup_timeout=120.0, run_timeout=60.0,
                            stop=5.0, env=env, log=lambda s: None)


def test_integration_workers_time_interleaved_runs_against_the_reference(tmp_path):
    pytest.importorskip("numba")
    from lagrange.integrate.taylor import available_interpreter

    if available_interpreter() != "c":
        pytest.skip("needs the C Taylor interpreter")
    mod, res = _measure(["taylor_c"], [1e-6, 1e-9], tmp_path)
    pts = {p["tol"]: p for p in res["points"]["taylor_c"]}
    assert res["reference"] and set(pts) == {1e-6, 1e-9}
    assert all(p["samples"] == 2 and p["cpu"] > 0 and p["wall"] > 0 for p in pts.values())
    # a tighter tolerance costs more steps and comes closer to the reference (rtol 1e-16)
    assert pts[1e-9]["work"] > pts[1e-6]["work"] and 0 < pts[1e-9]["error"] < pts[1e-6]["error"] < 1e-2
    assert res["profile"]["tape"] > 0


@pytest.mark.slow
@pytest.mark.skipif(not heyoka_available(), reason="heyoka is not installed")
def test_heyoka_worker_agrees_with_the_taylor_reference(tmp_path):
    """heyoka derives its own equations from T − V: its state at t = 10 is an independent check of the
    reference, and with the same step-size rule its error at a tolerance is lagrange's Taylor error there."""
    mod, res = _measure(["taylor_c", "heyoka_compact"], [1e-8], tmp_path)
    ours, theirs = res["points"]["taylor_c"][0], res["points"]["heyoka_compact"][0]
    assert theirs["error"] < 1e-5 and 0.1 < theirs["error"] / ours["error"] < 10
    assert res["checks"] and max(res["checks"].values()) < 1e-10
    assert mod.ratios(res)[0]["best"] == "taylor_c"
