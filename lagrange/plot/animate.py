"""Animations of a simulated system drawn from its own transformation equations.

Particles are dots, rods join consecutive points (``links="chain"``, from the fixed origin) or the pairs
you list, rigid bodies are drawn as their body-axis frame at the centre of mass. 2D when every point
stays in the plane z = 0, 3D otherwise. The result is a matplotlib ``FuncAnimation``; save it as GIF
(Pillow, always available) or MP4 (needs ffmpeg), or show it inline in Jupyter with
``animate(..., inline=True)`` (an :class:`InlineAnimation`, HTML with the frames embedded).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..conventions import t
from ..errors import LagrangeError
from ..model.coordinates import to_symbols
from ..safe_sympify import lambdify as _lambdify

__all__ = ["animate", "animation_html", "scene_points", "InlineAnimation"]


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
    f = _lambdify([t, syms], [list(e) for e in exprs], "numpy")
    n = len(coords)
    P = np.array([np.array(f(ti, yi[:n]), dtype=float) for ti, yi in zip(trajectory.t, trajectory.y)])
    axes = []
    for idx, R in frames:
        g = _lambdify([t, syms], R, "numpy")
        axes.append((idx, np.array([np.array(g(ti, yi[:n]), dtype=float) for ti, yi in zip(trajectory.t,
                                                                                           trajectory.y)])))
    return P, axes


class InlineAnimation:
    """An animation as a self-contained HTML/JavaScript player (frames embedded as PNG).

    Jupyter shows it through :meth:`_repr_html_`; ``html`` is the markup, ``frames`` the number of frames.
    No IPython needed: any front end that renders ``_repr_html_`` shows it, and ``save`` writes a page.
    """

    def __init__(self, html: str, frames: int):
        self.html = html
        self.frames = frames

    def _repr_html_(self) -> str:
        return self.html

    def save(self, path: str | Path) -> Path:
        """Write the player as a standalone HTML page."""
        path = Path(path)
        path.write_text(self.html, encoding="utf-8")
        return path

    def __repr__(self) -> str:
        return f"<InlineAnimation: {self.frames} frames, {len(self.html) / 1e3:.0f} kB of HTML>"


def animate(system, trajectory, path: str | Path | None = None, *, links: str | Sequence = "chain",
            frames: int = 150, fps: int = 25, trail: int = 40, title: str | None = None,
            inline: bool = False, dpi: int = 60, size: float = 6.0):
    """Animate ``trajectory`` of ``system``; write it to ``path`` (``.gif`` or ``.mp4``) when given.

    The user's matplotlib backend is never changed: to write a file or build an inline player the figure
    is made on its own Agg canvas, outside pyplot; otherwise (to show it with ``plt.show()``) pyplot makes it.

    Parameters
    ----------
    links : ``"chain"`` (origin → point 1 → point 2 …), ``"none"``, or a list of index pairs (−1 = origin)
    frames : number of frames (evenly spaced over the output times)
    trail : length of the fading path drawn behind the last point
    title : default: the system's name
    inline : return an :class:`InlineAnimation` (HTML player for Jupyter: ``frames`` PNGs at ``dpi`` of a
        ``size`` inch square figure; keep both small, about 60 frames at 60 dpi is 0.3 MB) instead of the
        ``FuncAnimation``; a file is still written when ``path`` is given
    dpi, size : resolution and side (inches) of the frames of an inline player

    Returns
    -------
    InlineAnimation when ``inline``; else the ``Path`` written when ``path`` is given; else a
    ``matplotlib.animation.FuncAnimation`` (show it with ``plt.show()``)

    Raises
    ------
    LagrangeError
        no bodies to draw, unknown parameter values, an unsupported file type, MP4 without ffmpeg.
    """
    if path is not None:
        suffix = Path(path).suffix.lower()
        if suffix not in (".gif", ".mp4"):
            raise LagrangeError(f"cannot save an animation as {suffix!r}: use .gif or .mp4 (or inline=True)")
        from matplotlib.animation import writers

        if suffix == ".mp4" and not writers.is_available("ffmpeg"):
            raise LagrangeError("saving MP4 needs ffmpeg on the PATH; save as .gif instead")
    from matplotlib.animation import FuncAnimation

    from .trajectory import new_figure

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
    offscreen = path is not None or inline
    fig = new_figure("file" if offscreen else None, figsize=(size, size))
    ax = fig.add_subplot(111) if planar else fig.add_subplot(111, projection="3d")
    lim = (-1.1 * span, 1.1 * span)
    ax.set_xlim(*lim)
    ax.set_ylim(*lim)
    if planar:
        ax.set_aspect("equal")
    else:
        ax.set_zlim(*lim)
    ax.set_title(title or system.name or "")
    if inline:  # tick labels are most of the drawing time of a frame; the scale is in the title
        ax.tick_params(labelbottom=False, labelleft=False, bottom=False, left=False)
        if not planar:
            ax.set_zticklabels([])

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

    if path is not None:
        from ..progress import counter

        path = Path(path)
        update_bar, close = counter(len(idx), desc=f"frames of {path.name}")
        try:
            if path.suffix.lower() == ".gif":
                from matplotlib.animation import PillowWriter

                _record(fig, update, len(idx), PillowWriter(fps=fps), path, fig.dpi, update_bar)
            else:
                from matplotlib.animation import FFMpegWriter

                _record(fig, update, len(idx), FFMpegWriter(fps=fps), path, fig.dpi, update_bar)
        finally:
            close()
    if inline:
        return _inline(fig, update, len(idx), fps, dpi)
    if path is not None:
        return path
    return FuncAnimation(fig, update, frames=len(idx), interval=1000 / fps, blit=False)


def _record(fig, update, n: int, writer, path: Path, dpi: float, progress=None) -> None:
    """Draw every frame once into ``writer`` (FuncAnimation.save draws each frame twice); ``progress(i)`` is
    told the number of frames done."""
    with writer.saving(fig, str(path), dpi):
        for f in range(n):
            update(f)
            writer.grab_frame()
            if progress is not None:
                progress(f + 1)


def _inline(fig, update, n: int, fps: int, dpi: int) -> InlineAnimation:
    """The frames as an HTML/JavaScript player (matplotlib's HTMLWriter, PNG frames embedded)."""
    import tempfile

    import matplotlib
    from matplotlib.animation import HTMLWriter

    with tempfile.TemporaryDirectory() as tmp, matplotlib.rc_context({"animation.embed_limit": 50.0}):
        out = Path(tmp) / "animation.html"
        _record(fig, update, n, HTMLWriter(fps=fps, embed_frames=True, default_mode="loop"), out, dpi)
        return InlineAnimation(out.read_text(encoding="utf-8"), n)


def animation_html(anim, *, fps: int | None = None, dpi: int = 60, frames: int = 0) -> InlineAnimation:
    """An :class:`InlineAnimation` (JavaScript player, frames as PNG at ``dpi``) of a ``FuncAnimation``."""
    import matplotlib

    with matplotlib.rc_context({"savefig.dpi": dpi, "animation.frame_format": "png",
                                "animation.embed_limit": 50.0}):
        html = anim.to_jshtml(fps=fps, default_mode="loop")
    return InlineAnimation(html, frames)
