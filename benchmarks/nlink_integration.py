"""N-link pendulum, integration only, at equal error: lagrange's fastest methods against heyoka.py (issue #23, item 2).

Work–precision for the planar N-link pendulum (unit masses and rods, q_i = 0.6(−1)^i/(i+1), q̇ = 0, g = 9.81,
t ∈ [0, 10]) at N = 10, 20, 50 (``--links``) and rtol = atol = 1e-6, 1e-8, 1e-10 (``--tols``). Routes, each in
its own persistent worker process (so a set-up that does not finish can be stopped: ``--setup-timeout``, scaled
by N/10 above N = 10; a route whose set-up did not finish is not tried at larger N):

* ``taylor C tape``: ``simulate(method="taylor")`` on a python-backend model, the tape interpreted in C;
* ``taylor numba series``: the same with a numba-backend model (the tape as straight-line code, JIT per order);
* ``DOP853 numba compiled loop``: ``simulate(method="DOP853", backend="numba", loop="compiled")``, also at
  1e-11 and 1e-12 (its error at a tolerance is larger than the Taylor methods');
* ``heyoka compact``: ``heyoka.lagrangian`` on lagrange's T − V, ``taylor_adaptive(..., compact_mode=True)``;
* ``heyoka default``: the same with ``compact_mode=False`` (heyoka's fastest per step, but its LLVM compile grows
  steeply with the size of the equations).

**Set-up is excluded**: derivation, code generation, numba JIT, heyoka's derivation and LLVM compile and one
warm-up run per tolerance happen before anything is timed (their wall and CPU seconds are reported in their own
table). Each timed sample is one ``t ∈ [0, 10]`` integration from the same initial state to the final state
(runs under 20 ms are timed as the mean of a batch lasting about 20 ms), measured with ``time.perf_counter``
(wall) and ``time.process_time`` (CPU) inside the worker; imports are not counted. Samples are **interleaved**:
each round runs every (tolerance, route) once, in an order rotated from round to round, and the tables give
the **median** over rounds.

Error: max-norm of the final state against a reference — lagrange's Taylor method (C tape) at rtol = atol =
1e-16 (order 20, ε-limited) — cross-checked against DOP853 (numba compiled loop) at 1e-13 and heyoka (compact) at
its default tolerance ε: errors below those distances are not meaningful. The pendulum is chaotic (errors grow
by orders of magnitude over t = 10), so rtol is not the achieved accuracy; the comparison is at equal
**achieved** error: for every heyoka point, each lagrange route's CPU time at that error is interpolated
log-linearly on its work–precision curve (no extrapolation), and the ratio is the best lagrange route / heyoka
(below 1: lagrange is faster). Writes ``results/nlink_integration.md`` and ``results/nlink_integration.png``.

``--derivation structural|expanded|auto`` builds the pendulum with ``System(..., derivation=...)`` (refused
with a clear message when the installed System has no such keyword). Run::

    python benchmarks/nlink_integration.py --quick     # N = 5 and 10, two tolerances, three routes (~1 min)
    python benchmarks/nlink_integration.py             # N = 10, 20, 50: 30+ minutes on a loaded 2-core box
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).parent / "results"

#: route → label (see the module docstring)
ROUTES = {
    "taylor_c": "lagrange taylor, C tape",
    "taylor_series": "lagrange taylor, numba series",
    "dop853_compiled": "lagrange DOP853, numba compiled loop",
    "heyoka_compact": "heyoka compact_mode",
    "heyoka_default": "heyoka default mode",
}
LAGRANGE_ROUTES = ("taylor_c", "taylor_series", "dop853_compiled")
HEYOKA_ROUTES = ("heyoka_compact", "heyoka_default")
QUICK_ROUTES = ("taylor_c", "dop853_compiled", "heyoka_compact")
#: DOP853's error at a tolerance is 10–100× the Taylor methods' there: two tighter points extend its curve to the
#: errors the Taylor methods reach (equal-error comparison without extrapolation)
DOP853_EXTRA_TOLS = (1e-11, 1e-12)
REFERENCE_TOL = 1e-16
CHECK_DOP853_TOL = 1e-13
T_END = 10.0
BATCH_S = 0.02  # runs shorter than this are timed as the mean of a batch lasting about this long


# --- the worker: one route, set up once, then timed runs on request ----------------------------------------
class _Worker:
    def __init__(self, n: int, route: str, system_kwargs: dict):
        from lagrange.bench.problems import get_problem

        self.route = route
        self.p = get_problem(f"nlink{n}", system_kwargs=system_kwargs)
        self.system = self.p.build()
        _ = self.system.derived
        self.y0 = np.array([0.6 * (-1) ** i / (i + 1) for i in range(n)] + [0.0] * n)
        self.runs: dict = {}
        if route.startswith("heyoka"):
            from lagrange.bench.heyoka_adapter import heyoka_model

            self.hm = heyoka_model(self.system, self.p.params)
        else:
            self.model = self.system.compile(self.p.params, backend="python" if route == "taylor_c" else "numba")

    def prepare(self, tol: float, *, warm: bool = True):
        """Build what ``tol`` needs (integrator, compiled series) and warm it up (``warm``)."""
        if tol in self.runs:
            return
        if self.route.startswith("heyoka"):
            ta, _ = self.hm.integrator(self.y0, tol, compact=self.route == "heyoka_compact")
            self.ta = ta

            def run():
                ta.time = 0.0
                ta.state[:] = self.y0
                out = ta.propagate_until(T_END)
                return np.array(ta.state, dtype=float), int(out[3])  # steps
        else:
            method = "DOP853" if self.route == "dop853_compiled" else "taylor"
            backend = self.model.backend
            extra = {"loop": "compiled"} if method == "DOP853" else {}
            if method == "taylor" and backend == "numba":
                from lagrange.integrate.taylor import taylor_order

                self.model.taylor_series(taylor_order(tol))

            def run():
                sol = self.system.simulate((0.0, T_END), self.p.initial, self.p.params, method=method, rtol=tol,
                                           atol=tol, backend=backend, model=self.model, t_eval=[T_END], **extra)
                return np.asarray(sol.y[-1], dtype=float), int(sol.nfev)
        if warm:
            run()  # warm-up (and JIT of anything left)
        self.runs[tol] = run

    def once(self, tol: float) -> dict:
        """One untimed run (references and cross-checks)."""
        self.prepare(tol, warm=False)
        y, work = self.runs[tol]()
        return dict(state=y.tolist(), work=work)

    def profile(self) -> dict:
        """Per-call costs of what this route runs (see the profile table's caption in :func:`write`)."""
        import timeit

        n = self.p.pendulum_links
        y = np.concatenate([self.y0[:n], np.full(n, 0.1)])

        def per_call(f, k):
            f()
            return statistics.median(timeit.repeat(f, number=k, repeat=7)) / k

        if self.route == "taylor_c":
            tape = self.model.taylor_tape()
            return dict(tape=tape.size, entries=f"{int((tape.mass >= 0).sum())} / {tape.force.size}")
        if self.route == "dop853_compiled":
            import numba

            @numba.njit(cache=False)
            def ldl_solves(A0, b0, k):  # the rhs's dense LDLᵀ solve alone, as loops in compiled code
                n = A0.shape[0]
                A, x = np.empty_like(A0), np.empty_like(b0)
                for _ in range(k):
                    A[:, :] = A0
                    x[:] = b0
                    for j in range(n):  # L below the diagonal, D on it
                        for i in range(j, n):
                            s = A[i, j]
                            for m in range(j):
                                s -= A[i, m] * A[j, m] * A[m, m]
                            A[i, j] = s if i == j else s / A[j, j]
                    for i in range(n):
                        for m in range(i):
                            x[i] -= A[i, m] * x[m]
                    for i in range(n):
                        x[i] /= A[i, i]
                    for i in range(n - 1, -1, -1):
                        for m in range(i + 1, n):
                            x[i] -= A[m, i] * x[m]
                return x

            M, f = self.model.mass_and_forcing(0.0, y)
            assert np.allclose(ldl_solves(M, f, 1), np.linalg.solve(M, f), rtol=1e-9, atol=1e-12)
            k = 200
            return dict(fun=per_call(lambda: self.model.fun(0.0, y), 200),
                        numba_solve=per_call(lambda: ldl_solves(M, f, k), 1) / k)
        if self.route.startswith("heyoka"):  # heyoka's elementary operations per Taylor order
            return dict(heyoka_ops=len(self.ta.decomposition) - 2 * n)
        return {}

    def time(self, tol: float) -> dict:
        self.prepare(tol)
        run = self.runs[tol]
        w0, c0 = time.perf_counter(), time.process_time()
        y, work = run()
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        if wall < BATCH_S:
            k = max(1, math.ceil(BATCH_S / max(wall, 1e-6)))
            w0, c0 = time.perf_counter(), time.process_time()
            for _ in range(k):
                y, work = run()
            wall, cpu = (time.perf_counter() - w0) / k, (time.process_time() - c0) / k
        return dict(wall=wall, cpu=cpu, state=y.tolist(), work=work)


def _worker_main(spec: str) -> None:
    a = json.loads(spec)
    w0, c0 = time.perf_counter(), time.process_time()
    try:
        w = _Worker(a["n"], a["route"], a.get("system_kwargs") or {})
        for tol in a["tols"]:
            w.prepare(tol)
    except Exception as exc:  # noqa: BLE001 - reported to the parent as the route's result
        print(json.dumps(dict(error=f"{type(exc).__name__}: {str(exc)[:300]}")), flush=True)
        return
    print(json.dumps(dict(ready=True, setup_wall=time.perf_counter() - w0, setup_cpu=time.process_time() - c0)),
          flush=True)
    for line in sys.stdin:
        req = json.loads(line)
        if req.get("quit"):
            break
        try:
            if req.get("profile"):
                print(json.dumps(w.profile()), flush=True)
                continue
            if req.get("once"):
                print(json.dumps(w.once(req["tol"])), flush=True)
                continue
            w0, c0 = time.perf_counter(), time.process_time()
            w.prepare(req["tol"])
            extra = dict(extra_setup_wall=time.perf_counter() - w0, extra_setup_cpu=time.process_time() - c0)
            print(json.dumps(w.time(req["tol"]) | extra), flush=True)
        except Exception as exc:  # noqa: BLE001
            print(json.dumps(dict(error=f"{type(exc).__name__}: {str(exc)[:300]}")), flush=True)


# --- the parent: start workers, interleave, tabulate ---------------------------------------------------------
class _Route:
    """A worker process seen from the parent."""

    def __init__(self, n: int, route: str, tols, system_kwargs: dict, timeout: float, env: dict):
        self.route, self.ok, self.note = route, False, ""
        self.setup_wall = self.setup_cpu = None
        spec = json.dumps(dict(n=n, route=route, tols=list(tols), system_kwargs=system_kwargs))
        self.proc = subprocess.Popen([sys.executable, __file__, "--worker", spec], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        reply = self._read(timeout)
        if reply is None:
            self.note = f"set-up did not finish within {timeout:g} s (stopped)"
            self.close()
        elif "error" in reply:
            self.note = f"failed: {reply['error']}"
            self.close()
        else:
            self.ok, self.setup_wall, self.setup_cpu = True, reply["setup_wall"], reply["setup_cpu"]

    def _read(self, timeout: float):
        import selectors

        sel = selectors.DefaultSelector()
        sel.register(self.proc.stdout, selectors.EVENT_READ)
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0 or not sel.select(left):
                return None
            line = self.proc.stdout.readline()
            if not line:  # the worker died
                err = self.proc.stderr.read().strip().splitlines()
                return dict(error=(err or ["worker exited"])[-1][:300])
            if line.startswith("{"):
                return json.loads(line)

    def ask(self, tol: float | None, timeout: float, **how) -> dict | None:
        """Time one run at ``tol`` (``once=True``: one untimed run; ``profile=True``: the per-call profile)."""
        self.proc.stdin.write(json.dumps(dict(tol=tol, **how)) + "\n")
        self.proc.stdin.flush()
        reply = self._read(timeout)
        if reply is None:
            self.note = f"a run at tol {tol:g} took over {timeout:g} s (stopped)"
            self.close()
        return reply

    def close(self):
        self.ok = False
        if self.proc.poll() is None:
            try:
                self.proc.stdin.write(json.dumps(dict(quit=True)) + "\n")
                self.proc.stdin.flush()
                self.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()
                self.proc.wait()


#: errors within this factor of a curve's end count as that end (two Taylor runs with the same steps differ
#: in the last digits)
EQUAL_ERROR = 1.1


class _Skipped:
    ok, setup_wall, setup_cpu = False, None, None

    def __init__(self, note: str):
        self.note = note

    def close(self):
        pass


def _interp_cpu(points, err: float) -> float | None:
    """CPU time of a route at ``err``: log-linear interpolation on its (error, cpu) points, no extrapolation
    (beyond :data:`EQUAL_ERROR`)."""
    pts = sorted((p["error"], p["cpu"]) for p in points if p["error"] > 0)
    if len(pts) < 1 or not (pts[0][0] / EQUAL_ERROR <= err <= pts[-1][0] * EQUAL_ERROR):
        return None
    if len(pts) == 1:
        return pts[0][1]
    le = np.log([e for e, _ in pts])
    lc = np.log([c for _, c in pts])
    return float(np.exp(np.interp(math.log(err), le, lc)))


def measure(n: int, routes, tols, *, repeats: int, system_kwargs: dict, setup_timeout: float, run_timeout: float,
            stop: float, env: dict, log, do_profile: bool = True, skip: dict | None = None) -> dict:
    """Every route at every tolerance for the N-link pendulum: the setups, the reference and the interleaved
    samples (see the module docstring). ``skip``: route → why it is not tried at this N."""
    workers = {}
    skip = skip or {}
    tols_of = {r: sorted(set(tols) | (set(DOP853_EXTRA_TOLS) if r == "dop853_compiled" else set()), reverse=True)
               for r in routes}
    for r in routes:
        if r in skip:
            workers[r] = _Skipped(skip[r])
            continue
        log(f"N={n}: setting up {r}")
        workers[r] = _Route(n, r, tols_of[r], system_kwargs, setup_timeout, env)
        log(f"N={n}: {r}: " + (f"ready in {workers[r].setup_wall:.1f} s" if workers[r].ok else workers[r].note))
    # reference and its cross-checks (not timed)
    ref, checks = None, {}
    if workers.get("taylor_c") and workers["taylor_c"].ok:
        rep = workers["taylor_c"].ask(REFERENCE_TOL, run_timeout * 3, once=True)
        if rep and "state" in rep:
            ref = np.array(rep["state"])
    for r, tol in (("dop853_compiled", CHECK_DOP853_TOL), ("heyoka_compact", 2.0**-52)):
        if ref is not None and workers.get(r) and workers[r].ok:
            rep = workers[r].ask(tol, run_timeout * 3, once=True)
            if rep and "state" in rep:
                checks[f"{ROUTES[r]} at {tol:.1g}"] = float(np.max(np.abs(np.array(rep["state"]) - ref)))
    samples: dict = {(r, tol): [] for r in routes for tol in tols_of[r]}
    stopped: set = set()
    for k in range(repeats):
        order = [(r, tol) for r in routes for tol in tols_of[r]]
        order.sort(key=lambda rt: -rt[1])  # by tolerance, the routes side by side
        order = order[k % len(order):] + order[:k % len(order)]  # rotate: no route always first after another
        for r, tol in order:
            w = workers[r]
            if not w.ok or (r, tol) in stopped:
                continue
            rep = w.ask(tol, run_timeout)
            if rep is None or "error" in rep:
                if rep:
                    w.note = f"failed at tol {tol:g}: {rep['error']}"
                continue
            samples[(r, tol)].append(rep)
            if rep["wall"] > stop:
                stopped.add((r, tol))  # one sample of a long run is enough on a shared machine
        log(f"N={n}: round {k + 1}/{repeats} done")
    profile = dict(n=n)
    if do_profile:
        for r in ("taylor_c", "dop853_compiled", "heyoka_compact"):
            if workers.get(r) and workers[r].ok:
                rep = workers[r].ask(None, run_timeout, profile=True)
                if rep and "error" not in rep:
                    profile.update(rep)
    for w in workers.values():
        w.close()
    points = {}
    for (r, tol), reps in samples.items():
        if not reps:
            continue
        err = float(np.max(np.abs(np.array(reps[-1]["state"]) - ref))) if ref is not None else float("nan")
        points.setdefault(r, []).append(dict(
            tol=tol, wall=statistics.median(x["wall"] for x in reps), cpu=statistics.median(x["cpu"] for x in reps),
            error=err, work=reps[-1]["work"], samples=len(reps)))
    return dict(n=n, points=points, checks=checks, reference=ref is not None, profile=profile,
                setup={r: (w.setup_wall, w.setup_cpu, w.note) for r, w in workers.items()})


def ratios(result: dict) -> list[dict]:
    """For each heyoka point: the best lagrange route's interpolated CPU time at heyoka's error, and the ratio."""
    out = []
    pts = result["points"]
    for h in HEYOKA_ROUTES:
        for hp in pts.get(h, []):
            best = None
            for r in LAGRANGE_ROUTES:
                c = _interp_cpu(pts.get(r, []), hp["error"])
                if c is not None and (best is None or c < best[1]):
                    best = (r, c)
            out.append(dict(heyoka=h, tol=hp["tol"], error=hp["error"], heyoka_cpu=hp["cpu"],
                            best=best[0] if best else None, lagrange_cpu=best[1] if best else None,
                            ratio=best[1] / hp["cpu"] if best else None))
    return out


def _t(s) -> str:
    if s is None:
        return "—"
    return (f"{s:.2f} s" if s >= 1 else f"{s * 1e3:.1f} ms" if s >= 1e-3 else f"{s * 1e6:.0f} µs" if s >= 1e-5
            else f"{s * 1e6:.2f} µs")


def write(results: list, args, path: Path) -> None:
    from lagrange.bench.report import machine_info

    m = machine_info()
    doc = __doc__.split("\n\n")
    lines = ["# N-link pendulum: integration at equal error, lagrange against heyoka", "",
             f"Machine: {m.get('cpu', '?')}, {m.get('cores', '?')} logical cores, shared with other work (load average "
             f"{os.getloadavg()[0]:.1f} when this table was written: wall times stretch with it, CPU times much less). "
             "Versions: "
             + ", ".join(f"{k} {v}" for k, v in m.get("versions", {}).items() if v) + ".", "",
             "Run: `" + " ".join(["python benchmarks/nlink_integration.py", *sys.argv[1:]]) + "`; "
             f"{args.repeats} interleaved rounds; derivation: "
             + (f"`System(..., derivation={args.derivation!r})`" if args.derivation else "the default path") + ".",
             "", *(d if "\n* " in d else d.replace("\n", " ") for d in doc[1:4]), ""]
    summary = ["## Summary: lagrange / heyoka CPU time at equal error", "",
               "Best lagrange route at heyoka's achieved error (log-linear interpolation on the lagrange curve; "
               "— where heyoka's error lies outside the lagrange curves' range). Below 1: lagrange is faster. "
               "The target of issue #23 is ≤ 2.", "",
               "| N | heyoka mode | tol | heyoka error | heyoka CPU | best lagrange route | its CPU at that error "
               "| lagrange / heyoka |", "|---|---|---|---|---|---|---|---|"]
    body = []
    for res in results:
        n = res["n"]
        for rt in ratios(res):
            summary.append(f"| {n} | {ROUTES[rt['heyoka']]} | {rt['tol']:.0e} | {rt['error']:.1e} | "
                           f"{_t(rt['heyoka_cpu'])} | {ROUTES.get(rt['best'], '—')} | {_t(rt['lagrange_cpu'])} | "
                           + (f"**{rt['ratio']:.2f}**" if rt["ratio"] is not None else "—") + " |")
        body += [f"## N = {n}", ""]
        if res["checks"]:
            body += ["Reference: lagrange taylor (C tape) at rtol 1e-16; distance from " + "; ".join(
                f"{k}: {v:.1e}" for k, v in res["checks"].items()) + ".", ""]
        elif not res["reference"]:
            body += ["No reference (the Taylor route did not set up): errors are not available.", ""]
        body += ["Set-up (excluded from the times below): wall / CPU seconds in the worker, imports not counted.", "",
                 "| route | set-up wall | set-up CPU | note |", "|---|---|---|---|"]
        for r, (sw, sc, note) in res["setup"].items():
            body.append(f"| {ROUTES[r]} | {_t(sw)} | {_t(sc)} | {note} |")
        tols = sorted({p["tol"] for pts in res["points"].values() for p in pts}, reverse=True)
        body += ["", "Integration, t ∈ [0, 10]: median CPU · median wall · error · work (nfev for DOP853, "
                 "tape passes = steps × order for lagrange's Taylor, steps for heyoka) · samples.", "",
                 "| route | " + " | ".join(f"tol {t:.0e}" for t in tols) + " |",
                 "|---|" + "---|" * len(tols)]
        for r, pts in res["points"].items():
            by = {p["tol"]: p for p in pts}
            cells = [f"{_t(by[t]['cpu'])} · {_t(by[t]['wall'])} · {by[t]['error']:.1e} · {by[t]['work']} · "
                     f"{by[t]['samples']}" if t in by else "—" for t in tols]
            body.append(f"| {ROUTES[r]} | " + " | ".join(cells) + " |")
        body += ["", *_per_step(res, tols), ""]
    prof = []
    profile = [r["profile"] for r in results if len(r.get("profile", {})) > 1]
    if profile:
        prof = ["## What one right-hand side costs (numba backend, one state)", "",
                "`model.fun` = the generated rhs (M and f assembled, then the linear solve, in one compiled "
                "function, called from Python; the solve is an unrolled LDLᵀ); `LDLᵀ in numba` = the same "
                "factorization and solve (n³/6 multiply-adds) written as loops in compiled code, so M and f cost "
                "about the difference. Taylor: lagrange's tape instructions per "
                "order (M and f; the interpreter solves with M on top, O(n²) per order after one LU per step) "
                "against heyoka's elementary operations per order (its decomposition of the explicit q̈, solve "
                "included). Median of 7 timeit repeats.", "",
                "| N | model.fun (numba) | LDLᵀ in numba | lagrange tape instructions | M / f entries on the tape "
                "| heyoka operations per order |", "|---|---|---|---|---|---|"]
        for row in profile:
            prof.append(f"| {row['n']} | {_t(row.get('fun'))} | {_t(row.get('numba_solve'))} "
                        f"| {row.get('tape', '—')} | {row.get('entries', '—')} | {row.get('heyoka_ops', '—')} |")
        prof.append("")
    path.write_text("\n".join(lines + summary + [""] + body + prof) + "\n", encoding="utf-8")
    _plot(results, path.with_suffix(".png"))


def _per_step(res: dict, tols) -> list[str]:
    """Taylor steps and CPU per step: lagrange's (nfev = steps × order) against heyoka's (steps)."""
    from lagrange.integrate.taylor import taylor_order

    taylor = [r for r in ("taylor_c", "taylor_series", "heyoka_compact", "heyoka_default") if r in res["points"]]
    if not taylor:
        return []
    out = ["Taylor methods per step (same step-size rule, Jorba & Zou): steps · CPU per step.", "",
           "| route | " + " | ".join(f"tol {t:.0e}" for t in tols) + " |", "|---|" + "---|" * len(tols)]
    for r in taylor:
        by = {p["tol"]: p for p in res["points"][r]}
        cells = []
        for t in tols:
            if t not in by:
                cells.append("—")
                continue
            steps = by[t]["work"] if r.startswith("heyoka") else by[t]["work"] / taylor_order(t)
            cells.append(f"{steps:.0f} · {_t(by[t]['cpu'] / max(steps, 1))}")
        out.append(f"| {ROUTES[r]} | " + " | ".join(cells) + " |")
    return out


def _plot(results, png: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(results), figsize=(4.6 * len(results), 3.8), squeeze=False,
                             constrained_layout=True)
    for ax, res in zip(axes[0], results):
        for r, pts in res["points"].items():
            pts = sorted(pts, key=lambda p: p["error"])
            ax.loglog([p["error"] for p in pts], [p["cpu"] for p in pts], "o-" if r in LAGRANGE_ROUTES else "s--",
                      label=ROUTES[r])
        ax.set_xlabel("final-state error (max norm)")
        ax.set_ylabel("CPU time per integration [s]")
        ax.set_title(f"N = {res['n']}, t ∈ [0, 10]")
        ax.legend(fontsize="x-small")
    fig.savefig(png, dpi=110)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--worker", help=argparse.SUPPRESS)
    ap.add_argument("--links", default=None, help="comma-separated N (default 10,20,50; quick: 5,10)")
    ap.add_argument("--tols", default=None, help="comma-separated rtol = atol (default 1e-6,1e-8,1e-10)")
    ap.add_argument("--routes", default=None, help="comma-separated routes: " + ", ".join(ROUTES))
    ap.add_argument("--repeats", type=int, default=None, help="interleaved rounds (default 5; quick: 3)")
    ap.add_argument("--setup-timeout", type=float, default=None, help="seconds a route's set-up may take at "
                    "N ≤ 10, N/10 times that above (default 180; quick: 40)")
    ap.add_argument("--derivation", default=None, help="pass System(..., derivation=...) through")
    ap.add_argument("--profile", action=argparse.BooleanOptionalAction, default=None,
                    help="per-call rhs profile (default on, off in --quick)")
    ap.add_argument("--cache-dir", default=None, help="lagrange's and numba's cache for the workers "
                    "(default: <tmp>/lagrange-nlink-bench-cache, kept between runs)")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    if args.worker:
        _worker_main(args.worker)
        return
    from lagrange.bench.heyoka_adapter import heyoka_available
    from lagrange.bench.problems import derivation_options

    system_kwargs = derivation_options(args.derivation)  # refuses an unknown keyword before anything runs
    q = args.quick
    links = [int(v) for v in (args.links or ("5,10" if q else "10,20,50")).split(",")]
    tols = [float(v) for v in (args.tols or ("1e-6,1e-9" if q else "1e-6,1e-8,1e-10")).split(",")]
    routes = args.routes.split(",") if args.routes else list(QUICK_ROUTES if q else ROUTES)
    unknown = [r for r in routes if r not in ROUTES]
    if unknown:
        ap.error(f"unknown route(s) {', '.join(unknown)}; choose from {', '.join(ROUTES)}")
    if not heyoka_available():
        print("heyoka is not installed (pip install \"lagrange-dynamics[heyoka]\"): lagrange routes only")
        routes = [r for r in routes if r not in HEYOKA_ROUTES]
    args.repeats = args.repeats or (3 if q else 5)
    setup_timeout = args.setup_timeout or (40.0 if q else 180.0)
    out = Path(args.out or RESULTS / ("nlink_integration_quick.md" if q else "nlink_integration.md"))
    out.parent.mkdir(parents=True, exist_ok=True)

    def log(msg):
        print(msg, flush=True)

    results = []
    # one cache for this benchmark, kept between runs (set-up is not measured): the first worker of each N
    # derives and JIT-compiles, the others and later runs read the entries
    cache = args.cache_dir or os.path.join(tempfile.gettempdir(), "lagrange-nlink-bench-cache"
                                           + (f"-{args.derivation}" if args.derivation else ""))
    env = dict(os.environ, LAGRANGE_CACHE_DIR=cache, NUMBA_CACHE_DIR=cache, LAGRANGE_DERIVATION_CACHE="1")
    skip: dict = {}
    for n in links:
        res = measure(n, routes, tols, repeats=args.repeats, system_kwargs=system_kwargs,
                      setup_timeout=setup_timeout * max(1.0, n / 10), run_timeout=120.0 if q else 300.0,
                      stop=2.0 if q else 10.0, env=env, log=log,
                      do_profile=args.profile if args.profile is not None else not q, skip=skip)
        results.append(res)
        for r, (_, _, note) in res["setup"].items():  # a set-up that timed out is not tried at larger N
            if note.startswith("set-up did not finish"):
                skip.setdefault(r, f"not tried: its set-up did not finish at N = {n}")
        write(results, args, out)
    print(out.read_text())


if __name__ == "__main__":
    main()
