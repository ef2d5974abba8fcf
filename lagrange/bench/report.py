"""Benchmark results as data (JSON-ready dicts), Markdown tables and the README summary.

Everything is rendered from the plain dict made by :func:`results_data` (also written as JSON next to the
Markdown), so the tables and the README section can be regenerated from a saved run and never drift from
the measured numbers.

Columns of the per-problem tables: for each tolerance (or fixed step), ``wall time · final error · nfev``
(wall time = median over repeats, ms; error = max-norm against the reference, see
:mod:`lagrange.bench.runner`). "Cheapest at error ≤ E" = the smallest wall time among the runs of a group of
methods whose error is at most E.
"""

from __future__ import annotations

import importlib.metadata
import math
import os
import platform
from collections.abc import Iterable, Sequence

import numpy as np

__all__ = ["TARGETS", "machine_info", "results_data", "render_markdown", "readme_section", "cheapest",
           "LAGRANGE_KINDS"]

#: error targets of the summary tables
TARGETS = (1e-4, 1e-7, 1e-10)
#: curve kinds that are lagrange's own methods
LAGRANGE_KINDS = ("simulate", "fixed")


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _version(dist: str) -> str | None:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return None


def machine_info() -> dict:
    """CPU model, core count, OS, thread settings and the versions of everything measured."""
    versions = {"python": platform.python_version()}
    for dist in ("numpy", "scipy", "sympy", "numba", "heyoka"):
        versions[dist] = _version(dist)
    from .. import __version__  # the distribution is lagrange-dynamics (PyPI's "lagrange" is another project)

    versions["lagrange"] = _version("lagrange-dynamics") or __version__
    threads = {k: os.environ[k] for k in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "NUMBA_NUM_THREADS")
               if k in os.environ}
    return {"cpu": _cpu_model(), "cores": os.cpu_count(), "os": f"{platform.system()} {platform.release()}",
            "threads": threads, "versions": versions, "c_compiler": _c_compiler()}


