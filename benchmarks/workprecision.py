"""Work-precision benchmarks of every problem of ``lagrange.bench``: error against wall time and against
function evaluations, energy error against time over long runs, time to first result, all side by side in
one run against the plain sympy.physics.mechanics route and heyoka.py (when installed).

Writes ``benchmarks/results/workprecision.md`` (tables), ``workprecision.json`` (every number),
``workprecision_<problem>.png`` (figures) and ``README_section.md`` (the README's "Speed against error"
section, rendered from the JSON). Run::

    python benchmarks/workprecision.py            # full run (budget about 10 minutes on 2 quiet cores)
    python benchmarks/workprecision.py --quick    # a first look in about a minute
    python benchmarks/workprecision.py --render   # only re-render the tables, PNGs and README_section.md
                                                  # from the saved workprecision.json

Greenspan's top: the rigid model is one of the problems; the molecular model (11,000,000 discrete-gradient
steps) is measured by ``benchmarks/greenspan.py``, whose speed table is summarized here when present.
"""

from __future__ import annotations

import argparse
import json
import os
import re
from pathlib import Path

# derivation times are measured cold: the derivation cache (lagrange.codegen.derivation_cache) stays off
os.environ.setdefault("LAGRANGE_DERIVATION_CACHE", "0")

from lagrange.bench.report import readme_section
from lagrange.bench.suite import run_suite, write_report

RESULTS = Path(__file__).parent / "results"


def greenspan_summary() -> str:
    """The molecular/rigid rows of ``results/greenspan.md``'s speed table, as a short Markdown section."""
    path = RESULTS / "greenspan.md"
    if not path.exists():
        return ""
    rows = [ln for ln in path.read_text().splitlines()
            if re.match(r"\| (molecular|rigid DOP853 numba \| 1e-(08|10|12))", ln)]
    if not rows:
        return ""
    return "\n".join(["## Greenspan's top: molecular model (from benchmarks/greenspan.py)", "",
                      "Example 1 over t = 110; error = max |ΔP1| against the rigid reference (DOP853 rtol 1e-13). "
                      "Wall times there include derivation and code generation.", "",
                      "| run | tol | wall time | error vs reference | nfev / steps |", "|---|---|---|---|---|", *rows])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="short runs, two tolerances, python backend")
    ap.add_argument("--problem", action="append", help="only this problem (repeatable)")
    ap.add_argument("--no-heyoka", action="store_true")
    ap.add_argument("--render", action="store_true", help="only re-render md, PNGs and README_section.md from the JSON")
    ap.add_argument("--out", default=str(RESULTS))
    args = ap.parse_args()
    out = Path(args.out)
    if args.render:
        data = json.loads((out / "workprecision.json").read_text())
        write_report(data, out, extra=greenspan_summary())
    else:
        data = run_suite(args.problem, quick=args.quick, out=out, heyoka=not args.no_heyoka, extra=greenspan_summary())
    (out / "README_section.md").write_text(readme_section(data))
    print((out / "README_section.md").read_text())


if __name__ == "__main__":
    main()
