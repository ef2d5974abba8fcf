"""Time to first result against the size of the system: planar N-link pendulums, N = 2, 5, 8, 10.

Each route runs in a fresh process with empty caches (:mod:`lagrange.bench.first_result`; three processes, median
by total, when a route takes under a second), side by side in one run: lagrange's python backend with DOP853,
lagrange's Taylor method with the tape interpreted in C (built by an earlier process, as after a first use on the
machine; the numba build of the interpreter where there is no C compiler), and heyoka.py (``heyoka.lagrangian`` +
``taylor_adaptive``, cold LLVM compile, ``compact_mode`` above 100 operations). All at rtol = atol = 1e-10 over t
∈ [0, 10]; the error is the max-norm of the final state against DOP853 at rtol 1e-13. Writes
``results/first_result_scaling.md``. Run::

    python benchmarks/first_result_scaling.py          # about 5 minutes on 2 cores
"""

from __future__ import annotations

import argparse
from pathlib import Path

from lagrange.bench.first_result import ROUTES, first_result, import_times
from lagrange.bench.heyoka_adapter import heyoka_available
from lagrange.bench.problems import get_problem
from lagrange.bench.report import machine_info

RESULTS = Path(__file__).parent / "results"
ROUTE_SET = ("python", "taylor_primed", "heyoka")


def _ms(s):
    return "—" if s is None else f"{s * 1e3:.0f} ms" if s >= 0.0995 else f"{s * 1e3:.1f} ms"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--links", default="2,5,8,10")
    ap.add_argument("--out", default=str(RESULTS / "first_result_scaling.md"))
    args = ap.parse_args()
    routes = [r for r in ROUTE_SET if r != "heyoka" or heyoka_available()]
    m = machine_info()
    lines = ["# Time to first result against system size (planar N-link pendulum)", "",
             f"Machine: {m.get('cpu', '?')}, {m.get('cores', '?')} logical cores. Versions: "
             + ", ".join(f"{k} {v}" for k, v in m.get("versions", {}).items() if v) + "."
             + (f" C compiler: {m['c_compiler']}." if m.get("c_compiler") else ""), "",
             __doc__.split("\n\n")[1].replace("\n", " "), "",
             "Imports are not in these times; in a fresh process they take "
             + ", ".join(f"{_ms(v)} ({k})" for k, v in import_times().items()) + ".", "",
             "| N | route | derive | compile / JIT | integrate | total | error | note |",
             "|---|---|---|---|---|---|---|---|"]
    totals: dict = {}
    for n in (int(v) for v in args.links.split(",")):
        p = get_problem(f"nlink{n}")
        s = p.build()
        ref = s.simulate((0.0, p.t_end), p.initial, p.params, rtol=1e-13, atol=1e-13, t_eval=p.times()).y
        for route in routes:
            r = first_result(p, route, ref, timeout=900.0)
            totals[(n, route)] = r.total
            err = "—" if r.error is None else f"{r.error:.1e}"
            lines.append(f"| {n} | {ROUTES[route]} | {_ms(r.derive)} | {_ms(r.compile)} | {_ms(r.integrate)} | "
                         f"**{_ms(r.total)}** | {err} | {r.note} |")
            print(lines[-1], flush=True)
    if "heyoka" in routes:
        lines += ["", "Ratios, lagrange total / heyoka total (below 1: lagrange's first result comes sooner):", "",
                  "| N | python backend, DOP853 | Taylor, interpreted tape |", "|---|---|---|"]
        for n in sorted({k[0] for k in totals}):
            h = totals.get((n, "heyoka"))

            def ratio(route, n=n, h=h):
                v = totals.get((n, route))
                return "—" if not (v and h) else f"{v / h:.2f}"

            lines.append(f"| {n} | {ratio('python')} | {ratio('taylor_primed')} |")
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