def _c_compiler() -> str | None:
    """The first line of ``--version`` of the compiler that builds the C Taylor interpreter, or None."""
    import subprocess

    from ..codegen.c_interpreter import compiler

    cc = compiler()
    if cc is None:
        return None
    try:
        out = subprocess.run([*cc, "--version"], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    return (out.strip().splitlines() or [None])[0]


def _f(x):
    return None if x is None or (isinstance(x, float) and not math.isfinite(x)) else float(x)


def _rounded(values) -> list:
    """Four significant digits: enough for plots of energy error against time, a fifth of the JSON."""
    return [float(f"{v:.4g}") for v in np.asarray(values, dtype=float)]


def _curve_data(c) -> dict:
    return {"label": c.spec.label, "kind": c.spec.kind, "method": c.spec.method, "backend": c.spec.backend,
            "loop": c.spec.loop, "setup": _f(c.setup), "note": c.note,
            "points": [{"setting": p.setting, "wall": p.wall, "nfev": p.nfev, "error": p.error, "runs": p.runs}
                       for p in c.points]}


def results_data(results: Sequence, machine: dict | None = None, settings: dict | None = None) -> dict:
    """The JSON-ready dict of a list of :class:`~lagrange.bench.runner.ProblemResult`."""
    from .first_result import ROUTES

    problems = []
    for r in results:
        p = r.problem
        problems.append({
            "name": p.name, "title": p.title, "notes": p.notes, "t_end": p.t_end, "derive_s": r.derive_s,
            "conservative": p.conservative, "long_t_end": p.long_t_end,
            "reference": {"description": r.reference.description, "consistency": _f(r.reference.consistency),
                          "check": _f(r.reference.check)},
            "curves": [_curve_data(c) for c in r.curves],
            "energy": [{"label": e.label, "wall": e.wall, "t": _rounded(e.t), "error": _rounded(e.error)}
                       for e in r.energy],
            "first_result": [{"route": f.route, "label": ROUTES.get(f.route, f.route), "derive": _f(f.derive),
                              "compile": _f(f.compile), "integrate": _f(f.integrate), "total": _f(f.total),
                              "error": _f(f.error), "note": f.note} for f in r.first_result],
        })
    return {"machine": machine or machine_info(), "settings": settings or {}, "problems": problems}


# --- selection ------------------------------------------------------------------------------------------
def cheapest(curves: Iterable[dict], target: float) -> tuple[float, str, float] | None:
    """``(wall, label, error)`` of the fastest run with error ≤ ``target`` among ``curves``, or None.

    >>> c = [{"label": "a", "points": [{"wall": 2.0, "error": 1e-8, "setting": 1e-8}]},
    ...      {"label": "b", "points": [{"wall": 1.0, "error": 1e-3, "setting": 1e-3}]}]
    >>> cheapest(c, 1e-6)
    (2.0, 'a', 1e-08)
    """
    best = None
    for c in curves:
        for p in c["points"]:
            if p["error"] <= target and (best is None or p["wall"] < best[0]):
                best = (p["wall"], c["label"], p["error"])
    return best


def _groups(problem: dict) -> dict:
    cs = problem["curves"]
    return {"lagrange": [c for c in cs if c["kind"] in LAGRANGE_KINDS],
            "lagrange python": [c for c in cs if c["kind"] == "simulate" and c["backend"] == "python"
                                and c["method"] != "taylor"],  # its tape runs in a compiled kernel
            "plain sympy": [c for c in cs if c["kind"] == "sympy"],
            "heyoka": [c for c in cs if c["kind"] == "heyoka"]}


# --- formatting -----------------------------------------------------------------------------------------
def _ms(s: float | None) -> str:
    if s is None:
        return "—"
    return f"{s * 1e3:.3g} ms" if s < 1 else f"{s:.3g} s"


def _e(x: float | None) -> str:
    return "—" if x is None else f"{x:.1e}"


def _machine_lines(m: dict) -> list[str]:
    v = m["versions"]
    ver = ", ".join(f"{k} {val}" for k, val in v.items() if val) + "".join(
        f"; {k} not installed" for k, val in v.items() if not val)
    thr = ", ".join(f"{k}={val}" for k, val in m.get("threads", {}).items()) or "not set"
    cc = f" C compiler (the Taylor interpreter): {m['c_compiler']}." if m.get("c_compiler") else ""
    return [f"Machine: {m['cpu']}, {m['cores']} logical cores, {m['os']}. Versions: {ver}. Thread settings: {thr}."
            + cc]


def _problem_table(problem: dict, kinds: tuple, setting_label) -> list[str]:
    curves = [c for c in problem["curves"] if c["kind"] in kinds]
    settings = sorted({p["setting"] for c in curves for p in c["points"]}, reverse=True)
    if not curves:
        return []
    out = ["| method | setup | " + " | ".join(setting_label(s) for s in settings) + " | note |",
           "|---|---|" + "---|" * len(settings) + "---|"]
    for c in curves:
        cells = []
        by = {p["setting"]: p for p in c["points"]}
        for s in settings:
            p = by.get(s)
            cells.append("" if p is None else f"{_ms(p['wall'])} · {_e(p['error'])}"
                         + (f" · {p['nfev']}" if p["nfev"] is not None else ""))
        out.append(f"| {c['label']} | {_ms(c['setup'])} | " + " | ".join(cells) + f" | {c['note']} |")
    return out


def _summary_rows(problem: dict) -> list[str]:
    g = _groups(problem)
    rows = []
    for target in TARGETS:
        best = {k: cheapest(v, target) for k, v in g.items()}
        if best["lagrange"] is None and best["heyoka"] is None and best["plain sympy"] is None:
            continue

        def cell(b):
            return "—" if b is None else f"{_ms(b[0])} ({b[1]})"

        ratio_s = (f"×{best['plain sympy'][0] / best['lagrange'][0]:.1f}"
                   if best["plain sympy"] and best["lagrange"] else "—")
        ratio_h = (f"{best['lagrange'][0] / best['heyoka'][0]:.1f}"
                   if best["heyoka"] and best["lagrange"] else "—")
        rows.append(f"| {problem['name']} | ≤ {target:.0e} | {cell(best['lagrange'])} | {cell(best['plain sympy'])} "
                    f"| {cell(best['heyoka'])} | {ratio_s} | {ratio_h} |")
    return rows


def _energy_table(problem: dict) -> list[str]:
    if not problem["energy"]:
        return []
    out = [f"Long run, t ∈ [0, {problem['long_t_end']:.4g}]: relative energy error |E − E0|/|E0|.", "",
           "| method | wall | max error | max over the first 10 % | growth (max / first 10 %) |",
           "|---|---|---|---|---|"]
    for e in problem["energy"]:
        err = np.asarray(e["error"])
        k = max(2, len(err) // 10)
        first, mx = float(np.max(err[:k])), float(np.max(err))
        growth = f"×{mx / first:.1f}" if first > 0 else "—"
        out.append(f"| {e['label']} | {_ms(e['wall'])} | {_e(mx)} | {_e(first)} | {growth} |")
    return out


def _imports_text(imports: dict | None) -> str:
    if not imports:
        return ""
    return (" Imports are not in these times; in a fresh process they take " + ", ".join(
        f"{_ms(v)} ({k}{' with sympy, numpy and scipy.integrate' if k == 'lagrange' else ''})"
        for k, v in imports.items()) + ".")


def _first_result_table(problem: dict, imports: dict | None = None) -> list[str]:
    if not problem["first_result"]:
        return []
    out = ["Time to first result (fresh process, empty caches; DOP853/Taylor at rtol 1e-10; heyoka's derive is "
           "heyoka.lagrangian on the T − V lagrange formed, whose cost is not counted; a route under 1 s is the "
           "median, by total, of three fresh processes)." + _imports_text(imports),
           "",
           "| route | derive | compile / JIT | integrate | total | error |", "|---|---|---|---|---|---|"]
    for f in problem["first_result"]:
        if f["total"] is None:
            out.append(f"| {f['label']} | failed: {f['note']} | | | | |")
            continue
        label = f["label"] + (f" ({f['note']})" if f["note"] else "")
        out.append(f"| {label} | {_ms(f['derive'])} | {_ms(f['compile'])} | {_ms(f['integrate'])} "
                   f"| **{_ms(f['total'])}** | {_e(f['error'])} |")
    return out


def render_markdown(data: dict, *, title: str = "Speed against error: work-precision benchmarks",
                    extra: str = "") -> str:
    """The full report: machine, method, a summary across problems, then every problem's tables."""
    s = data.get("settings", {})
    lines = [f"# {title}", "", *_machine_lines(data["machine"]), "",
             f"Settings: {s.get('mode', 'full')} run; wall time = median of {s.get('repeats', 3)} sample(s) after "
             "a warm-up — for runs under 5 ms the fastest of 7 samples, as `timeit` advises (bursts of other work "
             "slow sub-millisecond runs by up to 2× on this shared machine), a sample of a run under 2 ms being "
             "the mean of a batch lasting about 2 ms; the warm-up alone for runs over the time budget; "
             "`time.perf_counter`; "
             "error = max-norm of the state error at the measured times against the reference; "
             "atol = rtol (× the problem's scale). "
             "Setup (code generation, JIT, heyoka's LLVM compile, building the Hamiltonian model) is not in the "
             "wall times; it is reported in its own column and in the time-to-first-result tables. Other "
             "processes may have been running: compare ratios measured in the same run.", "",
             "## Summary: cheapest run at a given error", "",
             "lagrange = any of its methods (scipy loop or compiled loop, python or numba backend, geometric). "
             "Ratios: plain sympy wall / lagrange wall (higher is better for lagrange); lagrange wall / heyoka "
             "wall (below 1: lagrange is faster).", "",
             "| problem | error | lagrange | plain sympy | heyoka | sympy / lagrange | lagrange / heyoka |",
             "|---|---|---|---|---|---|---|"]
    for p in data["problems"]:
        lines += _summary_rows(p)
    for p in data["problems"]:
        ref = p["reference"]
        refline = f"Reference: {ref['description']}"
        if ref["consistency"] is not None:
            refline += f"; self-consistency (vs rtol 1e-12) {ref['consistency']:.1e}"
        if ref["check"] is not None:
            refline += f"; DOP853 at rtol 1e-13 is {ref['check']:.1e} from it"
        lines += ["", f"## {p['name']}: {p['title']}", "", f"Derivation {_ms(p['derive_s'])}. {refline}.", ""]
        if p["notes"]:
            lines += [p["notes"], ""]
        lines += ["Cells: wall time · error · nfev.", ""]
        lines += _problem_table(p, ("simulate", "sympy", "heyoka"), lambda v: f"tol {v:.0e}")
        fixed = _problem_table(p, ("fixed",), lambda v: f"h = {v:g}")
        if fixed:
            lines += ["", "Geometric fixed-step methods (Newton on the stage equations; steps in Python or in the "
                      "compiled loop):", "", *fixed]
        for block in (_energy_table(p), _first_result_table(p, s.get("imports"))):
            if block:
                lines += ["", *block]
    if extra:
        lines += ["", extra]
    return "\n".join(lines) + "\n"


def readme_section(data: dict) -> str:
    """The README's "Speed against error" section, rendered from the measured numbers."""
    rows = []
    for p in data["problems"]:
        g = _groups(p)
        for target in (1e-7,):
            lg, py, sy, hy = (cheapest(g[k], target) for k in ("lagrange", "lagrange python", "plain sympy",
                                                                 "heyoka"))
            if lg is None:
                continue
            rows.append(f"| {p['name']} | {_ms(lg[0])} ({lg[1]}) | "
                        + (f"{_ms(py[0])} ({py[1]})" if py else "—") + " | "
                        + (f"{_ms(sy[0])} (×{sy[0] / lg[0]:.0f} / ×{sy[0] / py[0]:.1f})" if sy and py else "—")
                        + " | " + (f"{_ms(hy[0])} ({lg[0] / hy[0]:.1f})" if hy else "—") + " |")
    ttfr = []
    for p in data["problems"]:
        fr = {f["route"]: f for f in p["first_result"] if f["total"] is not None}
        if not fr:
            continue
        cells = [f"{_ms(fr[r]['total'])}" if r in fr else "—" for r in ("python", "python_rerun", "taylor_primed",
                                                                         "taylor_rerun", "compiled_primed", "sympy",
                                                                         "heyoka", "heyoka_rerun")]
        ttfr.append(f"| {p['name']} | " + " | ".join(cells) + " |")
    m = data["machine"]
    out = ["## Speed against error", "",
           "`lagrange bench` (and `python benchmarks/workprecision.py`, which writes "
           "`benchmarks/results/workprecision.md` and one PNG per problem) measures final error against wall "
           "time and against function evaluations, and energy error against time over long runs, on a double "
           "pendulum, a 5-link pendulum, a heavy symmetric top, a Kepler orbit (closed form), a stiff damped "
           "double pendulum, a stick-slip friction oscillator (closed form) and Greenspan's top, against the "
           "plain `sympy.physics.mechanics` route and heyoka.py. "
           f"Measured on {m['cpu']} ({m['cores']} cores).", "",
           "Cheapest run reaching a final error ≤ 1e-7 (integration only; code generation, JIT and compilation "
           "excluded). Ratios: plain sympy's time over lagrange's best and over lagrange's python backend "
           "(scipy's loop, no compiler); lagrange's best time over heyoka's (below 1: lagrange is faster).", "",
           "| problem | lagrange (best method) | lagrange, python backend | plain sympy (÷ best / ÷ python) "
           "| heyoka.py (best ÷ heyoka) |", "|---|---|---|---|---|", *rows]
    if ttfr:
        out += ["", "Time to first result (derive + generate/compile + integrate at rtol 1e-10, fresh process after "
                "its imports, empty caches unless stated, median of three processes under 1 s; heyoka's excludes "
                "forming T − V, which lagrange does for it; cold columns for every route are in "
                "workprecision.md):", "",
                "| problem | lagrange python (DOP853) | same, re-run "
                "| lagrange taylor (interpreter built earlier, new model) | taylor, re-run "
                "| lagrange compiled loop (loops cached, new model) | plain sympy | heyoka.py "
                "| heyoka.py, re-run (its on-disk cache) |",
                "|---|---|---|---|---|---|---|---|---|", *ttfr]
    return "\n".join(out) + "\n"
