import os

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _isolated_cache(tmp_path_factory, monkeypatch):
    """Generated numba modules go to a per-session temporary cache directory."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path_factory.getbasetemp() / "lagrange-cache"))
    os.environ.setdefault("OMP_NUM_THREADS", "1")
