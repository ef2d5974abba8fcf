"""Rich display of results in Jupyter: pure functions from a result object to HTML or LaTeX text.

The result classes attach these with one-line ``_repr_html_`` / ``_repr_latex_`` methods, so the
display code lives here, once, and the classes stay about their data:

=====================================================  ====================================================
:class:`~lagrange.results.trajectory.Trajectory`        :func:`trajectory_html` (system, method, span,
                                                        points, status, nfev, energy error, constraints)
:class:`~lagrange.analysis.small_oscillations.LinearModel`  :func:`linear_model_latex` (a, b, c, F)
:class:`~lagrange.analysis.small_oscillations.Modes`    :func:`modes_html` (ω, period, normalized shapes)
:class:`~lagrange.analysis.hamilton.HamiltonianForm`    :func:`hamiltonian_latex` (H, canonical equations)
:class:`~lagrange.sweep.ensemble.EnsembleResult`        :func:`ensemble_html` (members, status, work)
:class:`~lagrange.analysis.equilibria.Equilibrium`      :func:`equilibrium_latex` (positions, multipliers λ)
:class:`~lagrange.analysis.series.PotentialSeries`      :func:`potential_series_latex` (series by degree)
:class:`~lagrange.discrete.greenspan.Summary`           :func:`greenspan_summary_html` (fall, P1 drift)
=====================================================  ====================================================

``sweep()`` returns a pandas DataFrame, which Jupyter already shows as a table. Every string taken from
the user (names, messages) is HTML-escaped. Nothing here imports IPython.
"""

from __future__ import annotations

import html
from collections.abc import Iterable

import numpy as np
import sympy as sp

from .errors import LagrangeError
from .model.coordinates import coordinate_name, to_symbols

__all__ = ["html_table", "trajectory_summary", "trajectory_html", "linear_model_latex", "modes_html",
           "hamiltonian_latex", "ensemble_html", "equilibrium_latex", "potential_series_latex",
           "greenspan_summary_html"]


def html_table(rows: Iterable[Iterable], *, header: Iterable | None = None, caption: str | None = None) -> str:
    """A plain HTML table; every cell is converted with ``str`` and escaped."""
    parts = ["<table>"]
    if caption:
        parts.append(f"<caption style='text-align:left'><b>{html.escape(caption)}</b></caption>")
    if header is not None:
        parts.append("<thead><tr>" + "".join(f"<th>{html.escape(str(h))}</th>" for h in header) + "</tr></thead>")
    parts.append("<tbody>")
    for row in rows:
        cells = list(row)
        tag = ["th"] + ["td"] * (len(cells) - 1) if header is None else ["td"] * len(cells)
        parts.append("<tr>" + "".join(f"<{g} style='text-align:left'>{html.escape(str(c))}</{g}>"
                                      for g, c in zip(tag, cells)) + "</tr>")
    parts.append("</tbody></table>")
    return "".join(parts)


def trajectory_summary(traj) -> list[tuple[str, str]]:
    """(label, value) rows describing a trajectory: system, coordinates, method, time span, points, status,
    right-hand-side evaluations, each check of its verdict, energy (power-balance) error and, with constraints,
    the constraint names and the largest violation."""
    eqs = traj.model.equations
    rows = [("system", eqs.name or "(unnamed)"),
            ("coordinates", ", ".join(coordinate_name(c) for c in traj.coordinates)),
            ("method", traj.method),
            ("time span", f"[{traj.t[0]:.6g}, {traj.t[-1]:.6g}]" if len(traj.t) else "(no points)"),
            ("points", str(len(traj.t))),
            ("status", _status_text(traj)),
            ("rhs evaluations", str(traj.nfev))]
    if traj.verdict is not None:
        rows.extend((f"check: {c.name}", str(c).split(": ", 1)[1]) for c in traj.verdict.checks)
    if len(traj.t):
        label = "energy drift (relative)" if traj.work is None else "power-balance residual (relative)"
        try:
            rows.append((label, f"{traj.energy_error():.3e}"))
        except (LagrangeError, ArithmeticError, ValueError) as exc:
            rows.append((label, f"unavailable: {exc}"))
    if traj.model.m:
        rows.append(("constraints (λ)", ", ".join(eqs.constraint_names)))
        if len(traj.t):
            rows.append(("max constraint violation", f"{traj.max_constraint_violation():.3e}"))
    return rows


