"""What the benchmark runner and its companions (first result, long runs) share: the initial state of a problem,
the energy-error record of a long run, whether numba is here. Its own module, so that none of them imports the
runner that imports them."""

from __future__ import annotations

import numpy as np

from ..records import record
from .problems import BenchProblem

__all__ = ["EnergyRun", "initial_vector"]


@record(frozen=True)
class EnergyRun:
    """Relative energy error ``|E(t) − E(0)| / |E(0)|`` along a long run."""

    label: str
    t: np.ndarray
    error: np.ndarray
    wall: float


def initial_vector(problem: BenchProblem, system) -> np.ndarray:
    """``y0 = [q, q̇]`` of ``problem`` in the order of the system's coordinates."""
    names = [c.func.__name__ for c in system.derived.coordinates]
    return np.array([problem.initial[n] for n in names] + [problem.initial[n + "_dot"] for n in names], dtype=float)


def _numba_ok() -> bool:
    import importlib.util

    return importlib.util.find_spec("numba") is not None
