"""Run a set of benchmark problems and write the report: Markdown, JSON (the raw numbers) and one PNG
per problem. What ``lagrange bench`` and ``benchmarks/workprecision.py`` call.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from .heyoka_adapter import heyoka_available
from .problems import PROBLEMS, get_problem
from .report import machine_info, render_markdown, results_data
from .runner import run_problem

__all__ = ["run_suite", "write_report"]


def write_report(data: dict, out: str | Path, *, name: str = "workprecision", extra: str = "") -> dict:
    """Write ``name.md``, ``name.json`` and ``name_<problem>.png`` into ``out``; returns their paths."""
    from ..plot.workprecision import plot_work_precision

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"md": out / f"{name}.md", "json": out / f"{name}.json", "png": []}
    paths["json"].write_text(json.dumps(data, indent=1))
    paths["md"].write_text(render_markdown(data, extra=extra))
    for p in data["problems"]:
        png = out / f"{name}_{p['name']}.png"
        plot_work_precision(p, png)
        paths["png"].append(png)
    return paths


def run_suite(problems: Sequence[str] | None = None, *, quick: bool = False, out: str | Path | None = None,
              heyoka: bool = True, first_result: bool | None = None, log: Callable[[str], None] | None = print,
              extra: str = "") -> dict:
    """Benchmark ``problems`` (default: all of :data:`~lagrange.bench.problems.PROBLEMS`).

    ``quick``: short horizons, two tolerances, one repeat, python backend, no time-to-first-result
    subprocesses (unless ``first_result=True``). heyoka is used when installed (a note is printed
    otherwise). Writes the report into ``out`` when given; returns the results dict
    (:func:`~lagrange.bench.report.results_data`).
    """
    say = log or (lambda s: None)
    names = list(problems) if problems else list(PROBLEMS)
    chosen = [get_problem(n, quick=quick) for n in names]  # validates every name first
    use_heyoka = heyoka and heyoka_available()
    if heyoka and not use_heyoka:
        say("note: heyoka.py is not installed, skipping the heyoka comparison "
            '(pip install "lagrange-dynamics[heyoka]")')
    ttfr = (not quick) if first_result is None else first_result
    t0 = time.perf_counter()
    results = [run_problem(p, quick=quick, heyoka=use_heyoka, first_result=ttfr, log=say) for p in chosen]
    settings = {"mode": "quick" if quick else "full", "repeats": 1 if quick else 3,
                "elapsed_s": round(time.perf_counter() - t0, 1)}
    if ttfr:
        from .first_result import import_times

        settings["imports"] = import_times()
    data = results_data(results, machine_info(), settings)
    if out is not None:
        paths = write_report(data, out, extra=extra)
        say(f"wrote {paths['md']}, {paths['json']} and {len(paths['png'])} PNG(s) in {settings['elapsed_s']} s")
    return data
