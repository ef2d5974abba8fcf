"""Work-precision figures of a benchmark problem (from the dict of :func:`lagrange.bench.report.results_data`).

Panels: final error against wall time, final error against right-hand-side evaluations (methods that
report them), and — for conservative problems with a long run — relative energy error against time.
Log-log axes; one curve per method; line styles group the routes (lagrange scipy loop solid, compiled loop
dash-dot, geometric dotted, plain sympy dashed grey, heyoka black).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["plot_work_precision"]


def _style(curve: dict) -> dict:
    if curve["kind"] == "heyoka":
        return {"color": "black", "marker": "*", "linestyle": "-"}
    if curve["kind"] == "sympy":
        return {"color": "0.55", "marker": "s", "linestyle": "--"}
    if curve["kind"] == "fixed":
        return {"marker": "^", "linestyle": ":"}
    if curve.get("loop") == "compiled":
        return {"marker": "D", "linestyle": "-."}
    return {"marker": "o", "linestyle": "-" if curve["backend"] == "numba" else "--"}


def plot_work_precision(problem: dict, path: str | Path | None = None, *, dpi: int = 110):
    """Draw the work-precision panels of one problem; write a PNG when ``path`` is given.

    Returns the matplotlib Figure.
    """
    from matplotlib import colormaps

    from .trajectory import new_figure

    curves = [c for c in problem["curves"] if c["points"]]
    panels = 3 if problem.get("energy") else 2
    fig = new_figure(path, figsize=(6.2 * panels, 6.2), layout="constrained")  # file: no pyplot, backend untouched
    axes = fig.subplots(1, panels)
    for ax in axes[:2]:
        ax.set_prop_cycle(color=colormaps["tab20"].colors)
    for c in curves:
        err = [max(p["error"], 1e-17) for p in c["points"]]
        axes[0].loglog(err, [p["wall"] * 1e3 for p in c["points"]], label=c["label"], ms=4, **_style(c))
        with_nfev = [(e, p["nfev"]) for e, p in zip(err, c["points"]) if p["nfev"]]
        if with_nfev:
            axes[1].loglog(*zip(*with_nfev), label=c["label"], ms=4, **_style(c))
    axes[0].set_xlabel("final error (max norm)")
    axes[0].set_ylabel("wall time [ms] (median)")
    axes[0].set_title("error vs wall time")
    axes[1].set_xlabel("final error (max norm)")
    axes[1].set_ylabel("right-hand-side evaluations")
    axes[1].set_title("error vs function evaluations")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=6, fontsize="x-small")
    if panels == 3:
        ax = axes[2]
        for e in problem["energy"]:
            t, err = np.asarray(e["t"]), np.asarray(e["error"])
            keep = t > 0
            ax.loglog(t[keep], np.maximum(err[keep], 1e-17), label=e["label"], lw=1)
        ax.set_xlabel("t")
        ax.set_ylabel("|E − E0| / |E0|")
        ax.set_title("energy error, long run")
        ax.legend(fontsize="x-small")
    fig.suptitle(f"{problem['name']}: {problem['title']}", fontsize="medium")
    if path is not None:
        fig.savefig(path, dpi=dpi)
    return fig
