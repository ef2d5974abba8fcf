"""Sweep resume keyed by everything that defines a run, reserved column names, attribution of Dask worker
deaths, release of unpickled tasks, and Ctrl-C."""

import os
import pickle
import select
import signal
import subprocess
import sys
import textwrap
import time
import uuid
from concurrent.futures import Executor, Future
from pathlib import Path

import numpy as np
import pytest

import lagrange as lg
from lagrange.errors import SweepError
from lagrange.sweep import task as task_module
from lagrange.sweep.executor import run_points
from lagrange.sweep.identity import run_config

pytest.importorskip("pandas")

x = lg.coordinates("x")
k, mass = lg.parameters("k mass")
OSC = lg.System([x], bodies=[lg.Particle(mass, (x,))], V=k * x**2 / 2)
BASE = dict(t_end=1.0, initial={"x": 1.0, "x_dot": 0.0}, params={"mass": 1.0, "k": 1.0}, progress=False,
            workers=0)
OVER = {"k": [1.0, 4.0]}


def mark_call(traj):
    """One file per computed run in $SWEEP_MARKS."""
    Path(os.environ["SWEEP_MARKS"], uuid.uuid4().hex).touch()
    return 0.0


@pytest.fixture
def marks(tmp_path, monkeypatch):
    d = tmp_path / "marks"
    d.mkdir()
    monkeypatch.setenv("SWEEP_MARKS", str(d))
    return lambda: len(list(d.iterdir()))


STIFFER = lg.System([x], bodies=[lg.Particle(mass, (x,))], V=k * x**2)  # V changed: ω = √(2k)


@pytest.mark.parametrize("change", [
    {"t_end": 2.0},
    {"system": STIFFER},
    {"rtol": 1e-6},
    {"method": "RK45"},
    {"initial": {"x": 0.5, "x_dot": 0.0}},
    {"params": {"mass": 2.0, "k": 1.0}},
])
def test_resume_recomputes_runs_of_another_configuration(tmp_path, marks, change):
    store = tmp_path / "runs.csv"
    first = lg.sweep(OSC, OVER, summaries=[mark_call], store=store, **BASE)
    assert marks() == 2 and first["run_config"].nunique() == 1
    kw = {**BASE, **{k_: v for k_, v in change.items() if k_ != "system"}}
    system = change.get("system", OSC)
    resumed = lg.sweep(system, OVER, summaries=[mark_call], store=store, resume=True, **kw)
    assert marks() == 4  # nothing stale reused: both runs computed again
    fresh = lg.sweep(system, OVER, summaries=[mark_call], **kw)
    assert marks() == 6
    cols = ["run_id", "k", "status", "t_final", "final_x", "final_x_dot", "run_config"]
    assert resumed[cols].values.tolist() == fresh[cols].values.tolist()
    assert (resumed["run_config"] != first["run_config"]).all()
    # the truth: x = x0 cos(ω t) with ω = √(k/m) (√(2k/m) for the stiffer V)
    x0 = kw["initial"]["x"]
    m_ = kw["params"]["mass"]
    w = np.sqrt((2 if system is STIFFER else 1) * resumed["k"] / m_)
    assert np.allclose(resumed["final_x"], x0 * np.cos(w * kw["t_end"]), atol=1e-5)
    again = lg.sweep(system, OVER, summaries=[mark_call], store=store, resume=True, **kw)
    assert marks() == 6 and again[cols].values.tolist() == fresh[cols].values.tolist()  # same config: reused


def test_run_config_is_stable_and_sensitive():
    from lagrange.sweep.task import SimulationTask

    def make(**kw):
        return SimulationTask(OSC, kw.pop("t_end", 1.0), {"x": 1.0, "x_dot": 0.0}, {"mass": 1.0, "k": 1.0}, **kw)

    a, b = make(), make()
    assert run_config(a) == run_config(b) == run_config(pickle.loads(pickle.dumps(a)))
    assert run_config(make(t_end=1.5)) != run_config(a)
    assert run_config(make(options={"atol": 1e-8})) != run_config(a)


def test_reserved_point_names_are_refused():
    status, final_x = lg.parameters("status final_x")
    s = lg.System([x], bodies=[lg.Particle(1, (x,))], V=status * final_x * x**2 / 2)
    base = dict(t_end=1.0, initial={"x": 1.0, "x_dot": 0.0}, progress=False, workers=0)
    with pytest.raises(SweepError, match="'status'.*reserved"):
        lg.sweep(s, {"status": [1.0, 2.0]}, params={"final_x": 1.0}, **base)
    with pytest.raises(SweepError, match="'final_x'.*reserved"):
        lg.sweep(s, {"final_x": [1.0, 2.0]}, params={"status": 1.0}, **base)
    with pytest.raises(SweepError, match="'run_config'"):
        lg.sweep(_square, {"run_config": [1.0]}, progress=False, workers=0)


