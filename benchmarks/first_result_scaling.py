"""Time to first result against the size of the system: planar N-link pendulums, N = 2, 5, 10, 20, 50.

Each route runs in a fresh process with empty caches (:mod:`lagrange.bench.first_result`), side by side in one run:
lagrange's python backend with DOP853, lagrange's Taylor method with the tape interpreted in C (built by an earlier
process, as after a first use on the machine; the numba build of the interpreter where there is no C compiler),
heyoka.py (``heyoka.lagrangian`` + ``taylor_adaptive``, cold LLVM compile, ``compact_mode`` above 100 operations)
and sympy.physics.mechanics (``KanesMethod``, its faster formulation for chains, and the plain ``LagrangesMethod``;
each + ``lambdify(cse=True)`` + ``numpy.linalg.solve`` in the rhs + ``solve_ivp`` DOP853). All at rtol = atol =
1e-10 over t ∈ [0, 10]; the error is the max-norm of the final state against lagrange's Taylor method (C tape) at
rtol 1e-15. Interleaved: for each N the routes run one after the other (A, B, C, D), and a route whose first result
came within a second runs two more rounds (A, B, …, A, B, …), median by total. A route that does not finish within
the time-out (``--timeout``; ``--sympy-timeout`` for the sympy routes) is stopped and reported as timed out.

Times: wall-clock phases (derive, compile / JIT, integrate) measured inside the route's process, imports not
counted; CPU time of the same phases (``time.process_time``, imports not counted); and the CPU and wall time of
the whole process (``resource.getrusage`` of the child: interpreter start-up and imports counted). Writes
``results/first_result_scaling.md``. Run::

    python benchmarks/first_result_scaling.py                  # about 15–20 minutes on 2 shared cores
    python benchmarks/first_result_scaling.py --quick          # N = 2, 5, one round, no LagrangesMethod: ~1 min
    python benchmarks/first_result_scaling.py --derivation structural   # System(..., derivation=...)
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import numpy as np

from lagrange.bench.first_result import REPEAT_BELOW_S, ROUTES, first_result_once, import_times, median_by_total
from lagrange.bench.heyoka_adapter import heyoka_available
from lagrange.bench.problems import derivation_options, get_problem
from lagrange.bench.report import machine_info

RESULTS = Path(__file__).parent / "results"
ROUTE_SET = ("python", "taylor_primed", "heyoka", "sympy_kane", "sympy")
RATIO_ROUTES = ("python", "taylor_primed", "sympy_kane", "sympy")


def _ms(s):
    if s is None:
        return "—"
    return f"{s:.1f} s" if s >= 9.95 else f"{s * 1e3:.0f} ms" if s >= 0.0995 else f"{s * 1e3:.1f} ms"


def reference(p, system) -> np.ndarray:
    """The final state of lagrange's Taylor method (C tape) at rtol = atol = 1e-15 (order 19)."""
    return system.simulate((0.0, p.t_end), p.initial, p.params, method="taylor", rtol=1e-15, atol=1e-15,
                           t_eval=p.times()).y


