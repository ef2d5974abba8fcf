"""The ways to run a Taylor tape, side by side in one run (issue #22 item 6): which to keep.

Engines (same tape, same order, same step rule):

* ``c``      — the interpreter in C (``lagrange.integrate.c_taylor``), called through ctypes;
* ``series`` — the tape written out as straight-line code and JIT-compiled per model (``backend="numba"``);
* ``numba``  — the same interpreter as C compiled by numba: retired after this measurement; measured only when
  the checked-out code still has it (``_taylor_loop.taylor``, up to commit 191ee35), skipped otherwise.

Per problem and tolerance: the setup cost paid once (first call in this process: loading/compiling the engine,
plus the per-model JIT of the series) and the median CPU and wall time of a warm run, interleaved
(c, numba, series, c, numba, series, ...) so the machine's load hits every engine alike. The final states are
compared with each other (they should agree to rounding).

Run ``python benchmarks/taylor_engines.py [--quick]``; writes ``benchmarks/results/taylor_engines.md``. The
numbers that decided what is kept are quoted in docs/guide.md ("The Taylor method: what is kept and why").
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
PROBLEMS = ("double_pendulum", "kepler", "top", "nlink")


def _runner(engine: str, problem, tol: float):
    """``(setup seconds, run())`` for one engine on one problem."""
    from lagrange.integrate import taylor as tay

    system = problem.build()
    backend = "numba" if engine == "series" else "python"
    model = system.compile(problem.params, backend=backend)
    y0 = np.array([float(v) for v in problem.initial.values()])
    t_eval = np.array([problem.t_end])
    kwargs = {"rtol": tol, "atol": tol}
    if engine in ("c", "numba"):
        kwargs["engine"] = engine

    def run():
        return tay.integrate_taylor(model, (0.0, problem.t_end), y0, t_eval, **kwargs)

    t0 = time.perf_counter()
    run()
    return time.perf_counter() - t0, run


def _time(run, repeats: int) -> tuple[list, list, np.ndarray]:
    cpu, wall = [], []
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        traj = run()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return cpu, wall, traj.y[-1]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--rounds", type=int, default=None)
    args = ap.parse_args(argv)
    from lagrange.bench.problems import get_problem

    rounds = args.rounds or (5 if args.quick else 9)
    tols = (1e-9, 1e-13) if args.quick else (1e-6, 1e-9, 1e-13)
    from lagrange.integrate import taylor as tay

    engines = ("c", "numba", "series") if "numba" in getattr(tay, "ENGINES", ("numba",)) else ("c", "series")
    lines = ["# Taylor engines side by side", "",
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores (shared), "
             f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; rounds interleaved: {rounds}; "
             "times per run in ms (median), setup = first call in this process (engine load/JIT + model JIT).", "",
             "| problem | tol | engine | setup s | CPU ms | wall ms | vs C (CPU) | max |Δy| vs C |",
             "|---|---|---|---|---|---|---|---|"]
    for name in PROBLEMS:
        problem = get_problem(name, quick=args.quick)
        for tol in tols:
            runners = {e: _runner(e, problem, tol) for e in engines}
            samples = {e: ([], [], None) for e in engines}
            for _ in range(rounds):
                for e in engines:
                    cpu, wall, y = _time(runners[e][1], 1)
                    samples[e][0].extend(cpu)
                    samples[e][1].extend(wall)
                    samples[e] = (samples[e][0], samples[e][1], y)
            c_cpu = statistics.median(samples["c"][0])
            for e in engines:
                cpu, wall, y = samples[e]
                dy = float(np.max(np.abs(y - samples["c"][2])))
                lines.append(f"| {name} | {tol:g} | {e} | {runners[e][0]:.2f} | {1e3 * statistics.median(cpu):.2f} "
                             f"| {1e3 * statistics.median(wall):.2f} | {statistics.median(cpu) / c_cpu:.2f} "
                             f"| {dy:.1e} |")
            print("\n".join(lines[-3:]), flush=True)
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "taylor_engines.md"
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