def _square(point):
    return {"y": point["a"] ** 2}


def _clashing(point):
    return {"status": "fine", "a": -1.0, "y": 1.0}


def k_(traj):  # a summary column named like the swept parameter
    return 0.0


k_.__name__ = "k"


def test_result_columns_never_overwrite_the_point_or_the_status():
    table = lg.sweep(_clashing, {"a": [1.0, 2.0]}, progress=False, workers=0)
    assert table["a"].tolist() == [1.0, 2.0] and (table["status"] == "error").all()
    assert table["error"].str.contains("'status', 'a'").all()
    osc = lg.sweep(OSC, OVER, summaries=[k_], **BASE)
    assert osc["k"].tolist() == [1.0, 4.0] and (osc["status"] == "error").all()
    assert osc["error"].str.contains("'k'").all()


# --- Dask worker deaths: attribute KilledWorker to the run that crashes ----------------------------------

class KilledWorker(Exception):
    """Stands for distributed's KilledWorker (matched by name, as the executor does)."""


def _crash_at_2(point):
    if point["a"] == 2.0:
        os._exit(7)
    return {"y": point["a"] ** 2}


class SharedWorkerDies(Executor):
    """A cluster on which every run shares the one worker that the crashing run kills: each gets
    KilledWorker, as Dask reports it when a task was on a worker that died too often."""

    def __init__(self):
        self.submitted = 0

    def submit(self, fn, *args, **kwargs):
        self.submitted += 1
        fut = Future()
        fut.set_exception(KilledWorker("Attempted to run task on 4 different workers, all of which died"))
        return fut


def test_killed_worker_is_attributed_to_the_crashing_run():
    ex = SharedWorkerDies()
    table = lg.sweep(_crash_at_2, {"a": [1.0, 2.0, 3.0]}, executor=ex, workers=2, progress=False)
    assert ex.submitted == 3
    assert table["status"].tolist() == ["ok", "died", "ok"], table
    assert table["y"].tolist()[::2] == [1.0, 9.0] and "again when run alone" in table["error"][1]


# --- unpickled tasks are released -------------------------------------------------------------------------

def test_workers_keep_few_unpickled_tasks(monkeypatch):
    monkeypatch.setattr(task_module, "_TASKS", type(task_module._TASKS)())
    payload = pickle.dumps(_square)
    for token in ("s1", "s2", "s3"):
        row = task_module.execute(payload, token, "r", {"a": 3.0})
        assert row["y"] == 9.0
    assert list(task_module._TASKS) == ["s2", "s3"]  # the oldest was released
    assert task_module.release_task("s3") and not task_module.release_task("s1")
    assert list(task_module._TASKS) == ["s2"]


def test_dask_client_releases_the_task():
    calls = []

    class FakeClient:
        __module__ = "distributed.client"

        def run(self, fn, *args):
            calls.append((fn, args))

    ex = SharedWorkerDies()
    ex._client = FakeClient()
    run_points(b"", "tok", [], executor=ex, workers=1, on_row=lambda row: None)
    assert calls == [(task_module.release_task, ("tok",))]


# --- Ctrl-C stops a sweep at once --------------------------------------------------------------------------

@pytest.mark.slow
def test_ctrl_c_stops_a_process_pool_sweep(tmp_path):
    store = tmp_path / "runs.csv"
    child = textwrap.dedent(f"""\
        import sys, time
        import lagrange as lg
        def slow(point):
            if point["a"] > 1:
                time.sleep(3600)
            return {{"y": point["a"]}}
        print("READY", flush=True)
        try:
            lg.sweep(slow, {{"a": [0.0, 1.0, 2.0, 3.0]}}, workers=2, store={str(store)!r}, progress=False)
        except KeyboardInterrupt:
            print("INTERRUPTED", flush=True)
            sys.exit(130)
    """)
    proc = subprocess.Popen([sys.executable, "-c", child], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # Ctrl-C as from a
    try:  # terminal, even when the tests run in the background (which starts children with SIGINT ignored)
        assert proc.stdout.readline().startswith("READY")
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not (store.exists() and store.read_text().count("\n") >= 3):
            time.sleep(0.2)
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)  # to the parent only: its workers are sleeping for an hour
        ready, _, _ = select.select([proc.stdout], [], [], 120)  # never wait forever for the reply
        assert ready, "no reply 120 s after SIGINT: the sweep went on running"
        reply = proc.stdout.readline()
        proc.communicate(timeout=60)
        delay = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
    assert reply.startswith("INTERRUPTED") and proc.returncode == 130
    assert delay < 20
    import pandas as pd

    assert sorted(pd.read_csv(store)["a"]) == [0.0, 1.0]  # the finished rows are kept for resume=True