def _status_text(traj) -> str:
    """``ok``, ``INACCURATE`` (a check of the verdict failed) or ``FAILED``, with the run's message."""
    from .results.verdict import RunStatus

    word = {RunStatus.SUCCESS: "ok", RunStatus.INACCURATE: "INACCURATE", RunStatus.STOPPED: "FAILED"}[traj.status]
    return word + (f": {traj.message}" if traj.message else "")


def trajectory_html(traj) -> str:
    """HTML summary table of a :class:`~lagrange.results.trajectory.Trajectory`."""
    return html_table(trajectory_summary(traj), caption="Trajectory")


def _coords_latex(coordinates) -> str:
    return ", ".join(sp.latex(to_symbols(q, coordinates)) for q in coordinates)


def linear_model_latex(linear) -> str:
    r"""``a s̈ + b ṡ + c s = F`` with the matrices written out, the coordinates ``s`` and the reference state.

    .. math:: \mathbf a\,\ddot{\mathbf s} + \mathbf b\,\dot{\mathbf s} + \mathbf c\,\mathbf s = \mathbf F(t)
    """
    coords = linear.coordinates
    mats = [sp.latex(to_symbols(sp.Matrix(getattr(linear, k)), coords)) for k in ("a", "b", "c")]
    F = sp.Matrix(linear.forcing)
    lines = [r"\mathbf a\,\ddot{\mathbf s} + \mathbf b\,\dot{\mathbf s} + \mathbf c\,\mathbf s = \mathbf F(t),"
             rf"\quad \mathbf s = ({_coords_latex(coords)}) - \text{{reference}}",
             rf"\mathbf a = {mats[0]},\quad \mathbf b = {mats[1]},\quad \mathbf c = {mats[2]}"]
    if any(e != 0 for e in F):
        lines.append(rf"\mathbf F = {sp.latex(to_symbols(F, coords))}")
    if linear.about:
        ref = ",\\ ".join(rf"{sp.latex(to_symbols(k, coords))} = {sp.latex(to_symbols(sp.sympify(v), coords))}"
                          for k, v in linear.about.items())
        lines.append(rf"\text{{about }} {ref}")
    return r"$\displaystyle \begin{gathered} " + r" \\ ".join(lines) + r" \end{gathered}$"


def modes_html(modes, names: Iterable[str] | None = None) -> str:
    """HTML table of normal modes: angular frequency, period and the mode shape scaled to its largest
    component (one column per coordinate, named by ``names`` when given)."""
    n = len(modes.omega)
    names = list(names) if names is not None else [f"s{i + 1}" for i in range(n)]
    rows = []
    for k in range(n):
        shape = np.asarray(modes.shapes[:, k])  # complex for gyroscopic modes (amplitude and phase)
        shape = shape.real if not np.iscomplexobj(shape) or not np.any(shape.imag) else shape
        big = shape[np.argmax(np.abs(shape))] if np.any(shape) else 1.0
        rows.append([k + 1, f"{modes.omega[k]:.6g}", f"{modes.periods[k]:.6g}",
                     *(f"{v:.4g}" for v in shape / big)])
    return html_table(rows, header=["mode", "ω", "period 2π/ω", *(f"shape: {c}" for c in names)],
                      caption=f"Normal modes ({n})")


