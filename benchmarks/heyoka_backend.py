"""method="heyoka" against the project's Taylor method and heyoka used directly (issue #22 item 6).

Three ways to integrate the same problem with a Taylor method at the same tolerance (rtol = atol = tol):

* ``taylor``   — ``simulate(method="taylor")``: the project's tape, run by the C interpreter;
* ``heyoka``   — ``simulate(method="heyoka")``: the project's derived equations converted to heyoka expressions
  (:mod:`lagrange.codegen.heyoka_expr`), integrated by heyoka's ``taylor_adaptive`` (built once, reused);
* ``taylor_fn``, ``heyoka_fn`` — the same two without ``simulate``: ``integrate_taylor`` and ``integrate_heyoka``
  called on the compiled model (what is left is the integration and the output);
* ``direct``   — heyoka used directly: ``heyoka.lagrangian`` on lagrange's ``T − V`` and ``taylor_adaptive``
  (:mod:`lagrange.bench.heyoka_adapter`, the work-precision benchmark's adapter), only the propagation timed.

Both ``simulate`` routes get the compiled model (``model=``), so a run measures what a sweep pays per run:
validation, binding the parameters, the integration. Per problem and tolerance: the setup paid once (first call
in this process: tape/interpreter or LLVM compilation) and the median CPU and wall time of a warm run,
interleaved (taylor, heyoka, direct, taylor, ...) so the machine's load hits every route alike; the final
states are compared with the ``taylor`` route's.

Run ``python benchmarks/heyoka_backend.py [--quick]``; writes ``benchmarks/results/heyoka_backend.md``.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).parent / "results"
PROBLEMS = ("double_pendulum", "kepler", "top")
ROUTES = ("taylor", "heyoka", "taylor_fn", "heyoka_fn", "direct")


def _runner(route: str, problem, tol: float):
    """``(setup seconds, run() -> final state)`` for one route on one problem."""
    system = problem.build()
    y0 = np.array([float(v) for v in problem.initial.values()])
    t0 = time.perf_counter()
    if route == "direct":
        from lagrange.bench.heyoka_adapter import heyoka_model

        hm = heyoka_model(system, problem.params)
        ta, _ = hm.integrator(y0, tol)

        def run():
            return hm.propagate(ta, y0, [problem.t_end])[0][-1]
    elif route.endswith("_fn"):
        from lagrange.integrate.heyoka_backend import integrate_heyoka
        from lagrange.integrate.taylor import integrate_taylor

        fn = integrate_taylor if route == "taylor_fn" else integrate_heyoka
        model = system.compile(problem.params)

        def run():
            return fn(model, (0.0, problem.t_end), y0, np.array([problem.t_end]), rtol=tol, atol=tol).y[-1]
    else:
        model = system.compile(problem.params)

        def run():
            sol = system.simulate((0.0, problem.t_end), problem.initial, problem.params, method=route, model=model,
                                  rtol=tol, atol=tol, t_eval=[problem.t_end])
            return sol.y[-1]
    run()
    return time.perf_counter() - t0, run


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--rounds", type=int, default=None)
    args = ap.parse_args(argv)
    import heyoka

    from lagrange.bench.problems import get_problem

    rounds = args.rounds or (5 if args.quick else 9)
    tols = (1e-9, 1e-13) if args.quick else (1e-6, 1e-9, 1e-13)
    lines = ["# method=\"heyoka\" vs the project's Taylor method vs heyoka directly", "",
             f"`python benchmarks/heyoka_backend.py{' --quick' if args.quick else ''}`, heyoka {heyoka.__version__}, "
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores (shared, load average "
             f"{os.getloadavg()[0]:.0f}), {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; rounds interleaved: "
             f"{rounds}; times per run in ms (median); setup = first call in this process (s).", "",
             "| problem | tol | route | setup s | CPU ms | wall ms | vs taylor (CPU) | vs direct (CPU) "
             "| max abs Δy vs taylor |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name in PROBLEMS:
        problem = get_problem(name, quick=args.quick)
        for tol in tols:
            runners = {r: _runner(r, problem, tol) for r in ROUTES}
            cpu = {r: [] for r in ROUTES}
            wall = {r: [] for r in ROUTES}
            final = {}
            for _ in range(rounds):
                for r in ROUTES:
                    c0, w0 = time.process_time(), time.perf_counter()
                    final[r] = runners[r][1]()
                    cpu[r].append(time.process_time() - c0)
                    wall[r].append(time.perf_counter() - w0)
            med = {r: statistics.median(cpu[r]) for r in ROUTES}
            for r in ROUTES:
                dy = float(np.max(np.abs(final[r] - final["taylor"])))
                lines.append(f"| {name} | {tol:g} | {r} | {runners[r][0]:.2f} | {1e3 * med[r]:.2f} "
                             f"| {1e3 * statistics.median(wall[r]):.2f} | {med[r] / med['taylor']:.2f} "
                             f"| {med[r] / med['direct']:.2f} | {dy:.1e} |")
            print("\n".join(lines[-len(ROUTES):]), flush=True)
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "heyoka_backend.md"
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
