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

Two more parts (``--part cache``, ``--part batch``; ``--part all`` runs the three):

* **first result, cold vs warm from disk** (``benchmarks/results/heyoka_cache.md``): a NEW process per run
  (imports counted) runs ``simulate(method="heyoka")`` on an n-link pendulum. ``cold``: the derivation cache is
  warm but there is no heyoka entry (the LLVM compile is paid); ``warm_disk``: the integrator is loaded from the
  sealed on-disk cache (:mod:`lagrange.codegen.heyoka_jit`); ``direct``: heyoka used directly in a new process
  (``heyoka.lagrangian`` + ``taylor_adaptive``: its first build compiles, its in-memory cache makes a second
  build in the same process cheap; both reported). Interleaved (cold, warm_disk, direct, ...); wall time from
  the parent, CPU of the child (``getrusage(RUSAGE_CHILDREN)``), and the time of the call itself inside the
  child (imports excluded).
* **batch mode** (``benchmarks/results/heyoka_batch.md``): ``integrate_ensemble(model, ..., method="heyoka")``
  (:mod:`lagrange.integrate.heyoka_batch`) against heyoka's ``taylor_adaptive_batch`` used directly on
  ``heyoka.lagrangian`` equations of the same pendulum (g a runtime parameter in both), per member, warm (the
  first call, which compiles, is reported separately), interleaved; and the default ensemble (DOP853) when the
  ensemble is small.

Run ``python benchmarks/heyoka_backend.py [--quick] [--part warm|cache|batch|all]``; writes
``benchmarks/results/heyoka_backend.md`` (and the two files above).
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
    ap.add_argument("--part", choices=("warm", "cache", "batch", "all"), default="all")
    args = ap.parse_args(argv)
    if args.part in ("cache", "all"):
        cache_part(args.quick, args.rounds)
    if args.part in ("batch", "all"):
        batch_part(args.quick, args.rounds)
    if args.part not in ("warm", "all"):
        return 0
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


# --- first result in a new process: cold (LLVM compile) vs warm from the on-disk cache vs heyoka directly ---

_CHILD = r"""
import json, sys, time
links, tol, route = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
c0, w0 = time.process_time(), time.perf_counter()
from lagrange.examples import n_link_pendulum
start = {f"q{i + 1}": 0.5 for i in range(links)} | {f"q{i + 1}_dot": 0.0 for i in range(links)}
s = n_link_pendulum(links)
out = {}
if route == "direct":
    import numpy as np
    from lagrange.bench.heyoka_adapter import heyoka_model
    hm = heyoka_model(s, {"g": 9.81})
    y0 = np.array(list(start.values()), float)
    c1, w1 = time.process_time(), time.perf_counter()
    ta, _ = hm.integrator(y0, tol)
    hm.propagate(ta, y0, [1.0])
    out["call_cpu"], out["call_wall"] = time.process_time() - c1, time.perf_counter() - w1
    c2, w2 = time.process_time(), time.perf_counter()
    ta, _ = hm.integrator(y0, tol)  # heyoka's in-memory cache: the same system again in this process
    hm.propagate(ta, y0, [1.0])
    out["second_cpu"], out["second_wall"] = time.process_time() - c2, time.perf_counter() - w2
else:
    from lagrange.integrate import heyoka_backend
    c1, w1 = time.process_time(), time.perf_counter()
    s.simulate(1.0, start, {"g": 9.81}, method="heyoka", rtol=tol, atol=tol, t_eval=[1.0])
    out["call_cpu"], out["call_wall"] = time.process_time() - c1, time.perf_counter() - w1
    out["compiled"], out["loaded"] = heyoka_backend.compilations(), heyoka_backend.disk_loads()
print(json.dumps(out))
"""


def _child(cache: Path, links: int, tol: float, route: str) -> dict:
    """Run one first result in a new process; its CPU (rusage of children), wall, and what it printed."""
    import json
    import resource
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    env = {**os.environ, "LAGRANGE_CACHE_DIR": str(cache),
           "PYTHONPATH": os.pathsep.join([str(root / ".pp"), str(root), os.environ.get("PYTHONPATH", "")])}
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", _CHILD, str(links), repr(tol), route], env=env, check=True,
                          capture_output=True, text=True)
    wall = time.perf_counter() - w0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = json.loads(done.stdout.strip().splitlines()[-1])
    out["cpu"] = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    out["wall"] = wall
    return out


