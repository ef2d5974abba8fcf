"""Compiled DOP853 loop vs scipy's solve_ivp, on the planar N-link pendulum (measured side by side in one run).

For N = 2, 5, 10, t in [0, 10], q_i = 0.6(-1)^i/(i+1), u = 0, g = 9.81, rtol = atol = 1e-6, 1e-9, 1e-12:

* wall time (median of ``--repeats``) of ``solve_ivp(DOP853)`` with the python-backend rhs, with the numba rhs,
  and of the compiled loop (``run_loop``; and ``simulate(..., loop="compiled")`` end to end), all with one
  output time t = 10;
* final error (max norm) against a reference: the compiled loop at 1e-13 (its agreement with 1e-12 is
  reported);
* the compiled loop's work-precision sweep (tol 1e-5 … 1e-13) interpolated at heyoka.py's errors (numbers
  quoted in issue #7, not measured here);
* time to first result in fresh processes (import + derivation, rhs and field JIT, loading or compiling the
  generic loops, first integration): with an empty cache, with the loops cached but a new model (the usual
  case: the loops compile once per machine), and with the same model again.

Writes ``benchmarks/results/compiled_loop.md``. Run ``python benchmarks/compiled_loop.py`` (``--quick``: N = 2, 5,
fewer repeats).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import scipy
from scipy.integrate import solve_ivp

RESULTS = Path(__file__).parent / "results"
TOLS = (1e-6, 1e-9, 1e-12)
SWEEP = tuple(10.0 ** -k for k in range(5, 14))
#: heyoka.py Taylor integrator, same problem, from issue #7: N -> [(final error, ms)]
HEYOKA = {2: [(1.5e-7, 0.2), (2e-11, 0.4), (3e-13, 0.8)], 5: [(4e-4, 2.0), (6e-8, 4.0), (2e-10, 7.0)]}

_CHILD = """
import json, sys, time
import numpy as np
t0 = time.perf_counter()
from lagrange.examples import n_link_pendulum
from lagrange.integrate.compiled import loops, run_loop
n = int(sys.argv[1])
s = n_link_pendulum(n)
_ = s.derived
t1 = time.perf_counter()
import numba  # noqa: E402,F401
t1b = time.perf_counter()
m = s.compile({"g": 9.81}, backend="numba")
t2 = time.perf_counter()
lp = loops()
t3 = time.perf_counter()
y0 = np.array([0.6 * (-1) ** i / (i + 1) for i in range(n)] + [0.0] * n)
run_loop(m, "DOP853", (0.0, 10.0), y0, [10.0], rtol=1e-9, atol=1e-9)
t4 = time.perf_counter()
print(json.dumps({"import+derive": t1 - t0, "import numba": t1b - t1, "codegen+rhs+field JIT": t2 - t1b,
                  "loops JIT/load": t3 - t2, "first integration": t4 - t3, "total": t4 - t0,
                  "loops compiled": sum(lp.dop853.stats.cache_misses.values()) > 0}))
