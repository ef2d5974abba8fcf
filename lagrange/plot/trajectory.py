"""Standard figure of a trajectory: each coordinate against time, phase portraits, energy balance, λ.

Backend policy (every function of :mod:`lagrange.plot`): the user's matplotlib backend is never changed.
A figure written to a file is a :class:`matplotlib.figure.Figure` on its own Agg canvas, outside pyplot's
list of figures, so it works headless and leaves an inline Jupyter session alone; a figure returned for
display is made by pyplot, so it shows the way the user's backend shows figures; with ``ax=`` the curves
go on the user's axes and nothing else is created.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..errors import LagrangeError
from ..model.coordinates import canonical_key, coordinate_name, is_coordinate

__all__ = ["plot_trajectory", "select_coordinates", "new_figure", "multiplier_labels", "PlotError"]


class PlotError(LagrangeError, ValueError):
    """A plot was asked for something the trajectory does not have (coordinate, axes count)."""


def select_coordinates(traj, coordinates=None) -> list[int]:
    """Indices (into ``traj.coordinates``) of the coordinates selected by ``coordinates``.

    Parameters
    ----------
    traj : Trajectory
    coordinates : None (all), or a sequence of coordinate functions, their names (``"theta"``) or indices

    Raises
    ------
    PlotError
        naming the entry that is not a coordinate of the trajectory, and the coordinates it has.
    """
    n = traj.model.n
    if coordinates is None:
        return list(range(n))
    if isinstance(coordinates, (str, int)) or is_coordinate(canonical_key(coordinates)):
        coordinates = [coordinates]
    names = [coordinate_name(c) for c in traj.coordinates]
    out = []
    for given in coordinates:
        c = canonical_key(given, traj.coordinates)  # dynamicsymbols
        if isinstance(c, str) and c in names:
            out.append(names.index(c))
        elif isinstance(c, (int, np.integer)) and not isinstance(c, bool) and -n <= c < n:
            out.append(int(c) % n)
        elif is_coordinate(c) and c in traj.coordinates:
            out.append(traj.coordinates.index(c))
        else:
            raise PlotError(f"cannot plot {given!r}: not a coordinate of this trajectory "
                            f"(coordinates: {', '.join(names)}; give names, coordinates or indices)")
    if not out:
        raise PlotError("coordinates=[] selects nothing to plot")
    return out


def multiplier_labels(traj) -> list[str]:
    """``λ[name]`` for every constraint of the trajectory's model, in multiplier order."""
    return [f"λ[{name}]" for name in traj.model.equations.constraint_names]


def new_figure(path, **kwargs):
    """A Figure: on its own Agg canvas (no pyplot state) when it is to be written to ``path``, else from
    pyplot (shown by the user's backend, inline in Jupyter)."""
    if path is not None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fig = Figure(**kwargs)
        FigureCanvasAgg(fig)
        return fig
    import matplotlib.pyplot as plt

    return plt.figure(**kwargs)


def _as_axes_list(ax, k: int) -> list:
    """The user's ``ax=``: one Axes for every curve, or a sequence with one Axes per selected coordinate."""
    if isinstance(ax, np.ndarray):
        ax = list(ax.ravel())
    if isinstance(ax, Sequence):
        ax = list(ax)
        if len(ax) != k:
            raise PlotError(f"ax= has {len(ax)} axes for {k} selected coordinate(s): give one Axes, or one per "
                            "coordinate")
        return ax
    return [ax] * k


def _time_series(traj, idx: list[int], axes: list) -> None:
    names = traj.names
    shared = len(set(map(id, axes))) < len(axes)
    for j, (i, a) in enumerate(zip(idx, axes)):
        a.plot(traj.t, traj.y[:, i], color=f"C{j % 10}", label=names[i])
        if shared:
            a.set_ylabel("coordinates")
            a.legend(loc="best", fontsize="small")
        else:
            a.set_ylabel(names[i])
    for a in axes:
        a.set_xlabel("t")


def plot_trajectory(traj, path: str | Path | None = None, *, coordinates=None, ax=None, title: str | None = None,
                    dpi: int = 120, figsize: tuple[float, float] | None = None):
    """Plot a trajectory; write a PNG when ``path`` is given; return the Figure.

    Without ``ax``: a figure whose left column stacks one panel per selected coordinate ``q(t)`` (shared
    time axis), and whose right column shows the phase portraits ``(q, q̇)``, the power-balance residual
    ``|h − h₀ − ∫ dh/dt| / max|h|`` (:meth:`Trajectory.power_balance`) and, with constraints, the
    multipliers labelled ``λ[constraint name]``. The title is ``title``, else the system's name.

    With ``ax`` (one Axes, or one per selected coordinate): only the time series are drawn there, nothing
    else is created; returns the Axes' figure.

    Parameters
    ----------
    traj : Trajectory
    path : PNG file to write (the figure is then made outside pyplot and the backend is never touched)
    coordinates : coordinates to plot, by function, name or index (default: all), see
        :func:`select_coordinates`
    ax : matplotlib Axes or sequence of Axes
    title, dpi, figsize : figure title (default: the system's name), PNG resolution, figure size

    Raises
    ------
    PlotError (a LagrangeError and ValueError)
        unknown coordinate, or a number of axes that does not match the selection.
    """
    idx = select_coordinates(traj, coordinates)
    if ax is not None:
        axes = _as_axes_list(ax, len(idx))
        _time_series(traj, idx, axes)
        fig = axes[0].figure
        if path is not None:
            fig.savefig(path, dpi=dpi)
        return fig
    k = len(idx)
    side = 3 if traj.model.m else 2
    fig = new_figure(path, figsize=figsize or (12, max(4.0, 1.6 * max(k, side))), layout="constrained")
    left, right = fig.subfigures(1, 2, width_ratios=[3, 2])
    axes = list(np.atleast_1d(left.subplots(k, 1, sharex=True)))
    _time_series(traj, idx, axes)
    for a in axes[:-1]:
        a.set_xlabel("")
    panels = np.atleast_1d(right.subplots(side, 1))
    names = traj.names
    n = traj.model.n
    a = panels[0]
    for j, i in enumerate(idx):
        a.plot(traj.y[:, i], traj.y[:, n + i], color=f"C{j % 10}", label=names[i])
    a.set_xlabel("q")
    a.set_ylabel("q̇")
    a.set_title("phase portrait", fontsize="medium")
    a.legend(loc="best", fontsize="small")
    a = panels[1]
    scale = max(float(np.max(np.abs(traj.jacobi))), 1e-300)
    a.semilogy(traj.t, np.abs(traj.power_balance()) / scale + 1e-18)
    a.set_xlabel("t")
    a.set_ylabel("|h − h₀ − ∫ ḣ dt| / max|h|")
    a.set_title("power balance", fontsize="medium")
    if traj.model.m:
        a = panels[2]
        for j, label in enumerate(multiplier_labels(traj)):
            a.plot(traj.t, traj.multipliers[:, j], label=label)
        a.set_xlabel("t")
        a.set_ylabel("λ")
        a.set_title("constraint multipliers", fontsize="medium")
        a.legend(loc="best", fontsize="small")
    fig.suptitle(title or traj.model.equations.name or "trajectory")
    if path is not None:
        fig.savefig(path, dpi=dpi)
    return fig
