"""Greenspan's molecular top: the discrete-gradient step before and after issue #21 (item 6), side by side.

For example 1 (dt = 1e-5), at the origin and translated by (100, −100, 0), it runs

* ``before``: the loop of commit ``191ee35`` (absolute coordinates, simplified Newton refreshed every 20 steps,
  velocities ``2(X − x)/dt − v``), loaded from git (``git show 191ee35:lagrange/discrete/pair_dg.py``);
* ``fixed point``: the current loop (positions relative to the centre of mass, increments as unknowns,
  ``v += dt F/m``, fixed-point iteration with the Newton fallback), ``solver="auto"``;
* ``Newton``: the current loop with ``solver="newton"`` (full Newton on every step),

and reports CPU and wall time per step, the energy drift ``max|E_k − E_0|`` of the recorded states (evaluated
in long double, the same function for every run) in absolute terms and in ulps of |E|, and how far the
horizontal centre of mass (fixed: the paper's spin has no horizontal momentum) moved. Writes
``benchmarks/results/greenspan_solver.md``. Run::

    python benchmarks/greenspan_solver.py                 # 1,000,000 steps (t = 10)
    python benchmarks/greenspan_solver.py --steps 11000000  # the paper's run (t = 110)

CPU time (``time.process_time``) is the cost measure on a shared machine; wall time is printed beside it.
"""

from __future__ import annotations

import argparse
import importlib.util
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from lagrange.discrete import greenspan as gs

RESULTS = Path(__file__).parent / "results"
BASELINE = "191ee35"
SHIFT = np.array([100.0, -100.0, 0.0])


def _before_model(masses):
    """The pre-change ``PairSystem`` (its module text from git, relative imports made absolute)."""
    root = Path(__file__).resolve().parents[1]
    text = subprocess.run(["git", "show", f"{BASELINE}:lagrange/discrete/pair_dg.py"], cwd=root, check=True,
                          capture_output=True, text=True).stdout
    text = text.replace("from ..", "from lagrange.")
    path = Path(tempfile.mkdtemp()) / "pair_dg_before.py"
    path.write_text(text)
    spec = importlib.util.spec_from_file_location("pair_dg_before", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["pair_dg_before"] = module
    spec.loader.exec_module(module)
    import sympy as sp

    r = sp.Symbol("r", positive=True)
    return module.PairSystem(masses, gs.A_PAIR * (-1 / r**3 + 1 / r**5), r, weights=[0.0, gs.G, gs.G, gs.G],
                             fixed=[(0, 2)])


def _measure(label, integrate, model, x0, v0, steps, offset):
    integrate(x0 + offset, v0, 100)  # compile / warm up
    c0, w0 = time.process_time(), time.perf_counter()
    res = integrate(x0 + offset, v0, steps)
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    E = model._energy(res.x - offset, res.v)  # long double, the same for every run
    drift = float(np.max(np.abs(E - E[0])))
    com = np.einsum("i,kic->kc", model.masses, res.x) / model.masses.sum()
    moved = float(np.max(np.abs(com[:, :2] - com[0, :2])))
    iters = getattr(res, "solver_report", lambda: f"simplified Newton, {res.newton_iterations / steps:.2f} "
                    "iterations per step")()
    row = dict(label=label, offset=offset, cpu=cpu / steps * 1e9, wall=wall / steps * 1e9, drift=drift,
               ulps=drift / np.spacing(abs(float(E[0]))), rel=drift / abs(float(E[0])), moved=moved, iters=iters)
    print(f"{label:12s} offset {offset[0]:5g}: {row['cpu']:6.0f} ns CPU/step, {row['wall']:6.0f} ns wall/step, "
          f"|ΔE| {drift:.2e} ({row['ulps']:.3f} ulp), centre moved {moved:.1e}; {iters}", flush=True)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--no-before", action="store_true", help="skip the pre-change loop (needs git)")
    ap.add_argument("--no-newton", action="store_true", help="skip the Newton-only run (3× the cost)")
    args = ap.parse_args()
    ex = gs.EXAMPLES[1]
    model = gs.molecular_model(ex.masses)
    x0, v0 = gs.initial_vertices(ex)
    rec = max(1, args.steps // 1000)

    def current(solver):
        return lambda x, v, n: model.integrate(x, v, dt=1e-5, steps=n, record_every=min(rec, n), solver=solver)

    runs = [("fixed point", current("auto"))] + ([] if args.no_newton else [("Newton", current("newton"))])
    if not args.no_before:
        old = _before_model(ex.masses)
        runs.insert(0, ("before", lambda x, v, n: old.integrate(x, v, dt=1e-5, steps=n, record_every=min(rec, n))))
    rows = [_measure(label, f, model, x0, v0, args.steps, off) for off in (np.zeros(3), SHIFT) for label, f in runs]
    RESULTS.mkdir(parents=True, exist_ok=True)
    lines = [f"# Greenspan's molecular top, example 1: the step before and after (issue #21, item 6), "
             f"{args.steps:,} steps of dt = 1e-5", "",
             f"Machine: {platform.machine()}, Python {platform.python_version()}, 2 cores shared with other jobs "
             "(wall times are inflated by the load; CPU time is the cost). |E| = 1.115e6, ulp(|E|) = 2.3e-10. "
             f"`before` is commit {BASELINE}. Energy of the 1,000 recorded states in long double.", "",
             "| loop | offset | CPU / step | wall / step | max abs(E − E0) | in ulps of abs(E) | relative "
             "| centre moved | solver |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['label']} | {r['offset'][0]:g}, {r['offset'][1]:g} | {r['cpu']:.0f} ns "
                     f"| {r['wall']:.0f} ns | {r['drift']:.2e} | {r['ulps']:.3f} | {r['rel']:.1e} | {r['moved']:.1e} "
                     f"| {r['iters']} |")
    out = RESULTS / "greenspan_solver.md"
    out.write_text("\n".join(lines) + "\n")
    print(out.read_text())


if __name__ == "__main__":
    main()
