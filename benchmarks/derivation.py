"""Derivation time with and without symengine, side by side in one run.

Each (model, path) runs in a fresh process (sympy's caches cold, its deferred imports and symengine's import
done first and not timed): ``lagrange.derive.lagrange.lagrange_equations`` on the model's System, the
derivation cache off. The "sympy" path forces :func:`lagrange.derive.lagrange.kinetic_derivatives` to its
sympy branch; the "symengine" path uses symengine for every model — lagrange itself does so only from
``SYMENGINE_MIN_NODES`` nodes of T, because the symengine import (not timed here) costs more than it saves on
smaller ones. Both
must give the same mass matrix and forcing: checked at random states in every run. Writes
``benchmarks/results/derivation.md``::

    python benchmarks/derivation.py
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
MODELS = ["kepler", "double_pendulum", "top", "stiff", "nlink3", "nlink4", "nlink", "nlink10", "greenspan"]

_CHILD = r"""
import json, os, sys, time
os.environ["LAGRANGE_DERIVATION_CACHE"] = "0"
import numpy as np, sympy as sp
import lagrange
from lagrange.bench.first_result import _warm_sympy
from lagrange.derive import lagrange as L
_warm_sympy()
name, path = sys.argv[1], sys.argv[2]
if path == "symengine":
    import symengine  # noqa: F401 - an import, not timed
    L.SYMENGINE_MIN_NODES = 0  # every model: what symengine does where lagrange would not use it
else:
    L._symengine_derivatives = lambda *args: None
if name.startswith("nlink") and name != "nlink":
    from lagrange.examples import n_link_pendulum
    system = n_link_pendulum(int(name[5:]))
else:
    from lagrange.bench.problems import get_problem
    system = get_problem(name).build()
t0 = time.perf_counter()
eqs = L.lagrange_equations(system)
elapsed = time.perf_counter() - t0
args = [*eqs.q, *eqs.qd, *eqs.parameters, lagrange.t]
f = sp.lambdify(args, [*eqs.mass_matrix, *eqs.forcing])
rng = np.random.default_rng(1)
values = [np.asarray(f(*rng.uniform(0.2, 1.2, len(args))), dtype=float).tolist() for _ in range(5)]
print(json.dumps({"seconds": elapsed, "values": values, "ops": int(sum(sp.count_ops(e) for e in eqs.forcing))}))
"""


def run(name: str, path: str) -> dict:
    r = subprocess.run([sys.executable, "-c", _CHILD, name, path], capture_output=True, text=True, timeout=600,
                       env=dict(os.environ))
    if r.returncode != 0:
        raise RuntimeError(r.stderr[-2000:])
    return json.loads(r.stdout.strip().splitlines()[-1])


def main() -> None:
    import numpy as np

    from lagrange.bench.report import machine_info

    m = machine_info()
    lines = ["# Derivation time: symengine against sympy", "",
             f"Machine: {m['cpu']}, {m['cores']} logical cores. Versions: "
             + ", ".join(f"{k} {v}" for k, v in m["versions"].items() if v) + ".", "",
             "`lagrange_equations` in a fresh process per cell (median of 3), derivation cache off, imports "
             "(sympy's deferred ones and symengine, 20–40 ms) not timed: lagrange uses symengine only from "
             "`SYMENGINE_MIN_NODES` = 75 nodes of T (the 3-link pendulum), where it pays for its import. "
             "symengine differentiates T (∂T/∂q̇, the Hessian M, "
             "the convective terms); everything else (tidying, forces, constraints) is sympy in both columns. "
             "Agreement: max relative difference of M and f at 5 random states.", "",
             "| model | sympy | symengine | sympy / symengine | agreement |", "|---|---|---|---|---|"]
    for name in MODELS:
        cells = {}
        for path in ("sympy", "symengine"):
            runs = [run(name, path) for _ in range(3)]
            cells[path] = (float(np.median([r["seconds"] for r in runs])), np.array(runs[0]["values"]))
        a, b = cells["sympy"][1], cells["symengine"][1]
        agree = float(np.max(np.abs(a - b)) / max(1.0, float(np.max(np.abs(a)))))
        ratio = cells["sympy"][0] / cells["symengine"][0]
        row = (f"| {name} | {cells['sympy'][0] * 1e3:.1f} ms | {cells['symengine'][0] * 1e3:.1f} ms | ×{ratio:.1f} "
               f"| {agree:.1e} |")
        print(row, flush=True)
        lines.append(row)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "derivation.md").write_text("\n".join(lines) + "\n")
    print(f"wrote {RESULTS / 'derivation.md'}")


if __name__ == "__main__":
    main()
