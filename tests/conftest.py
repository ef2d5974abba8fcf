import os

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _isolated_cache(tmp_path_factory, monkeypatch):
    """Generated numba modules go to a per-session temporary cache directory.

    Under pytest-xdist the workers of one session share it (the parent of each worker's base temporary
    directory), so numba's loops and kernels are compiled once per session, not once per worker; the cache is
    built for concurrent writers (atomic replaces, tested in tests/test_cache.py)."""
    base = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        base = base.parent
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(base / "lagrange-cache"))
    os.environ.setdefault("OMP_NUM_THREADS", "1")