def cache_part(quick: bool, rounds: int | None) -> None:
    """The first-result table (module docstring) -> ``benchmarks/results/heyoka_cache.md``."""
    import shutil
    import tempfile

    import heyoka

    rounds = rounds or (2 if quick else 5)
    cases = [(2, 1e-12)] if quick else [(2, 1e-12), (5, 1e-12)]
    routes = ("cold", "warm_disk", "direct")
    lines = ["# heyoka: first result in a new process, cold vs warm from the on-disk cache vs heyoka directly", "",
             f"`python benchmarks/heyoka_backend.py --part cache{' --quick' if quick else ''}`, heyoka "
             f"{heyoka.__version__}, {platform.machine()}, {os.cpu_count()} cores (shared, load average "
             f"{os.getloadavg()[0]:.0f}), {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {rounds} rounds "
             "interleaved (cold, warm_disk, direct); medians. Process: a new Python process, imports included "
             "(wall from the parent, CPU = the child's user + system time). Call: inside the child, the `simulate` "
             "call (it loads the derived equations and imports heyoka) or, for `direct`, heyoka's build + propagation "
             "(heyoka imported and its equations derived before). `direct 2nd`: "
             "heyoka's second build of the same system in the same process (its in-memory cache).", "",
             "| system | tol | route | process wall s | process CPU s | call wall s | call CPU s | compiled/loaded |",
             "|---|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as tmp:
        for links, tol in cases:
            base = Path(tmp) / f"base{links}"
            _child(base, links, tol, "cold")  # derivation cache + heyoka entry
            warm = Path(tmp) / f"warm{links}"
            shutil.copytree(base, warm)
            res = {r: [] for r in routes}
            for k in range(rounds):
                cold = Path(tmp) / f"cold{links}_{k}"
                shutil.copytree(base, cold)
                for entry in cold.glob("heyoka_*.pkl"):
                    entry.unlink()  # derivation cached, LLVM compile to pay
                res["cold"].append(_child(cold, links, tol, "cold"))
                res["warm_disk"].append(_child(warm, links, tol, "warm_disk"))
                res["direct"].append(_child(cold, links, tol, "direct"))
            for r in routes:
                def med(key, runs=res[r]):
                    return statistics.median(x[key] for x in runs)
                flag = (f"{res[r][-1]['compiled']}/{res[r][-1]['loaded']}" if r != "direct" else "-")
                lines.append(f"| {links}-link pendulum | {tol:g} | {r} | {med('wall'):.2f} | {med('cpu'):.2f} "
                             f"| {med('call_wall'):.3f} | {med('call_cpu'):.3f} | {flag} |")
                if r == "direct":
                    lines.append(f"| {links}-link pendulum | {tol:g} | direct 2nd | - | - "
                                 f"| {med('second_wall'):.3f} | {med('second_cpu'):.3f} | - |")
            print("\n".join(lines[-4:]), flush=True)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "heyoka_cache.md").write_text("\n".join(lines) + "\n")
    print(f"wrote {RESULTS / 'heyoka_cache.md'}")


# --- batch mode: integrate_ensemble(method="heyoka") vs taylor_adaptive_batch used directly ----------------------

def _direct_batch(system, B: int, tol: float):
    """heyoka's own equations of ``system`` (``heyoka.lagrangian``, g as runtime parameter par[0]) in a
    ``taylor_adaptive_batch`` of ``B`` lanes; returns ``run(Y0, P, t_eval) -> (k, m, 2n)``."""
    import heyoka as hy
    import sympy as sp

    eqs = system.derived
    (g,) = eqs.parameters
    n = eqs.n
    qv = list(hy.make_vars(*[f"dq{i}" for i in range(n)]))
    qdv = list(hy.make_vars(*[f"dqd{i}" for i in range(n)]))
    table = dict(zip(eqs.q, qv)) | dict(zip(eqs.qd, qdv)) | {g: hy.par[0]}
    L = sp.nfloat(eqs.kinetic - eqs.potential, exponent=False)
    odes = hy.lagrangian(hy.from_sympy(L, table), qv, qdv)
    ta = hy.taylor_adaptive_batch(odes, np.zeros((2 * n, B)), tol=tol, pars=np.zeros((1, B)),
                                  compact_mode=int(sp.count_ops(L)) > 100)

    def run(Y0, P, t_eval):
        k = Y0.shape[0]
        out = np.empty((k, t_eval.size, 2 * n))
        grid = np.ascontiguousarray(np.repeat(t_eval[:, None], B, axis=1))
        for g0 in range(0, k, B):
            rows = np.minimum(np.arange(g0, g0 + B), k - 1)
            ta.set_time(np.full(B, t_eval[0]))
            ta.state[:] = Y0[rows].T
            ta.pars[:] = P[rows].T
            res = ta.propagate_grid(grid)
            real = min(B, k - g0)
            out[g0:g0 + real] = np.transpose(np.asarray(res[-1])[:, :, :real], (2, 0, 1))
        return out

    return run