def run_n(n: int, routes, *, system_kwargs: dict, timeout: float, sympy_timeout: float, rounds: int, log,
          done=lambda r, result: None) -> dict:
    """Every route once (and, for those under :data:`REPEAT_BELOW_S`, ``rounds − 1`` more interleaved rounds);
    ``done(route, result)`` after each route's first run (results so far, for a partial table)."""
    p = get_problem(f"nlink{n}", system_kwargs=system_kwargs)
    ref = reference(p, p.build())
    runs: dict = {r: [] for r in routes}
    for k in range(rounds):
        todo = [r for r in routes if k == 0 or (runs[r][0].total is not None and runs[r][0].total < REPEAT_BELOW_S)]
        todo = todo[k % max(len(todo), 1):] + todo[:k % max(len(todo), 1)]
        for r in todo:
            runs[r].append(first_result_once(p, r, ref, timeout=sympy_timeout if r.startswith("sympy") else timeout,
                                             system_kwargs=system_kwargs))
            log(f"N={n} {r}: " + (f"{runs[r][-1].total:.2f} s" if runs[r][-1].total is not None
                                  else runs[r][-1].note))
            if k == 0:
                done(r, runs[r][0])
    return {r: median_by_total(v) for r, v in runs.items()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--links", default=None, help="comma-separated N (default 2,5,10,20,50; quick: 2,5,10)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds a lagrange or heyoka route may take")
    ap.add_argument("--sympy-timeout", type=float, default=300.0, help="seconds a sympy route may take")
    ap.add_argument("--derivation", default=None, help="pass System(..., derivation=...) through")
    ap.add_argument("--quick", action="store_true", help="N = 2, 5, one round, no LagrangesMethod route")
    ap.add_argument("--routes", default=None, help=f"comma-separated subset of {','.join(ROUTE_SET)}")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    system_kwargs = derivation_options(args.derivation)
    links = [int(v) for v in (args.links or ("2,5" if args.quick else "2,5,10,20,50")).split(",")]
    rounds = 1 if args.quick else 3
    out = Path(args.out or RESULTS / ("first_result_scaling_quick.md" if args.quick else "first_result_scaling.md"))
    routes = [r for r in ROUTE_SET if (r != "heyoka" or heyoka_available()) and not (args.quick and r == "sympy")]
    if args.routes:
        wanted = args.routes.split(",")
        unknown = sorted(set(wanted) - set(ROUTE_SET))
        if unknown:
            ap.error(f"unknown route(s) {', '.join(unknown)}; choose from {', '.join(ROUTE_SET)}")
        routes = [r for r in routes if r in wanted]
    m = machine_info()
    paragraphs = __doc__.split("\n\n")
    lines = ["# Time to first result against system size (planar N-link pendulum)", "",
             f"Machine: {m.get('cpu', '?')}, {m.get('cores', '?')} logical cores, shared with other work (load average "
             f"{os.getloadavg()[0]:.1f} when this table was written: wall times stretch with it, CPU times much less). "
             "Versions: "
             + ", ".join(f"{k} {v}" for k, v in m.get("versions", {}).items() if v) + "."
             + (f" C compiler: {m['c_compiler']}." if m.get("c_compiler") else ""), "",
             "Derivation: " + (f"`System(..., derivation={args.derivation!r})`." if args.derivation
                               else "the default path."), "",
             paragraphs[1].replace("\n", " "), "", paragraphs[2].split(" Writes")[0].replace("\n", " "), "",
             "Imports (not in the phase columns) take, in a fresh process, "
             + ", ".join(f"{_ms(v)} ({k})" for k, v in import_times(1 if args.quick else 3).items())
             + " (median of " + ("1" if args.quick else "3") + ").", "",
             "| N | route | derive | compile / JIT | integrate | **total (wall)** | CPU (no imports) "
             "| whole process: CPU / wall (imports counted) | error | note |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    results: dict = {}

    def log(msg):
        print(msg, flush=True)

    def row(n, route, r):
        err = "—" if r.error is None else f"{r.error:.1e}"
        whole = "—" if r.process_cpu is None else f"{_ms(r.process_cpu)} / {_ms(r.process_wall)}"
        return (f"| {n} | {ROUTES[route]} | {_ms(r.derive)} | {_ms(r.compile)} | {_ms(r.integrate)} | "
                f"**{_ms(r.total)}** | {_ms(r.cpu)} | {whole} | {err} | {r.note} |")

    for n in links:
        partial: list = []

        def done(route, r, n=n, partial=partial):  # a partial table while N's routes run (long runs at N = 50)
            partial.append(row(n, route, r))
            out.write_text("\n".join(lines + partial) + "\n", encoding="utf-8")

        for route, r in run_n(n, routes, system_kwargs=system_kwargs, timeout=args.timeout,
                              sympy_timeout=args.sympy_timeout, rounds=rounds, log=log, done=done).items():
            results[(n, route)] = r
            lines.append(row(n, route, r))
        out.write_text("\n".join(lines + _ratios(results, routes)) + "\n", encoding="utf-8")  # after each N
    print(out.read_text())


def _ratios(results: dict, routes) -> list[str]:
    if "heyoka" not in routes:
        return []
    lines = ["", "Ratios to heyoka, wall total and (in brackets) CPU without imports; below 1: the route's first "
             "result comes sooner than heyoka's:", "",
             "| N | " + " | ".join(ROUTES[r] for r in RATIO_ROUTES) + " |", "|---|" + "---|" * len(RATIO_ROUTES)]
    for n in sorted({k[0] for k in results}):
        h = results.get((n, "heyoka"))

        def ratio(route, n=n, h=h):
            v = results.get((n, route))
            if v is None:
                return "—"
            if v.total is None:
                return "did not finish"
            if h is None or h.total is None:
                return "heyoka did not finish"
            cpu = f" ({v.cpu / h.cpu:.2f})" if v.cpu and h.cpu else ""
            return f"{v.total / h.total:.2f}{cpu}"

        lines.append(f"| {n} | " + " | ".join(ratio(r) for r in RATIO_ROUTES) + " |")
    return lines


if __name__ == "__main__":
    main()
