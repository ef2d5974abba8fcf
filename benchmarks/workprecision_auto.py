"""Re-measure only the ``method="auto"`` rows of the work-precision report, after a change to ``method="auto"``.

``benchmarks/workprecision.py`` measures every method of every problem (about 10 minutes on 2 quiet cores);
when only ``auto`` changed (issue #23 item 3: it now picks the Taylor method on the stiff problem, DOP853 on the
stick-slip belt, where the report still showed Radau and LSODA), this script re-runs just the ``auto`` curve
(the stiff problem) and the ``python_auto`` time-to-first-result route (the non-conservative problems) with the
same machinery and settings (:func:`lagrange.bench.runner.run_curve`, :func:`lagrange.bench.first_result.
first_result`, derivation cache off as there) — and, in the same run beside them, the python-backend curve and
first-result route of the method auto picks (rows measured at different times are not comparable on this
shared machine) — merges them into ``benchmarks/results/workprecision.json`` and
re-renders ``workprecision.md``, the figures and ``README_section.md`` from it. Each re-measured row's note says
so and when: its times come from a later run than the other rows (compare them across rows only roughly).

Run::

    python benchmarks/workprecision_auto.py                  # stiff and stick_slip
    python benchmarks/workprecision_auto.py --problem stiff
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

# as in benchmarks/workprecision.py: derivation times are measured cold
os.environ.setdefault("LAGRANGE_DERIVATION_CACHE", "0")

from lagrange.bench.first_result import first_result  # noqa: E402
from lagrange.bench.problems import get_problem  # noqa: E402
from lagrange.bench.report import _curve_data, _f, readme_section  # noqa: E402
from lagrange.bench.runner import TOLERANCES, MethodSpec, reference_solution, run_curve  # noqa: E402
from lagrange.bench.suite import write_report  # noqa: E402

RESULTS = Path(__file__).parent / "results"


#: the first-result route of the method auto picks (python backend, empty caches like ``python_auto``)
PICK_ROUTE = {"taylor": "taylor", "DOP853": "python"}


def remeasure(data: dict, name: str, stamp: str) -> list[str]:
    """Replace the auto rows of problem ``name`` in ``data``, and beside them, in the same run, the rows of the
    method auto picks (the python-backend curve and first-result route of that method): rows measured at
    different times are not comparable on this shared machine. Returns what was replaced."""
    problem = get_problem(name)
    entry = next(p for p in data["problems"] if p["name"] == name)
    system = problem.build()
    ref = reference_solution(problem, system)
    done = []
    picked = None
    for i, c in enumerate(entry["curves"]):
        if c["method"] != "auto":
            continue
        spec = MethodSpec(c["label"], kind=c["kind"], method="auto", backend=c["backend"], loop=c["loop"])
        curve = run_curve(problem, system, spec, ref, TOLERANCES, repeats=3, budget=0.5, stop=2.5)
        new = _curve_data(curve)
        new["note"] = "; ".join(filter(None, [new["note"], stamp]))
        entry["curves"][i] = new
        done.append(f"{name}: curve {c['label']!r}")
        picked = system.simulate((0.0, problem.t_end), problem.initial, problem.params, method="auto", rtol=1e-9,
                                 atol=1e-9 * problem.atol_scale, **problem.options).method.split(" ")[0]
        for j, other in enumerate(entry["curves"]):
            if (other["method"] == picked and other["kind"] == "simulate" and other["backend"] == "python"
                    and not other["loop"] and "regularized" not in other["label"]):
                spec = MethodSpec(other["label"], kind="simulate", method=picked, backend="python", loop=None)
                new = _curve_data(run_curve(problem, system, spec, ref, TOLERANCES, repeats=3, budget=0.5, stop=2.5))
                new["note"] = "; ".join(filter(None, [new["note"], stamp + " (beside auto)"]))
                entry["curves"][j] = new
                done.append(f"{name}: curve {other['label']!r} (auto's pick)")
    for f in entry["first_result"]:
        if f["route"] != "python_auto":
            continue
        routes = ["python_auto", None]  # None: the route of auto's pick, known once auto has run
        for route in routes:  # auto and its pick's route, one after the other
            if route is None:
                route = PICK_ROUTE.get(picked or "")
                if route is None or all(g["route"] != route for g in entry["first_result"]):
                    break
            r = first_result(problem, route, ref.states)
            picked = r.note if route == "python_auto" else picked
            k = next(j for j, g in enumerate(entry["first_result"]) if g["route"] == route)
            tag = stamp if route == "python_auto" else stamp + " (beside auto)"
            entry["first_result"][k] = {"route": r.route, "label": entry["first_result"][k]["label"],
                                        "derive": _f(r.derive), "compile": _f(r.compile),
                                        "integrate": _f(r.integrate), "total": _f(r.total), "error": _f(r.error),
                                        "note": "; ".join(filter(None, [r.note, tag]))}
            done.append(f"{name}: first result {route!r} ({r.note})")
    return done


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--problem", action="append")
    ap.add_argument("--out", default=str(RESULTS))
    args = ap.parse_args()
    out = Path(args.out)
    data = json.loads((out / "workprecision.json").read_text())
    stamp = f"re-measured {time.strftime('%Y-%m-%d', time.gmtime())} by benchmarks/workprecision_auto.py"
    done = [d for name in (args.problem or ["stiff", "stick_slip"]) for d in remeasure(data, name, stamp)]
    from workprecision import greenspan_summary  # the same extra section as the full report

    write_report(data, out, extra=greenspan_summary())
    (out / "README_section.md").write_text(readme_section(data))
    print("\n".join(done))


if __name__ == "__main__":
    main()
