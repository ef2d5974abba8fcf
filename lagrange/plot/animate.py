"""Animations of a simulated system drawn from its own transformation equations.

Particles are dots, rods join consecutive points (``links="chain"``, from the fixed origin) or the pairs
you list, rigid bodies are drawn as their body-axis frame at the centre of mass. 2D when every point
stays in the plane z = 0, 3D otherwise. The result is a matplotlib ``FuncAnimation``; save it as GIF
(Pillow, always available) or MP4 (needs ffmpeg), or show it inline in Jupyter with
:func:`animation_html`.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import LagrangeError
from ..model.coordinates import to_symbols

__all__ = ["animate", "animation_html", "scene_points"]


def _body_points(system):
    """Symbolic points to draw: per body its position vectors, and for rigid bodies their axes."""
    points, frames = [], []
    for b in system.bodies:
        R = getattr(b, "R", None)
        if R is not None:
            c = b.centre_of_mass
            points.append(c)
            frames.append((len(points) - 1, R))
        else:
            points.extend(b.position_vectors())
    return points, frames


def scene_points(system, trajectory) -> tuple[np.ndarray, list]:
    """Positions of the drawn points at every output time, shape (m, k, 3), and the rigid-body axes
    ``[(point index, axes (m, 3, 3))]``."""
    points, frames = _body_points(system)
    if not points:
        raise LagrangeError("nothing to draw: the system has no bodies (T was given directly)")
    coords = system.coordinates
    syms = [to_symbols(q, coords) for q in coords]
    eqs = trajectory.model.equations
    values = dict(zip(eqs.parameters, trajectory.model.params))
    exprs = [to_symbols(P, coords).subs(values) for P in points]
    frames = [(i, to_symbols(R, coords).subs(values)) for i, R in frames]
    unknown = set().union(*(e.free_symbols for e in exprs)) - set(syms) - {t}
    if unknown:
        raise LagrangeError(f"cannot draw: no values for {', '.join(sorted(map(str, unknown)))}")
    f = sp.lambdify([t, syms], [list(e) for e in exprs], "numpy")
    n = len(coords)
    P = np.array([np.array(f(ti, yi[:n]), dtype=float) for ti, yi in zip(trajectory.t, trajectory.y)])
    axes = []
    for idx, R in frames:
        g = sp.lambdify([t, syms], R, "numpy")
        axes.append((idx, np.array([np.array(g(ti, yi[:n]), dtype=float) for ti, yi in zip(trajectory.t,
                                                                                           trajectory.y)])))
    return P, axes


def animate(system, trajectory, path: str | Path | None = None, *, links: str | Sequence = "chain",
            frames: int = 150, fps: int = 25, trail: int = 40, title: str | None = None):
    """Animate ``trajectory`` of ``system``; write it to ``path`` (``.gif`` or ``.mp4``) when given.

    Parameters
    ----------
    links : ``"chain"`` (origin → point 1 → point 2 …), ``"none"``, or a list of index pairs (−1 = origin)
    frames : number of frames (evenly spaced over the output times)
    trail : length of the fading path drawn behind the last point
    """
    import matplotlib

    if path is not None:
        suffix = Path(path).suffix.lower()
        if suffix not in (".gif", ".mp4"):
            raise LagrangeError(f"cannot save an animation as {suffix!r}: use .gif or .mp4")
        from matplotlib.animation import writers

        if suffix == ".mp4" and not writers.is_available("ffmpeg"):
            raise LagrangeError("saving MP4 needs ffmpeg on the PATH; save as .gif instead")
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    P, axes = scene_points(system, trajectory)
    idx = np.linspace(0, len(trajectory.t) - 1, min(frames, len(trajectory.t))).round().astype(int)
    P, times = P[idx], trajectory.t[idx]
    axes = [(i, A[idx]) for i, A in axes]
    k = P.shape[1]
    if links == "chain":
        pairs = [(-1, 0)] + [(i, i + 1) for i in range(k - 1)]
    elif links == "none":
        pairs = []
    else:
        pairs = list(links)
    planar = np.allclose(P[:, :, 2], 0.0)
    span = float(np.max(np.abs(P))) or 1.0
    L = 0.25 * span
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(111) if planar else fig.add_subplot(111, projection="3d")
    lim = (-1.1 * span, 1.1 * span)
    ax.set_xlim(*lim)
    ax.set_ylim(*lim)
    if planar:
        ax.set_aspect("equal")
    else:
        ax.set_zlim(*lim)
    ax.set_title(title or system.name or "")

    def xyz(pts):
        return (pts[:, 0], pts[:, 1]) if planar else (pts[:, 0], pts[:, 1], pts[:, 2])

    dots = ax.plot(*xyz(P[0]), "o", color="C0", ms=8)[0]
    rods = [ax.plot(*xyz(np.zeros((2, 3))), "-", color="0.3", lw=2)[0] for _ in pairs]
    path_line = ax.plot(*xyz(P[:1, -1, :]), "-", color="C1", lw=1, alpha=0.7)[0]
    frame_lines = [[ax.plot(*xyz(np.zeros((2, 3))), "-", color=f"C{2 + j}", lw=2)[0] for j in range(3)]
                   for _ in axes]
    label = ax.text(0.02, 0.95, "", transform=ax.transAxes) if planar else ax.text2D(0.02, 0.95, "",
                                                                                      transform=ax.transAxes)

    def set_data(line, pts):
        if planar:
            line.set_data(pts[:, 0], pts[:, 1])
        else:
            line.set_data(pts[:, 0], pts[:, 1])
            line.set_3d_properties(pts[:, 2])

    def update(f):
        pts = P[f]
        set_data(dots, pts)
        for line, (i, j) in zip(rods, pairs):
            a = np.zeros(3) if i < 0 else pts[i]
            set_data(line, np.array([a, pts[j]]))
        set_data(path_line, P[max(0, f - trail):f + 1, -1, :])
        for lines, (i, A) in zip(frame_lines, axes):
            for j in range(3):
                set_data(lines[j], np.array([pts[i], pts[i] + L * A[f][:, j]]))
        label.set_text(f"t = {times[f]:.3g}")
        return [dots, *rods, path_line, label, *(l for ls in frame_lines for l in ls)]

    anim = FuncAnimation(fig, update, frames=len(idx), interval=1000 / fps, blit=False)
    if path is not None:
        from ..progress import counter

        path = Path(path)
        update, close = counter(len(idx), desc=f"frames of {path.name}")
        try:
            if path.suffix.lower() == ".gif":
                from matplotlib.animation import PillowWriter

                anim.save(path, writer=PillowWriter(fps=fps), progress_callback=lambda i, n: update(i + 1))
            else:
                anim.save(path, writer="ffmpeg", fps=fps, progress_callback=lambda i, n: update(i + 1))
        finally:
            close()
        plt.close(fig)
    return anim


def animation_html(anim):
    """Inline HTML (JavaScript player) of an animation for Jupyter."""
    from IPython.display import HTML

    return HTML(anim.to_jshtml())
