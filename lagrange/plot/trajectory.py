"""Standard figure of a trajectory: coordinates against time, phase portraits, energy balance."""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["plot_trajectory"]


def plot_trajectory(traj, path: str | Path | None = None, *, title: str | None = None, dpi: int = 120):
    """Three panels: q(t); phase portraits (q, q̇); power-balance residual h − h0 − ∫dh/dt.

    Writes a PNG when ``path`` is given (headless backend) and returns the matplotlib Figure.
    """
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    names = traj.names
    n = traj.model.n
    fig, axes = plt.subplots(1, 3, figsize=(14, 4), constrained_layout=True)
    ax = axes[0]
    for i in range(n):
        ax.plot(traj.t, traj.y[:, i], label=names[i])
    ax.set_xlabel("t")
    ax.set_ylabel("coordinates")
    ax.legend(loc="best", fontsize="small")
    ax.set_title("coordinates")
    ax = axes[1]
    for i in range(n):
        ax.plot(traj.y[:, i], traj.y[:, n + i], label=f"{names[i]}")
    ax.set_xlabel("q")
    ax.set_ylabel("q̇")
    ax.set_title("phase portrait")
    ax.legend(loc="best", fontsize="small")
    ax = axes[2]
    res = traj.power_balance()
    scale = max(float(np.max(np.abs(traj.jacobi))), 1e-300)
    ax.semilogy(traj.t, np.abs(res) / scale + 1e-18)
    ax.set_xlabel("t")
    ax.set_ylabel("|h − h₀ − ∫ dh/dt| / max|h|")
    ax.set_title("energy / power balance error")
    fig.suptitle(title or traj.model.equations.name or "trajectory")
    if path is not None:
        fig.savefig(path, dpi=dpi)
        plt.close(fig)
    return fig
