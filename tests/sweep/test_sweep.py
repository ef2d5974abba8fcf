"""lagrange.sweep: grids and samples, the table, failures (exceptions, dead workers), store and resume, CLI."""

import os
import sys
import uuid
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import lagrange as lg
from lagrange.cli import main
from lagrange.errors import SweepError
from lagrange.sweep import grid_points, random_points, run_id

x = lg.coordinates("x")
k, mass = lg.parameters("k mass")
OSC = lg.System([x], bodies=[lg.Particle(mass, (x,))], V=k * x**2 / 2)
T_END = 2.0
BASE = dict(t_end=T_END, initial={"x": 1.0, "x_dot": 0.0}, params={"mass": 1.0, "k": 1.0}, progress=False)
OVER = {"k": [1.0, 2.0, 4.0, 9.0], "x": [0.5, 1.0]}


def _results(table):
    """The results (run_config differs between sweeps with other summaries: compared where it matters)."""
    return table.drop(columns=["wall_time", "run_config"]).reset_index(drop=True)


def peak(traj):
    return float(np.max(np.abs(traj["x"])))


def die_at_k2(traj):
    if traj.model.params[0] == 2.0:  # params in the order (k, mass)
        os._exit(3)
    return 0.0


def mark_call(traj):
    """Leave one file per call in $SWEEP_MARKS (counts the runs computed, in any process)."""
    Path(os.environ["SWEEP_MARKS"], uuid.uuid4().hex).touch()
    return 0.0


@pytest.fixture(scope="module")
def pool():
    with ProcessPoolExecutor(max_workers=2) as ex:
        yield ex


@pytest.fixture(scope="module")
def serial():
    return lg.sweep(OSC, OVER, workers=0, summaries=[peak], **BASE)


def test_grid_matches_closed_form_and_direct_runs(serial):
    assert list(serial.columns[:5]) == ["run_id", "k", "x", "status", "error"]
    assert len(serial) == 8 and (serial["status"] == "ok").all() and (serial["error"] == "").all()
    assert serial[["k", "x"]].values.tolist() == [[p["k"], p["x"]] for p in grid_points(OVER)]
    exact = serial["x"] * np.cos(np.sqrt(serial["k"]) * T_END)  # x0 cos(√k t)
    assert np.allclose(serial["final_x"], exact, atol=1e-8)
    assert np.allclose(serial["peak"], serial["x"], rtol=1e-9)
    assert (serial["energy_error"] < 1e-7).all() and serial["success"].all()
    direct = OSC.simulate(T_END, {"x": 0.5, "x_dot": 0.0}, {"mass": 1.0, "k": 9.0})
    row = serial[(serial["k"] == 9.0) & (serial["x"] == 0.5)].iloc[0]
    assert row["final_x"] == direct.y[-1, 0] and row["nfev"] == direct.nfev
    assert row["run_id"] == run_id({"k": 9.0, "x": 0.5})


def test_process_pool_gives_the_same_table(serial, pool):
    parallel = lg.sweep(OSC, OVER, executor=pool, summaries=[peak], **BASE)
    pd.testing.assert_frame_equal(_results(parallel), _results(serial))


def test_an_exception_in_one_run_is_reported(pool):
    table = lg.sweep(OSC, {"mass": [1.0, 0.0, 2.0]}, executor=pool, **BASE)  # mass 0: singular mass matrix
    assert table["status"].tolist() == ["ok", "error", "ok"]
    assert table["error"][1].startswith("SingularMassMatrixError") and "x" in table["error"][1]
    assert np.isclose(table["final_x"][2], np.cos(T_END / np.sqrt(2)), atol=1e-8)
    assert np.isnan(table["final_x"][1])