def batch_part(quick: bool, rounds: int | None) -> None:
    """The batch table (module docstring) -> ``benchmarks/results/heyoka_batch.md``."""
    import heyoka

    from lagrange.examples import n_link_pendulum
    from lagrange.integrate.heyoka_batch import batch_size
    from lagrange.sweep import integrate_ensemble

    rounds = rounds or (3 if quick else 5)
    links, k, tol = (3, 64, 1e-10) if quick else (10, 1000, 1e-10)
    system = n_link_pendulum(links)
    model = system.compile({"g": 9.81})
    rng = np.random.default_rng(7)
    Y0 = np.hstack([rng.uniform(-0.5, 0.5, (k, links)), np.zeros((k, links))])
    P = rng.uniform(5.0, 15.0, (k, 1))
    t_eval = np.linspace(0.0, 1.0, 11)
    B = batch_size()
    w0, c0 = time.perf_counter(), time.process_time()
    direct = _direct_batch(system, B, tol)
    first = {"direct_batch": (time.perf_counter() - w0, time.process_time() - c0)}
    routes = {"ensemble_heyoka": lambda: integrate_ensemble(model, (0.0, 1.0), Y0, P, method="heyoka", rtol=tol,
                                                            atol=tol, t_eval=t_eval).y,
              "direct_batch": lambda: direct(Y0, P, t_eval)}
    if k <= 100:
        routes["ensemble_DOP853"] = lambda: integrate_ensemble(model, (0.0, 1.0), Y0, P, method="DOP853", rtol=tol,
                                                               atol=tol, t_eval=t_eval).y
    w0, c0 = time.perf_counter(), time.process_time()
    ref = routes["ensemble_heyoka"]()
    first["ensemble_heyoka"] = (time.perf_counter() - w0, time.process_time() - c0)
    cpu = {r: [] for r in routes}
    wall = {r: [] for r in routes}
    final = {}
    for _ in range(rounds):
        for r, fn in routes.items():
            c0, w0 = time.process_time(), time.perf_counter()
            final[r] = fn()
            cpu[r].append(time.process_time() - c0)
            wall[r].append(time.perf_counter() - w0)
    med = {r: statistics.median(cpu[r]) for r in routes}
    lines = ["# heyoka batch mode: integrate_ensemble(method=\"heyoka\") vs taylor_adaptive_batch directly", "",
             f"`python benchmarks/heyoka_backend.py --part batch{' --quick' if quick else ''}`, heyoka "
             f"{heyoka.__version__}, batch size {B} (heyoka.recommended_simd_size()), {platform.machine()}, "
             f"{os.cpu_count()} cores (shared, load average {os.getloadavg()[0]:.0f}), "
             f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {links}-link pendulum, {k} members (random "
             f"angles, g per member in [5, 15]), t in [0, 1], 11 outputs, tol {tol:g}; {rounds} rounds interleaved; "
             "medians of warm calls (the first call, which compiles, in the `first` columns; imports not counted).",
             "", "| route | first wall s | first CPU s | CPU ms per member | wall ms per member | vs direct (CPU) "
             "| max abs Δy vs ensemble_heyoka |", "|---|---|---|---|---|---|---|"]
    for r in routes:
        fw, fc = first.get(r, (float("nan"), float("nan")))
        dy = float(np.nanmax(np.abs(final[r] - ref)))
        per_wall = 1e3 * statistics.median(wall[r]) / k
        lines.append(f"| {r} | {fw:.2f} | {fc:.2f} | {1e3 * med[r] / k:.3f} | {per_wall:.3f} "
                     f"| {med[r] / med['direct_batch']:.2f} | {dy:.1e} |")
    print("\n".join(lines), flush=True)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "heyoka_batch.md").write_text("\n".join(lines) + "\n")
    print(f"wrote {RESULTS / 'heyoka_batch.md'}")


if __name__ == "__main__":
    raise SystemExit(main())
