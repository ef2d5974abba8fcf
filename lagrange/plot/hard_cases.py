"""The figure of one hard case (from :func:`lagrange.bench.hard.run_hard_suite`): relative error against CPU
time, one point per method and tolerance, log-log. Filled markers: the run's verdict says accurate; open
markers: the run flagged itself; a red cross: silently wrong (accurate by its verdict, wrong by the reference).
Refused and errored runs have no point (the table names them).
"""

from __future__ import annotations

import math
from pathlib import Path

__all__ = ["plot_hard_case"]

_MARKERS = "osD^v<>ph*XP8H"


def plot_hard_case(runs, title: str, path: str | Path | None = None, *, dpi: int = 110):
    """Draw error against CPU for the ``runs`` (:class:`~lagrange.bench.hard.HardRun`) of one problem; write a
    PNG when ``path`` is given. Returns the matplotlib Figure."""
    from matplotlib import colormaps

    from .trajectory import new_figure

    fig = new_figure(path, figsize=(7.5, 5.5), layout="constrained")
    ax = fig.subplots()
    methods = list(dict.fromkeys(r.method for r in runs))
    colors = colormaps["tab20"].colors
    for i, method in enumerate(methods):
        pts = [r for r in runs if r.method == method and math.isfinite(r.error) and math.isfinite(r.cpu)]
        for r in pts:
            color = colors[i % len(colors)]
            style = {"marker": _MARKERS[i % len(_MARKERS)], "color": color, "markersize": 7, "linestyle": "none"}
            if r.outcome == "flagged":
                style["markerfacecolor"] = "none"
            if r.outcome == "SILENTLY WRONG":
                ax.plot(r.cpu, max(r.error, 1e-17), marker="x", color="red", markersize=14, linestyle="none")
            ax.plot(r.cpu, max(r.error, 1e-17), label=f"{method} rtol {r.rtol:.0e}", **style)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("CPU time [s] (process_time)")
    ax.set_ylabel("relative error against the reference")
    ax.set_title(title, fontsize="small")
    if ax.lines:
        ax.legend(fontsize="x-small", ncol=2)
    if path is not None:
        fig.savefig(path, dpi=dpi)
    return fig
