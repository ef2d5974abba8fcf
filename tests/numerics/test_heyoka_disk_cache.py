"""heyoka's compiled integrators kept in the sealed on-disk cache (lagrange/codegen/heyoka_jit.py).

A second process running the same model loads the integrator instead of compiling it (and without converting
the equations to heyoka expressions; counted by
``heyoka_backend.compilations`` / ``disk_loads`` and said in the result's message) and gives the same numbers;
an entry that fails authentication is never unpickled but rebuilt (CacheIntegrityWarning, the cache's policy),
a cache directory others can write is refused with CacheError; events are part of the key.
"""

import json
import os
import pickle
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import lagrange.codegen.cache as lc
from lagrange.errors import CacheError, CacheIntegrityWarning
from lagrange.examples import n_link_pendulum

hy = pytest.importorskip("heyoka")
from lagrange.codegen import heyoka_jit  # noqa: E402
from lagrange.integrate import heyoka_backend  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
RUN = """
import json
from lagrange.examples import n_link_pendulum
from lagrange.codegen import heyoka_expr
from lagrange.integrate import heyoka_backend
sol = n_link_pendulum(2).simulate(2.0, {"q1": 1.0, "q2": -0.5, "q1_dot": 0.0, "q2_dot": 0.3}, {"g": 9.81},
                                  method="heyoka", rtol=1e-12, atol=1e-12, n_points=5)
print(json.dumps({"compiled": heyoka_backend.compilations(), "loaded": heyoka_backend.disk_loads(),
                  "converted": len(heyoka_expr._ODES),
                  "message": sol.message, "y": sol.y[-1].tolist()}))
"""


def _fresh_process(cache: Path) -> dict:
    env = {**os.environ, "LAGRANGE_CACHE_DIR": str(cache),
           "PYTHONPATH": os.pathsep.join([str(ROOT / ".pp"), os.environ.get("PYTHONPATH", "")])}
    out = subprocess.run([sys.executable, "-c", RUN], env=env, capture_output=True, text=True, timeout=300,
                         check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_a_fresh_process_loads_the_compiled_integrator_from_disk(tmp_path):
    cache = tmp_path / "cache"
    first = _fresh_process(cache)
    assert (first["compiled"], first["loaded"], first["converted"]) == (1, 0, 1)
    assert "compiled by LLVM" in first["message"]
    assert len(list(cache.glob("heyoka_*.pkl"))) == 1
    second = _fresh_process(cache)
    assert (second["compiled"], second["loaded"], second["converted"]) == (0, 1, 0)  # no CSE, no conversion
    assert "loaded from the on-disk cache" in second["message"]
    assert second["y"] == first["y"]  # the same compiled code, bit for bit


PEND = (1.0, {"q1": 1.0, "q1_dot": 0.0}, {"g": 9.81})


def _run(events=()):
    return n_link_pendulum(1).simulate(*PEND, method="heyoka", rtol=1e-12, atol=1e-12, n_points=5,
                                       events=list(events) or None)


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty cache directory, nothing kept in memory, the once-per-process warning re-armed."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(lc, "_warned", False)
    heyoka_backend._INTEGRATORS.clear()
    yield tmp_path / "cache"
    heyoka_backend._INTEGRATORS.clear()


def test_a_tampered_entry_is_never_unpickled_and_is_rebuilt(fresh, monkeypatch):
    ref = _run()
    (entry,) = fresh.glob("heyoka_*.pkl")
    raw = bytearray(entry.read_bytes())
    raw[-100] ^= 0x01  # one bit of the pickled object code
    entry.write_bytes(bytes(raw))
    heyoka_backend._INTEGRATORS.clear()
    loads = []
    spy = SimpleNamespace(loads=lambda data: loads.append(data) or pickle.loads(data), dumps=pickle.dumps,
                          HIGHEST_PROTOCOL=pickle.HIGHEST_PROTOCOL)
    monkeypatch.setattr(heyoka_jit, "pickle", spy)  # what heyoka_jit unpickles, and nothing else
    before = heyoka_backend.compilations()
    with pytest.warns(CacheIntegrityWarning, match="authentication tag does not match"):
        sol = _run()
    assert not loads and heyoka_backend.compilations() == before + 1
    assert np.array_equal(sol.y, ref.y) and lc.read_verified(entry) is not None  # rewritten, sealed


def test_an_intact_entry_is_loaded_and_events_have_their_own_entries(fresh):
    ref = _run()
    heyoka_backend._INTEGRATORS.clear()
    loaded = heyoka_backend.disk_loads()
    again = _run()
    assert heyoka_backend.disk_loads() == loaded + 1 and np.array_equal(again.y, ref.y)

    def zero(t, y):
        return y[0]

    with_event = _run([zero])
    assert len(list(fresh.glob("heyoka_*.pkl"))) == 2 and with_event.t_events[0].size == 1
    heyoka_backend._INTEGRATORS.clear()
    reloaded = _run([zero])
    assert "loaded from the on-disk cache" in reloaded.message
    assert np.array_equal(reloaded.t_events[0], with_event.t_events[0])


def test_a_cache_directory_others_can_write_is_refused(fresh):
    fresh.mkdir(mode=0o700)
    os.chmod(fresh, 0o777)
    with pytest.raises(CacheError, match="writable by group and others"):
        _run()
