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


@pytest.fixture
def agrees_with_wells_14_16():
    """A check that a free particle's derived equations in an earth frame are Wells' (14.16)::

        ẍ + 2ω(ż cosΦ − ẏ sinΦ) − ω²x = 0
        ÿ + 2ω ẋ sinΦ + ω² sinΦ (z cosΦ − y sinΦ) = 0
        z̈ − 2ω ẋ cosΦ − ω² cosΦ (z cosΦ − y sinΦ) + g' = 0

    times the mass m (the R ω² terms cancel). Shared by the sphere and the ellipsoid tests."""
    import sympy as sp

    from lagrange import t
    from lagrange.simplification import is_zero

    def check(system, coords, m, w, Phi, gp):
        x, y, z = coords
        book = [
            x.diff(t, 2) + 2 * w * (z.diff(t) * sp.cos(Phi) - y.diff(t) * sp.sin(Phi)) - w**2 * x,
            y.diff(t, 2) + 2 * w * x.diff(t) * sp.sin(Phi)
            + w**2 * sp.sin(Phi) * (z * sp.cos(Phi) - y * sp.sin(Phi)),
            z.diff(t, 2) - 2 * w * x.diff(t) * sp.cos(Phi)
            - w**2 * sp.cos(Phi) * (z * sp.cos(Phi) - y * sp.sin(Phi)) + gp,
        ]
        acc = sp.Matrix([c.diff(t, 2) for c in coords])
        M_, f_ = system.mass_matrix, system.forcing
        for i in range(3):
            derived = (M_[i, :] * acc)[0, 0] - f_[i]
            assert is_zero(derived - m * book[i]), f"equation {i + 1} of (14.16)"

    return check
