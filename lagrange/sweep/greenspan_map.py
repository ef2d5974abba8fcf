r"""Stability map of Greenspan's tetrahedral top: which spins V and tilts α fall within a time.

The top (:mod:`lagrange.discrete.greenspan`) starts tilted by α in the XZ plane, spinning so that P2, P3,
P4 move with speed V about its axis; it *falls* when one of the weighted vertices P2, P3, P4 reaches the
plane z = 0 (the paper's stopping rule). The map uses the 5-degree-of-freedom rigid model (tip X, Y on
the plane, Wells' Euler angles ψ, θ, φ), which agrees with the paper's molecular model to 1e-2 or better
in the contact path and gives the same fall time for example 10 (``benchmarks/results/greenspan.md``), at a
fraction of its cost: a run that falls stops at the fall (a terminal event), one that does not costs
about 1 s of DOP853 for t = 110.

Columns added to the sweep table: ``fell`` (bool), ``fall_time`` (NaN if it did not fall) and
``zbar_min``, the lowest height of the geometric centre Pbar at the ``n_points`` output times and the fall,
:math:`\bar z = \tfrac{\sqrt6}{4} R\cos\theta` (the centroid of the body frame is on its z axis).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from ..discrete import greenspan as gs
from ..model.coordinates import to_symbols
from ..safe_sympify import lambdify as _lambdify
from .task import SimulationTask

__all__ = ["top_setup", "fall_events", "fall_summary", "stability_task", "stability_map"]


def top_setup(system, point: Mapping[str, float]) -> tuple[dict, dict]:
    """Initial state of the rigid top for the point's spin ``V`` and tilt ``alpha_deg`` (degrees)."""
    ex = gs.Example(0, float(point["V"]), float(point["alpha_deg"]))
    return gs.rigid_initial(ex, system.coordinates), {}


def fall_events(system) -> list:
    """Terminal events: the height of P2, P3 or P4 crossing zero downwards."""
    syms = [to_symbols(q, system.coordinates) for q in system.coordinates]
    heights = [to_symbols(b.position[2], system.coordinates) for b in system.bodies[1:]]
    z = _lambdify(syms, heights, "math")
    n = len(syms)
    events = []
    for i in range(len(heights)):
        def ev(t_, y, i=i):
            return float(z(*y[:n])[i])

        ev.terminal = True
        ev.direction = -1
        events.append(ev)
    return events


def fall_summary(traj) -> dict:
    """``fell``, ``fall_time`` (NaN when it did not fall) and ``zbar_min`` of a rigid-top trajectory."""
    times = [float(e[0]) for e in traj.t_events if len(e)]
    col = traj.names.index("theta")
    theta = np.concatenate([traj.y[:, col], *(ye[:, col] for ye in traj.y_events if len(ye))])
    zbar = gs.EDGE * math.sqrt(6.0) / 4 * np.cos(theta)
    return {"fell": bool(times), "fall_time": min(times) if times else math.nan, "zbar_min": float(zbar.min())}


def stability_task(t_end: float = 110.0, *, rtol: float = 1e-8, atol: float = 1e-10, backend: str = "python",
                   masses: Sequence[float] = (1.0, 1.0, 1.0, 1.0), n_points: int = 2201, **options) -> SimulationTask:
    """The sweep task ``point {V, alpha_deg} → row`` of the rigid top (system compiled once, here); ``options``
    go to :func:`~lagrange.integrate.run.simulate` (``method`` …)."""
    system, coords = gs.rigid_system(tuple(masses))
    base = gs.rigid_initial(gs.EXAMPLES[1], coords)
    return SimulationTask(system, t_end, base, {"g": gs.G},
                          options={"rtol": rtol, "atol": atol, "n_points": n_points, **options},
                          summaries=[fall_summary], setup=top_setup, events=fall_events, backend=backend)


def stability_map(V: Sequence[float], alpha_deg: Sequence[float], *, t_end: float = 110.0, rtol: float = 1e-8,
                  atol: float = 1e-10, backend: str = "python", **sweep_options):
    """Sweep the grid ``V × alpha_deg`` of the rigid top over [0, t_end]; returns the table of
    :func:`lagrange.sweep` with the columns ``fell``, ``fall_time``, ``zbar_min``.

    ``sweep_options`` go to :func:`lagrange.sweep` (``workers``, ``executor``, ``store``, ``resume``, …).
    """
    from .driver import sweep

    task = stability_task(t_end, rtol=rtol, atol=atol, backend=backend)
    return sweep(task, {"V": V, "alpha_deg": alpha_deg}, **sweep_options)