def test_a_dying_worker_loses_only_its_run(serial):
    table = lg.sweep(OSC, OVER, workers=2, summaries=[peak, die_at_k2], **BASE)
    died = table["k"] == 2.0
    assert (table.loc[died, "status"] == "died").all() and table.loc[died, "error"].str.contains("died").all()
    assert (table.loc[~died, "status"] == "ok").all()
    ok = _results(table.loc[~died].drop(columns=["die_at_k2"]))
    pd.testing.assert_frame_equal(ok, _results(serial.loc[serial["k"] != 2.0]), check_dtype=False)


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_resume_computes_only_the_missing_runs(tmp_path, monkeypatch, serial, suffix):
    marks = tmp_path / "marks"
    marks.mkdir()
    monkeypatch.setenv("SWEEP_MARKS", str(marks))
    store = tmp_path / f"runs{suffix}"
    full = lg.sweep(OSC, OVER, workers=0, summaries=[peak, mark_call], store=store, **BASE)
    assert len(list(marks.iterdir())) == 8
    # an interruption: half of the runs lost (and, for CSV, a torn last line)
    keep = set(full["run_id"][::2])
    if suffix == ".csv":
        lines = store.read_text().splitlines(keepends=True)
        kept = [ln for ln in lines[1:] if ln.split(",")[0] in keep]
        store.write_text(lines[0] + "".join(kept) + "0123,partial")
    else:
        for f in store.iterdir():
            if f.stem not in keep:
                f.unlink()
    with pytest.raises(SweepError, match="resume=True"):
        lg.sweep(OSC, OVER, workers=0, summaries=[peak, mark_call], store=store, **BASE)
    resumed = lg.sweep(OSC, OVER, workers=2, summaries=[peak, mark_call], store=store, resume=True, **BASE)
    assert len(list(marks.iterdir())) == 8 + 4  # only the four missing runs were computed
    cols = [c for c in serial.columns if c not in ("wall_time", "run_config")]  # other summaries: other config
    pd.testing.assert_frame_equal(resumed[cols], serial[cols], check_dtype=False)
    again = lg.sweep(OSC, OVER, workers=0, summaries=[peak, mark_call], store=store, resume=True, **BASE)
    assert len(list(marks.iterdir())) == 12 and len(again) == 8


def test_random_sample(pool):
    pts = random_points({"k": (1, 9), "x": (0.5, 1)}, 6, seed=2)
    table = lg.sweep(OSC, {"k": (1, 9), "x": (0.5, 1)}, random=6, seed=2, executor=pool, **BASE)
    assert table[["k", "x"]].values.tolist() == [[p["k"], p["x"]] for p in pts]
    assert table["k"].between(1, 9).all() and len(set(table["run_id"])) == 6
    assert np.allclose(table["final_x"], table["x"] * np.cos(np.sqrt(table["k"]) * T_END), atol=1e-8)


def test_declaration_errors(tmp_path):
    with pytest.raises(SweepError, match="cannot sweep omega"):
        lg.sweep(OSC, {"omega": [1.0]}, workers=0, **BASE)
    with pytest.raises(SweepError, match="start:stop:num"):
        lg.sweep(OSC, {"k": "1:2"}, workers=0, **BASE)
    with pytest.raises(SweepError, match="t_end"):
        lg.sweep(OSC, {"k": [1.0]}, workers=0)
    with pytest.raises(SweepError, match="repeated"):
        lg.sweep(OSC, {"k": [1.0, 1.0]}, workers=0, **BASE)
    with pytest.raises(SweepError, match="suffix"):
        lg.sweep(OSC, {"k": [1.0]}, workers=0, store=tmp_path / "x.txt", **BASE)


def test_missing_pandas_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(SweepError, match=r"lagrange-dynamics\[sweep\]"):
        lg.sweep(OSC, {"k": [1.0]}, workers=0, **BASE)


def test_progress_counter_without_tqdm(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "tqdm", None)
    lg.sweep(OSC, {"k": [1.0, 2.0, 3.0]}, workers=0, **{**BASE, "progress": True})
    assert "3/3 runs" in capsys.readouterr().err


def test_task_callable_and_lambda_summaries_travel(pool):
    table = lg.sweep(OSC, {"k": [1.0, 4.0]}, executor=pool, summaries=[lambda tr: tr.nfev * 0 + 7], **BASE)
    assert table["<lambda>"].tolist() == [7, 7]


def test_cli_sweep(tmp_path, capsys):
    out = tmp_path / "table.csv"
    code = main(["sweep", "ex3.4", "--over", "k=20:40:2", "--over", "theta=0.5,1", "--t-end", "1", "--workers", "0",
                 "--no-progress", "--out", str(out)])
    assert code == 0
    table = pd.read_csv(out)
    assert len(table) == 4 and (table["status"] == "ok").all()
    assert "4 runs: 4 ok" in capsys.readouterr().out
    assert main(["sweep", "ex3.4", "--over", "k=1:2", "--t-end", "1"]) == 2
    assert "start:stop:num" in capsys.readouterr().err
    assert main(["sweep", "ex3.4", "--over", "nope=1:2:2", "--t-end", "1", "--workers", "0"]) == 2
