"""The same sweep on a Dask LocalCluster of processes (Client and its executor) as on the local process pool."""

import pandas as pd
import pytest

import lagrange as lg
from lagrange.sweep.greenspan_map import stability_task

distributed = pytest.importorskip("distributed")

x = lg.coordinates("x")
k, mass = lg.parameters("k mass")
OSC = lg.System([x], bodies=[lg.Particle(mass, (x,))], V=k * x**2 / 2)
BASE = dict(t_end=2.0, initial={"x": 1.0, "x_dot": 0.0}, params={"mass": 1.0, "k": 1.0}, progress=False)
OVER = {"k": [1.0, 4.0, 9.0], "mass": [0.0, 1.0, 2.0]}  # mass 0: an error row must travel back too


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cl:
        with distributed.Client(cl) as c:
            yield c


def _results(table):
    return table.drop(columns=["wall_time", "run_config"])


def test_dask_client_and_executor_match_the_local_pool(client):
    local = lg.sweep(OSC, OVER, workers=2, **BASE)
    on_client = lg.sweep(OSC, OVER, executor=client, **BASE)
    on_executor = lg.sweep(OSC, OVER, executor=client.get_executor(), **BASE)
    assert (local["status"] == "error").sum() == 3 and (local["status"] == "ok").sum() == 6
    pd.testing.assert_frame_equal(_results(on_client), _results(local))
    pd.testing.assert_frame_equal(_results(on_executor), _results(local))


@pytest.mark.slow
def test_greenspan_map_on_the_cluster(client):
    task = stability_task(20.0)
    over = {"V": [1.0, 4.0], "alpha_deg": [15.0]}
    remote = lg.sweep(task, over, executor=client, progress=False)
    local = lg.sweep(task, over, workers=0, progress=False)
    pd.testing.assert_frame_equal(_results(remote), _results(local))
    assert remote["fell"].tolist() == [True, False]  # Greenspan's example 10 falls, example 1 does not