def hamiltonian_latex(form) -> str:
    r"""H and Hamilton's canonical equations :math:`\dot q_r = \partial H/\partial p_r`,
    :math:`\dot p_r = -\partial H/\partial q_r + Q_r` as one LaTeX block."""
    rows = [rf"H &= {sp.latex(form.H)}"]
    for q, p, qd, pd in zip(form.q, form.p, form.qdot, form.pdot):
        rows.append(rf"\dot{{{sp.latex(q)}}} &= {sp.latex(qd)}")
        rows.append(rf"\dot{{{sp.latex(p)}}} &= {sp.latex(pd)}")
    return r"$\displaystyle \begin{aligned} " + r" \\ ".join(rows) + r" \end{aligned}$"


def equilibrium_latex(eq) -> str:
    r"""An equilibrium as ``q = value`` lines, then the constraint multipliers ``λ_name = value`` when the
    system is constrained (coordinates printed as symbols, values exact or numeric as found)."""
    coords = list(eq)
    rows = [rf"{sp.latex(to_symbols(q, coords))} &= {sp.latex(to_symbols(sp.sympify(v), coords))}"
            for q, v in eq.items()]
    rows += [rf"\lambda_{{\text{{{_latex_text(name)}}}}} &= {sp.latex(to_symbols(sp.sympify(v), coords))}"
             for name, v in eq.multipliers.items()]
    return r"$\displaystyle \begin{aligned} " + r" \\ ".join(rows) + r" \end{aligned}$"


def potential_series_latex(series) -> str:
    r"""``V ≈ Σ_k terms[k]`` written by degree, with the expansion point (``q → ∞`` for a far-field series)."""
    rows = [rf"V_{{{k}}} &= {sp.latex(term)}" for k, term in enumerate(series.terms)]
    point = ",\\ ".join(rf"{sp.latex(q)} = {sp.latex(v)}" for q, v in series.about.items())
    rows.append(rf"&\text{{about }} {point},\ \text{{order }} {series.order}")
    return r"$\displaystyle \begin{aligned} " + r" \\ ".join(rows) + r" \end{aligned}$"


def greenspan_summary_html(summary) -> str:
    """HTML table of a Greenspan top run's summary: the span, whether (and when) it fell, P1's drift and mean
    velocity, the height range of the centre."""
    rows = summary.report()
    dx, dy = summary.P1_drift
    table = [("output times", f"{len(summary.t)}, t = {summary.t[0]:.6g} … {summary.t[-1]:.6g}"),
             ("fell", f"yes, at t = {summary.fall_time:.6g}" if summary.fell else "no"),
             ("P1 drift", f"({dx:+.6f}, {dy:+.6f})"),
             ("P̄ height range", f"{summary.zbar_range[0]:.6g} … {summary.zbar_range[1]:.6g}")]
    return html_table(table, caption=rows[0])


def _latex_text(name: str) -> str:
    """A user's name for ``\\text{…}``: LaTeX's special characters escaped."""
    special = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
               "_": r"\_", "%": r"\%", "^": r"\^{}", "~": r"\~{}"}
    return "".join(special.get(c, c) for c in str(name))


def ensemble_html(result) -> str:
    """HTML summary of an :class:`~lagrange.sweep.ensemble.EnsembleResult`: members, output times,
    method, how many succeeded (with the first failure's message) and the work per member."""
    k = len(result.status)
    ok = int(np.sum(result.success))
    rows = [("method", result.method), ("members", k),
            ("output times", f"{len(result.t)} in [{result.t[0]:.6g}, {result.t[-1]:.6g}]" if len(result.t) else 0),
            ("reached the end", f"{ok} of {k}")]
    failed = [m for m, s in zip(result.messages, result.status) if s != 0]
    if failed:
        rows.append(("first failure", failed[0]))
    if k:
        rows.append(("rhs evaluations per member", f"min {int(np.min(result.nfev))}, "
                     f"median {int(np.median(result.nfev))}, max {int(np.max(result.nfev))}"))
    return html_table(rows, caption="Ensemble")