"""
_LOOPS_ONLY = "from lagrange.integrate.compiled import loops; loops()"

#: the fresh-process scenarios of :func:`first_call_times`
SCENARIOS = ("empty cache", "new model, loops cached", "same model again")


def first_call_times(n: int) -> dict:
    """Seconds per phase in fresh processes: with an empty cache (the loops and the model compile), with the
    loops already cached by an earlier process but a new model (the usual first call), and the same model
    again (everything cached)."""
    out = {}
    with tempfile.TemporaryDirectory() as cold, tempfile.TemporaryDirectory() as primed:
        for label, cache, prime in zip(SCENARIOS, (cold, primed, primed), (False, True, False)):
            env = dict(os.environ, LAGRANGE_CACHE_DIR=cache)
            env.pop("NUMBA_CACHE_DIR", None)
            if prime:
                subprocess.run([sys.executable, "-c", _LOOPS_ONLY], env=env, check=True)
            r = subprocess.run([sys.executable, "-c", _CHILD, str(n)], env=env, capture_output=True, text=True,
                               check=True)
            out[label] = json.loads(r.stdout.strip().splitlines()[-1])
    return out


def median_time(fn, repeats: int) -> float:
    fn()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def run(ns, repeats: int, scipy_repeats: int):
    rows = {}
    for n in ns:
        rows[n] = measure(n, repeats, scipy_repeats)
        print(f"N={n}: done", flush=True)
    return rows


def measure(n: int, repeats: int, scipy_repeats: int) -> dict:
    """All measurements for one N."""
    from lagrange.examples import n_link_pendulum
    from lagrange.integrate.compiled import run_loop

    s = n_link_pendulum(n)
    py = s.compile({"g": 9.81}, backend="python")
    nb = s.compile({"g": 9.81}, backend="numba")
    y0 = np.array([0.6 * (-1) ** i / (i + 1) for i in range(n)] + [0.0] * n)
    ic = {**{f"q{i + 1}": y0[i] for i in range(n)}, **{f"q{i + 1}_dot": 0.0 for i in range(n)}}

    def loop(tol):
        return run_loop(nb, "DOP853", (0.0, 10.0), y0, [10.0], rtol=tol, atol=tol)

    ref = loop(1e-13).z[-1]
    consistency = float(np.max(np.abs(ref - loop(1e-12).z[-1])))
    table = []
    for tol in TOLS:
        res = {}
        for label, fun in (("scipy+python rhs", py.fun), ("scipy+numba rhs", nb.fun)):
            sol = solve_ivp(fun, (0.0, 10.0), y0, method="DOP853", rtol=tol, atol=tol, t_eval=[10.0])
            wall = median_time(lambda fun=fun, tol=tol: solve_ivp(fun, (0.0, 10.0), y0, method="DOP853", rtol=tol,
                                                                  atol=tol, t_eval=[10.0]), scipy_repeats)
            res[label] = (wall, float(np.max(np.abs(sol.y[:, -1] - ref))), sol.nfev)
        r = loop(tol)
        res["compiled loop"] = (median_time(lambda tol=tol: loop(tol), repeats),
                                float(np.max(np.abs(r.z[-1] - ref))), r.nfev)
        wall = median_time(lambda tol=tol: s.simulate(10, ic, {"g": 9.81}, rtol=tol, atol=tol, t_eval=[10.0],
                                                      model=nb, loop="compiled"), repeats)
        res["simulate(loop='compiled')"] = (wall, res["compiled loop"][1], r.nfev)
        table.append((tol, res))
    sweep = [(float(np.max(np.abs(loop(tol).z[-1] - ref))), median_time(lambda tol=tol: loop(tol), repeats))
             for tol in SWEEP if tol >= 1e-12]
    return dict(table=table, consistency=consistency, sweep=sweep, first=first_call_times(n))


def at_error(sweep, err: float) -> float | None:
    """Wall time of the compiled loop at final error ``err`` (log-log interpolation of the sweep)."""
    pts = sorted((e, w) for e, w in sweep if e > 0)
    es, ws = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    if not (es[0] <= np.log(err) <= es[-1]):
        return None
    return float(np.exp(np.interp(np.log(err), es, ws)))


def write(rows) -> str:
    import lagrange

    try:
        import numba

        nbv = numba.__version__
    except ImportError:  # pragma: no cover
        nbv = "absent"
    lines = [
        "# Compiled DOP853 loop vs solve_ivp (N-link pendulum, t in [0, 10], one run, side by side)",
        "",
        f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, numba {nbv}, lagrange "
        f"{lagrange.__version__}. Times are medians; other processes may load the machine, so read ratios.",
        "",
        "The DOP853/RK45 loops are generic (lagrange/integrate/_rk_loops.py), compiled once per machine and "
        "cached; each model passes its eagerly compiled `field` as a numba first-class function. Before, the "
        "loops were generated into every model's module and their JIT cost 5.9-7.4 s per new model on this "
        "machine. Per-step cost against those inlined loops (measured once, same process, interleaved, min of 15; "
        "results bitwise identical): N = 2 x0.82-1.05, N = 5 x1.25-1.38, N = 10 x1.04-1.28.",
        "",
    ]
    for n, row in rows.items():
        lines += [f"## N = {n}", "",
                  f"Reference: compiled DOP853 at 1e-13 (agrees with 1e-12 to {row['consistency']:.1e}).", "",
                  "| tol | scipy+python rhs: ms / error / nfev | scipy+numba rhs | compiled loop | "
                  "simulate(loop='compiled') | speed-up loop vs scipy+numba | vs scipy+python |",
                  "|---|---|---|---|---|---|---|"]
        for tol, res in row["table"]:
            a, b, c, d = (res[k] for k in ("scipy+python rhs", "scipy+numba rhs", "compiled loop",
                                           "simulate(loop='compiled')"))
            lines.append(f"| {tol:.0e} | {a[0] * 1e3:.2f} / {a[1]:.1e} / {a[2]} | {b[0] * 1e3:.2f} / {b[1]:.1e} / "
                         f"{b[2]} | {c[0] * 1e3:.3f} / {c[1]:.1e} / {c[2]} | {d[0] * 1e3:.3f} | x{b[0] / c[0]:.0f} | "
                         f"x{a[0] / c[0]:.0f} |")
        if n in HEYOKA:
            lines += ["", "Against heyoka.py (Taylor, numbers quoted in issue #7, not re-measured here): compiled "
                      "loop time at heyoka's final error, from the loop's work-precision sweep:", "",
                      "| heyoka error | heyoka ms | compiled loop ms (interpolated) | ratio loop/heyoka |",
                      "|---|---|---|---|"]
            for err, ms in HEYOKA[n]:
                w = at_error(row["sweep"], err)
                lines.append(f"| {err:.1e} | {ms} | {'out of range' if w is None else f'{w * 1e3:.3f}'} | "
                             f"{'-' if w is None else f'{w * 1e3 / ms:.2f}'} |")
        lines += ["", "Work-precision sweep of the compiled loop (tol: final error, ms): "
                  + "; ".join(f"{e:.1e}, {w * 1e3:.3f}" for e, w in row["sweep"]), ""]
        phases = [k for k in row["first"][SCENARIOS[0]] if k != "loops compiled"]
        lines += ["First call in a fresh process, seconds per phase (`loops JIT/load`: the generic loops, "
                  "compiled once per machine):", "",
                  "| scenario | " + " | ".join(phases) + " |", "|---" * (len(phases) + 1) + "|"]
        lines += [f"| {sc} | " + " | ".join(f"{row['first'][sc][k]:.2f}" for k in phases) + " |" for sc in SCENARIOS]
        lines.append("")
    text = "\n".join(lines) + "\n"
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "compiled_loop.md").write_text(text)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="N = 2, 5 and fewer repeats")
    ap.add_argument("--n", type=int, nargs="+")
    args = ap.parse_args()
    ns = args.n or ([2, 5] if args.quick else [2, 5, 10])
    rows = run(ns, repeats=5 if args.quick else 11, scipy_repeats=1 if args.quick else 3)
    print(write(rows))


if __name__ == "__main__":
    main()
