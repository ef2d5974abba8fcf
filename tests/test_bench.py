"""The benchmark package: closed forms, error measurement, reference self-consistency, report, CLI."""

import json
import math

import numpy as np
import pytest

from lagrange.bench.heyoka_adapter import heyoka_available
from lagrange.bench.problems import belt_state, belt_stick_interval, get_problem, kepler_state
from lagrange.bench.report import cheapest, readme_section, render_markdown
from lagrange.bench.runner import MethodSpec, Reference, reference_solution, run_curve
from lagrange.cli import main
from lagrange.errors import BackendError, SpecError


def test_kepler_closed_form_is_an_orbit():
    """Independent checks of the Kepler's-equation solution: energy −μ/2a, angular momentum √(μa(1−e²)),
    period 2π√(a³/μ), and the velocity is the derivative of the position."""
    ts = np.linspace(0, 7, 701)
    Y = kepler_state(ts, a=1.0, e=0.5)
    r = np.hypot(Y[:, 0], Y[:, 1])
    assert np.allclose(0.5 * (Y[:, 2] ** 2 + Y[:, 3] ** 2) - 1 / r, -0.5, atol=1e-13)
    assert np.allclose(Y[:, 0] * Y[:, 3] - Y[:, 1] * Y[:, 2], math.sqrt(0.75), atol=1e-13)
    assert np.allclose(kepler_state([2 * math.pi]), kepler_state([0.0]), atol=1e-12)
    assert np.allclose(np.gradient(Y[:, 0], ts)[1:-1], Y[1:-1, 2], atol=2e-3)


def test_belt_closed_form_obeys_the_friction_law():
    """Slip phase satisfies ẍ = −x − σμg, the stick phase moves with the belt at |x| ≤ μg/ω², and the limit
    cycle touches but never exceeds the belt speed."""
    t1, t2 = belt_stick_interval()
    ts = np.linspace(0, 20, 20001)
    Y = belt_state(ts)
    acc = np.gradient(Y[:, 1], ts)
    slip = ts < t1 - 0.01
    assert np.allclose(acc[slip][1:], -Y[slip, 0][1:] - 0.5, atol=1e-3)  # v0 = 0.5 > belt: friction backward
    stick = (ts > t1) & (ts < t2)
    assert np.allclose(Y[stick, 1], 0.2) and np.all(np.abs(Y[stick, 0]) <= 0.5 + 1e-12)
    cycle = ts > t2
    assert np.max(Y[cycle, 1]) == pytest.approx(0.2, abs=1e-6) and np.all(Y[cycle, 1] <= 0.2 + 1e-12)
    assert np.allclose(acc[cycle][1:-1], -Y[cycle, 0][1:-1] + 0.5, atol=1e-3)  # slower than belt: forward


def test_runner_error_against_kepler_closed_form():
    p = get_problem("kepler", quick=True)
    system = p.build()
    ref = reference_solution(p, system, backend="python")
    assert ref.description == "closed form" and ref.check < 1e-9  # DOP853 at 1e-13 agrees with the closed form
    curve = run_curve(p, system, MethodSpec("DOP853 python"), ref, (1e-6, 1e-9), repeats=1)
    assert [pt.setting for pt in curve.points] == [1e-6, 1e-9] and not curve.note
    for pt in curve.points:  # the reported error is the distance from Kepler's equation, computed independently
        sol = system.simulate(p.t_end, p.initial, p.params, rtol=pt.setting, atol=pt.setting, t_eval=[p.t_end])
        assert pt.error == pytest.approx(np.max(np.abs(sol.y[-1] - kepler_state([p.t_end])[0])), rel=1e-9)
        assert pt.nfev == sol.nfev and pt.wall > 0
    assert curve.points[1].error < 1e-2 * curve.points[0].error


def test_reference_self_consistency_is_reported():
    p = get_problem("double_pendulum", quick=True)
    ref = reference_solution(p, p.build(), backend="python")
    assert ref.description.startswith("DOP853 rtol 1e-13")
    assert 0 < ref.consistency < 1e-9  # two tight runs differ, but only at round-off level


def test_unavailable_and_inapplicable_methods_are_reported():
    p = get_problem("kepler", quick=True)
    system = p.build()
    ref = Reference(kepler_state(p.times()), "closed form", None)
    bad = run_curve(p, system, MethodSpec("bogus loop", loop="no-such-loop"), ref, (1e-6,))
    assert not bad.points and bad.note.startswith("unavailable")
    friction = get_problem("stick_slip", quick=True)
    # with heyoka installed the friction system is refused; without it, the missing extra is named
    with pytest.raises(BackendError, match="dry friction" if heyoka_available() else 'lagrange-dynamics\\[heyoka\\]'):
        from lagrange.bench.heyoka_adapter import heyoka_model

        heyoka_model(friction.build(), friction.params)


def test_plain_sympy_route_agrees_with_lagrange():
    from lagrange.bench.sympy_route import plain_pendulum_route
    from lagrange.examples import n_link_pendulum

    _, _, rhs = plain_pendulum_route(3)
    model = n_link_pendulum(3).compile({"g": 9.81})
    for y in np.random.default_rng(1).uniform(-2, 2, (5, 6)):
        assert np.allclose(rhs(0.0, y), model.fun(0.0, y), rtol=1e-11, atol=1e-11)


