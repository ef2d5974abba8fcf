"""The hard-case suite (lagrange/bench/hard.py, ``lagrange bench --hard``): each problem's reference is right
(checked against a second, independent truth), the report has every column, the classifier can tell a silently
wrong run from an accurate one, and no run of the quick suite is silently wrong except the one case named below.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from lagrange.bench.hard import (
    COLUMNS,
    HARD_PROBLEMS,
    QUICK_METHODS,
    SILENT_FACTOR,
    STICK_REST,
    HardProblem,
    car_axis_reference,
    get_hard_problem,
    render_hard_markdown,
    run_hard_case,
    run_hard_suite,
    spherical_reference,
    write_hard_report,
)
from lagrange.bench.problems import kepler_state
from lagrange.cli import main
from lagrange.errors import SpecError
from lagrange.examples import SQUEEZER_REFERENCE


@pytest.fixture(scope="module")
def quick_runs():
    return run_hard_suite(quick=True, log=None)


def _tight(problem, rtol=1e-11, method="DOP853", **kw):
    s = problem.build()
    return s.simulate((0.0, problem.t_end), problem.initial, problem.params, method=method, rtol=rtol,
                      atol=rtol * problem.atol_scale, n_points=problem.n_points, **(problem.options | kw))


# --- the references are right ----------------------------------------------------------------------------------

def test_squeezer_published_reference_reached_by_the_default_method():
    p = get_hard_problem("squeezer", quick=True)
    sol = _tight(p, rtol=1e-10, method="DOP853")
    assert sol.verdict.ok
    assert np.max(np.abs(p.observe(sol)[-1] - np.array(SQUEEZER_REFERENCE[0]))) < 1e-7


def test_car_axis_two_formulations_agree():
    """The derived index-3 model (projection) and the hand-written index-1 KKT formulation."""
    p = get_hard_problem("car_axis", quick=True)
    sol = _tight(p, rtol=1e-10)
    assert np.max(np.abs(p.observe(sol) - car_axis_reference(sol.t))) < 1e-8
    assert sol.max_constraint_violation() < 1e-9


def test_kepler_closed_form_at_zero_and_after_one_period():
    e = 0.9
    y0 = kepler_state([0.0], e=e)[0]
    assert y0 == pytest.approx([1 - e, 0.0, 0.0, math.sqrt((1 + e) / (1 - e))], abs=1e-14)
    assert kepler_state([2 * math.pi], e=e)[0] == pytest.approx(y0, abs=1e-11)
    half = kepler_state([math.pi], e=e)[0]  # aphelion
    assert half == pytest.approx([-(1 + e), 0.0, 0.0, -math.sqrt((1 - e) / (1 + e))], abs=1e-11)
    ys = kepler_state(np.linspace(0, 2 * math.pi, 50), e=e)  # vis-viva: E = −μ/(2a) = −1/2
    energy = (ys[:, 2] ** 2 + ys[:, 3] ** 2) / 2 - 1 / np.hypot(ys[:, 0], ys[:, 1])
    assert np.max(np.abs(energy + 0.5)) < 1e-12


def test_double_pendulum_reference_agrees_with_a_second_method():
    p = get_hard_problem("double_pendulum", quick=True)
    sol = _tight(p, rtol=1e-13)
    keep = sol.t <= p.error_until
    assert np.max(np.abs(sol.y[keep] - p.reference(sol.t)[keep])) < 1e-8


def _cone_closed_form(time, x0=1.0):
    """ε → 0, V = |x|, m = 1, from rest at x0: x = x0 − t²/2 until the kink; period 4√(2 x0)."""
    quarter = math.sqrt(2 * x0)
    s = time % (4 * quarter)
    if s <= 2 * quarter:
        return x0 - s**2 / 2 if s <= quarter else -x0 + (2 * quarter - s) ** 2 / 2
    return -_cone_closed_form(s - 2 * quarter, x0)


def test_cone_reference_near_the_kink_limit():
    p = get_hard_problem("cone", quick=True)
    times = np.linspace(0, p.t_end, 101)
    ref = p.reference(times)[:, 0]
    assert np.max(np.abs(ref - [_cone_closed_form(tt) for tt in times])) < 1e-3  # O(ε) per crossing, ε = 1e-4


def test_stick_slip_exact_rest_matches_a_tight_run():
    p = get_hard_problem("stick_slip", quick=True)
    sol = _tight(p, rtol=1e-10, method="Radau")
    assert abs(sol["x"][-1] - STICK_REST) < 5e-6 and abs(sol["x_dot"][-1]) < 1e-5


def test_spherical_pole_reference_is_the_same_motion():
    p = get_hard_problem("spherical_pole", quick=True)
    sol = _tight(p, rtol=1e-12)
    ref = spherical_reference(sol.t)
    assert np.max(np.abs(np.linalg.norm(ref, axis=1) - 1.0)) < 1e-9  # on the sphere
    assert np.max(np.abs(p.observe(sol) - ref)) < 1e-7
    # it passes within 2.4e-4 rad of the pole: the turning point of p_φ²/(2 sin²θ) − g cos θ = its initial value
    g, th0, w0 = p.params["g"], p.initial["theta"], p.initial["phi_dot"]
    p_phi = math.sin(th0) ** 2 * w0
    level = p_phi**2 / (2 * math.sin(th0) ** 2) - g * math.cos(th0)
    theta_min = brentq(lambda th: p_phi**2 / (2 * math.sin(th) ** 2) - g * math.cos(th) - level, 1e-9, 0.5)
    assert 2e-4 < theta_min < 3e-4
    assert np.max(np.abs(np.sin(sol["theta"]) ** 2 * sol["phi_dot"] - p_phi)) < 1e-9  # p_φ conserved


# --- the classifier, on both sides -------------------------------------------------------------------------------

def _oscillator(offset: float) -> HardProblem:
    from lagrange import System, coordinates, t

    x = coordinates("x")
    return HardProblem("osc", "oscillator", lambda: System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2), {}, {"x": 1.0,
                       "x_dot": 0.0}, 3.0, lambda sol: sol.y[:, :1],
                       lambda times: np.cos(times)[:, None] + offset, "closed form", (1e-8,), n_points=31)


@pytest.mark.parametrize("offset,outcome", [(0.0, "accurate"), (1e-3, "SILENTLY WRONG")])
def test_classifier_tells_silently_wrong_from_accurate(offset, outcome):
    p = _oscillator(offset)
    run = run_hard_case(p, p.build(), "DOP853", 1e-8)
    assert run.outcome == outcome, run
    assert (run.error > SILENT_FACTOR * 1e-8) == (offset > 0)


def test_refusals_and_failures_are_recorded_not_raised():
    p = _oscillator(0.0)
    s = p.build()
    assert run_hard_case(p, s, "no_such_method", 1e-6).outcome == "refused"
    bad = HardProblem("bad", "bad", p.build, {}, {"x": 1.0, "x_dot": 0.0, "zz": 2.0}, 1.0, p.observe, p.reference, "",
                      (1e-6,))  # an unknown name
    r = run_hard_case(bad, s, "DOP853", 1e-6)
    assert r.outcome in ("ERRORED", "refused") and r.detail.split(":")[0].endswith("Error")


# --- the quick suite -----------------------------------------------------------------------------------------------

#: a run the suite found silently wrong, with its cause; strict: the test fails once it is fixed
KNOWN_SILENT = {
    ("kepler", "LSODA"): "LSODA at rtol 1e-6 on the e = 0.9 orbit: phase error 2.5e-3 after 3 periods while the "
                         "energy drifts 2.6e-6 (allowed 1.2e-3): the power balance cannot see a phase error",
}


@pytest.mark.parametrize("problem,method", [
    pytest.param(p, m, marks=pytest.mark.xfail(strict=True, reason=KNOWN_SILENT[(p, m)]) if (p, m) in KNOWN_SILENT
                 else ()) for p in HARD_PROBLEMS for m in QUICK_METHODS])
def test_no_quick_run_is_silently_wrong(quick_runs, problem, method):
    runs = [r for r in quick_runs if r.problem == problem and r.method == method]
    assert runs
    for r in runs:
        assert r.outcome != "SILENTLY WRONG", r
        assert r.outcome != "ERRORED", r  # a refusal names what works; anything else is a bug
        if r.outcome == "accurate":
            assert r.error <= SILENT_FACTOR * r.rtol + get_hard_problem(problem, quick=True).floor


def test_quick_suite_flags_what_fails(quick_runs):
    """The hard cases do break methods, and those runs say so themselves: Taylor on the kink, gl4 through the pole;
    the constrained mechanisms are refused by the methods that cannot hold constraints, and auto is accurate."""
    by = {(r.problem, r.method): r for r in quick_runs}
    assert by["cone", "taylor"].outcome == "flagged" and by["cone", "taylor"].error > 1
    assert by["spherical_pole", "gl4"].outcome == "flagged"
    for problem in ("squeezer", "car_axis"):
        assert by[problem, "taylor"].outcome == "refused" and by[problem, "gl4"].outcome == "refused"
        assert by[problem, "DOP853"].drift is not None and by[problem, "DOP853"].drift < 1e-6
    assert all(by[p, "auto"].outcome == "accurate" for p in HARD_PROBLEMS)
    assert by["double_pendulum", "DOP853"].horizon > 1.0


def test_table_has_every_column_and_row(quick_runs, tmp_path):
    md = render_hard_markdown(quick_runs, quick=True)
    assert "| " + " | ".join(COLUMNS) + " |" in md
    rows = [ln for ln in md.splitlines() if ln.startswith("| ") and not ln.startswith("| problem")]
    assert len(rows) == len(quick_runs) == len(HARD_PROBLEMS) * len(QUICK_METHODS)
    assert all(ln.count(" | ") == len(COLUMNS) - 1 for ln in rows)
    paths = write_hard_report([r for r in quick_runs if r.problem == "cone"], tmp_path, quick=True)
    assert paths["png"][0].stat().st_size > 10_000


def test_cli_bench_hard(tmp_path, capsys):
    assert main(["bench", "--hard", "--quick", "--problem", "cone", "--out", str(tmp_path), "-q"]) == 0
    md = (tmp_path / "hard_cases.md").read_text()
    assert "| cone | auto |" in md and (tmp_path / "hard_cases_cone.png").exists()
    assert main(["bench", "--hard", "--problem", "nope"]) == 2
    assert "--problem nope: unknown hard case" in capsys.readouterr().err
    with pytest.raises(SpecError, match="unknown hard case"):
        get_hard_problem("nope")