def _crash_at_2_slowly(point):
    time.sleep(1.0)  # the healthy runs are on the worker when the crashing one kills it
    return _crash_at_2(point)


@pytest.mark.slow
def test_killed_worker_on_a_dask_cluster_blames_only_the_crashing_run():
    distributed = pytest.importorskip("distributed")
    import dask

    with dask.config.set({"distributed.scheduler.allowed-failures": 0}), \
            distributed.LocalCluster(n_workers=1, processes=True, threads_per_worker=3,
                                     dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        table = lg.sweep(_crash_at_2_slowly, {"a": [1.0, 2.0, 3.0]}, executor=client, progress=False)
    assert table["status"].tolist() == ["ok", "died", "ok"], table[["a", "status", "error"]]
    assert table["y"].tolist()[::2] == [1.0, 9.0]


# ----- functions identified by what they compute ---------------------------------------------------------------
def _config(*summaries):
    from lagrange.sweep.task import SimulationTask

    return run_config(SimulationTask(OSC, 1.0, {"x": 1.0, "x_dot": 0.0}, {"mass": 1.0, "k": 1.0},
                                     summaries=summaries))


def _module_function(source: str, name: str, module: str = "user_summaries", **globals_):
    """``name`` from ``source`` executed as the module ``module`` with the given globals (a user's file)."""
    namespace = {"__name__": module, **globals_}
    exec(compile(source, f"{module}.py", "exec"), namespace)  # noqa: S102 - the test's own source
    return namespace[name]


def test_functions_are_identified_by_code_closure_defaults_and_globals():
    from lagrange.sweep.identity import describe

    def final(tr):
        return float(tr.y[-1, 0])

    assert _config(final) == _config(final)  # the same function twice
    assert _config(lambda tr: float(tr.t[-1])) == _config(lambda tr: float(tr.t[-1]))  # same body, same code
    assert _config(lambda tr: float(tr.t[-1])) != _config(lambda tr: float(tr.t[0]))  # every lambda looks alike
    assert _config(lambda tr: 2.0 * tr.t[-1]) != _config(lambda tr: 3.0 * tr.t[-1])  # a changed constant

    def scaled(c):
        return lambda tr: c * tr.t[-1]

    assert _config(scaled(2.0)) == _config(scaled(2.0)) and _config(scaled(2.0)) != _config(scaled(3.0))
    assert describe(lambda tr, c=1.0: c) != describe(lambda tr, c=2.0: c)  # defaults
    # a global of the user's module, and a helper function of that module, by value and by code
    src = "def helper(tr):\n    return {body}\n\ndef summary(tr):\n    return SCALE * helper(tr)\n"
    base = _module_function(src.format(body="tr.t[-1]"), "summary", SCALE=2.0)
    assert _config(base) == _config(_module_function(src.format(body="tr.t[-1]"), "summary", SCALE=2.0))
    assert _config(base) != _config(_module_function(src.format(body="tr.t[-1]"), "summary", SCALE=3.0))
    assert _config(base) != _config(_module_function(src.format(body="tr.t[0]"), "summary", SCALE=2.0))
    # moving a function in its file changes nothing; recursion terminates
    moved = _module_function("\n\n\n" + src.format(body="tr.t[-1]"), "summary", SCALE=2.0)
    assert _config(base) == _config(moved)
    rec = _module_function("def f(n):\n    return 1 if n < 1 else n * f(n - 1)\n", "f")
    assert describe(rec) == describe(_module_function("def f(n):\n    return 1 if n < 1 else n * f(n - 1)\n", "f"))


def test_resume_recomputes_rows_after_a_summary_lambda_changed(tmp_path):
    store = tmp_path / "runs.csv"
    first = lg.sweep(OSC, OVER, summaries=[lambda tr: float(tr.y[-1, 0])], store=store, **BASE)
    resumed = lg.sweep(OSC, OVER, summaries=[lambda tr: 2.0 * float(tr.y[-1, 0])], store=store, resume=True,
                       **BASE)
    assert np.allclose(resumed["<lambda>"], 2.0 * first["<lambda>"]) and np.all(first["<lambda>"] != 0)
    assert (resumed["run_config"] != first["run_config"]).all()


def test_misspelt_option_fails_once_before_any_run(marks):
    with pytest.raises(SweepError, match=r"'rtoll' \(did you mean 'rtol'"):
        lg.sweep(OSC, OVER, summaries=[mark_call], rtoll=1e-6, **BASE)
    assert marks() == 0
    with pytest.raises(SweepError, match="'colour'"):
        lg.sweep(OSC, OVER, summaries=[mark_call], colour="red", method="RK45", **BASE)
    assert marks() == 0
    table = lg.sweep(OSC, OVER, summaries=[mark_call], rtol=1e-6, method="RK45", **BASE)  # known options run
    assert marks() == 2 and (table["status"] == "ok").all()