@pytest.mark.skipif(not heyoka_available(), reason="heyoka not installed")
def test_heyoka_adapter_matches_kepler_closed_form():
    from lagrange.bench.heyoka_adapter import heyoka_model
    from lagrange.bench.runner import initial_vector

    p = get_problem("kepler", quick=True)
    system = p.build()
    hm = heyoka_model(system, p.params)
    y0 = initial_vector(p, system)
    ta, _ = hm.integrator(y0, 1e-14)
    Y, steps = hm.propagate(ta, y0, [1.0, p.t_end])
    assert np.allclose(Y, kepler_state([1.0, p.t_end]), atol=1e-10) and steps > 0


def _fake_data():
    def curve(label, kind, backend, pts):
        points = [{"setting": s, "wall": w, "nfev": n, "error": e, "runs": 3} for s, w, n, e in pts]
        return {"label": label, "kind": kind, "method": "DOP853", "backend": backend, "loop": None, "setup": 0.01,
                "note": "", "points": points}

    return {"machine": {"cpu": "Test CPU", "cores": 2, "os": "Linux", "threads": {},
                        "versions": {"python": "3.11", "numpy": "2", "heyoka": None}},
            "settings": {"mode": "full", "repeats": 3},
            "problems": [{"name": "toy", "title": "a toy", "notes": "", "t_end": 1.0, "derive_s": 0.1,
                          "conservative": True, "long_t_end": 0.0,
                          "reference": {"description": "closed form", "consistency": None, "check": 1e-14},
                          "curves": [curve("DOP853 python", "simulate", "python",
                                           [(1e-6, 0.002, 100, 3e-7), (1e-9, 0.004, 200, 2e-10)]),
                                     curve("plain sympy DOP853", "sympy", "python",
                                           [(1e-6, 0.010, 100, 3e-7), (1e-9, 0.020, 200, 2e-10)]),
                                     curve("heyoka", "heyoka", "python", [(1e-9, 0.001, None, 1e-11)])],
                          "energy": [], "first_result": [
                              {"route": "python", "label": "lagrange python", "derive": 0.1, "compile": 0.01,
                               "integrate": 0.002, "total": 0.112, "error": 2e-10, "note": ""}]}]}


def test_markdown_tables_have_the_expected_columns():
    md = render_markdown(_fake_data())
    assert "Machine: Test CPU, 2 logical cores" in md and "heyoka not installed" in md
    assert "| problem | error | lagrange | plain sympy | heyoka | sympy / lagrange | lagrange / heyoka |" in md
    assert "| method | setup | tol 1e-06 | tol 1e-09 | note |" in md
    assert "| DOP853 python | 10 ms | 2 ms · 3.0e-07 · 100 | 4 ms · 2.0e-10 · 200 |  |" in md
    # at error ≤ 1e-7: lagrange 4 ms, plain 20 ms (×5.0), heyoka 1 ms (lagrange/heyoka = 4.0)
    assert "| toy | ≤ 1e-07 | 4 ms (DOP853 python) | 20 ms (plain sympy DOP853) | 1 ms (heyoka) | ×5.0 | 4.0 |" in md
    assert "| derive | compile / JIT | integrate | total | error |" in md
    assert "Imports are not" not in md  # none measured
    data = _fake_data()
    data["settings"]["imports"] = {"lagrange": 0.5, "heyoka": 0.25}
    assert ("in a fresh process they take 500 ms (lagrange with sympy, numpy and scipy.integrate), 250 ms (heyoka)."
            in render_markdown(data))
    section = readme_section(_fake_data())
    assert section.startswith("## Speed against error")
    assert "| toy | 4 ms (DOP853 python) | 4 ms (DOP853 python) | 20 ms (×5 / ×5.0) | 1 ms (4.0) |" in section
    assert cheapest(_fake_data()["problems"][0]["curves"], 1e-12) is None


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_cli_bench_quick_writes_markdown_and_png(tmp_path, capsys):
    assert main(["bench", "--quick", "--problem", "kepler", "--out", str(tmp_path)]) == 0
    md = (tmp_path / "workprecision.md").read_text()
    assert "## kepler" in md and "DOP853 python" in md and "Reference: closed form" in md
    png = tmp_path / "workprecision_kepler.png"
    assert png.stat().st_size > 20_000
    data = json.loads((tmp_path / "workprecision.json").read_text())
    errs = [pt["error"] for c in data["problems"][0]["curves"] if c["label"] == "DOP853 python" for pt in c["points"]]
    assert len(errs) == 2 and errs[1] < errs[0] < 1e-2
    assert main(["bench", "--quick", "--problem", "nope"]) == 2
    assert "--problem nope: unknown benchmark problem" in capsys.readouterr().err


def test_unknown_problem_is_a_spec_error():
    with pytest.raises(SpecError, match="choose from double_pendulum"):
        get_problem("pendulum")


def test_time_to_first_result_runs_cold_in_a_fresh_process():
    from lagrange.bench.first_result import first_result

    p = get_problem("kepler", quick=True)
    fr = first_result(p, "python", kepler_state(p.times()), tol=1e-8, quick=True)
    assert fr.derive > 0 and fr.compile > 0 and fr.integrate > 0, fr.note
    assert fr.total == pytest.approx(fr.derive + fr.compile + fr.integrate)
    assert fr.error < 1e-4


def test_import_times_are_measured_in_fresh_processes():
    from lagrange.bench.first_result import import_times

    t = import_times(repeats=1)
    assert 0.01 < t["lagrange"] < 30  # sympy, numpy and scipy.integrate at least
