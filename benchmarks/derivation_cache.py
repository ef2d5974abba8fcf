"""Derivation cache: first run vs second run of the same model in fresh processes (measured side by side).

For the double pendulum, the 5-link pendulum and the heavy top (``lagrange.bench.problems``), with the
``python`` and ``numba`` backends, each run is a fresh interpreter with ``LAGRANGE_CACHE_DIR`` set to a
temporary directory; it times ``build()`` (the declaration), ``System.derived`` (the derivation),
``System.compile(params, backend=...)`` (code generation: CSE and printing; with numba also the JIT of the
model or loading it from numba's cache) and a short ``simulate`` (t in [0, 0.5]). Three scenarios:

* **cold**: empty cache (the generic numba integrator loops, compiled once per machine, are primed first so
  they do not hide the model's own cost);
* **warm, derivation cache off**: the same model again with ``LAGRANGE_DERIVATION_CACHE=0`` (what a re-run
  cost before the derivation cache: numba's cache skips the JIT, but derivation and code generation rerun);
* **warm**: the same model again with the derivation cache on (the default).

Each scenario runs ``--repeats`` times (a fresh cache directory per cold run) and the median is reported.
Writes ``benchmarks/results/derivation_cache.md``. Run ``python benchmarks/derivation_cache.py``
(``--repeats 1`` for a quick look).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
PROBLEMS = ("double_pendulum", "nlink", "top")
BACKENDS = ("python", "numba")
SCENARIOS = ("cold", "warm, cache off", "warm")
PHASES = ("import", "build", "derive", "compile", "simulate")

_CHILD = """
import json, os, sys, time
from pathlib import Path
def entries():
    return {(p.name, p.stat().st_mtime_ns) for p in Path(os.environ["LAGRANGE_CACHE_DIR"]).glob("[ds][eo]*_*.*")}
before = entries()
t0 = time.perf_counter()
import numpy as np
from lagrange.bench.problems import get_problem
name, backend = sys.argv[1], sys.argv[2]
if backend == "numba":
    import numba  # noqa: F401 - imported before the clock starts on compile
pb = get_problem(name)
t1 = time.perf_counter()
s = pb.build()
t2 = time.perf_counter()
eqs = s.derived
t3 = time.perf_counter()
model = s.compile(pb.params, backend=backend)
t4 = time.perf_counter()
tr = s.simulate(0.5, pb.initial, pb.params, backend=backend, **pb.options)
t5 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "build": t2 - t1, "derive": t3 - t2, "compile": t4 - t3, "simulate": t5 - t4,
                  "final": [float(v) for v in tr.y[-1]], "rhs": [float(v) for v in model.fun(0.0, tr.y[0])],
                  "written": len(entries() - before)}))
"""
_LOOPS_ONLY = "from lagrange.integrate.compiled import loops; loops()"


def _child(cache: str, name: str, backend: str, derivation_cache: bool) -> dict:
    env = dict(os.environ, LAGRANGE_CACHE_DIR=cache, LAGRANGE_DERIVATION_CACHE="1" if derivation_cache else "0")
    env.pop("NUMBA_CACHE_DIR", None)
    r = subprocess.run([sys.executable, "-c", _CHILD, name, backend], env=env, capture_output=True, text=True,
                       check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


def measure(name: str, backend: str, repeats: int, loops_cache: str) -> dict:
    """Median phase times per scenario; also checks that the warm runs reproduce the cold results exactly."""
    runs: dict = {sc: [] for sc in SCENARIOS}
    attempts = 0
    while len(runs["cold"]) < repeats:
        with tempfile.TemporaryDirectory() as cache:
            shutil.copytree(loops_cache, cache, dirs_exist_ok=True)
            cold = _child(cache, name, backend, True)
            off = _child(cache, name, backend, False)
            warm = _child(cache, name, backend, True)
        if not cold["written"] or off["written"] or warm["written"]:  # a warm run must load, not write
            attempts += 1
            if attempts > 3:
                raise AssertionError(f"{name}/{backend}: the warm run kept missing the cache")
            print(f"{name}/{backend}: warm run missed (lagrange's source edited meanwhile?); repeating", flush=True)
            continue
        for result in (off, warm):
            if result["final"] != cold["final"] or result["rhs"] != cold["rhs"]:
                raise AssertionError(f"{name}/{backend}: a warm run differs from the cold run")
        for sc, result in zip(SCENARIOS, (cold, off, warm)):
            runs[sc].append(result)
    return {sc: {ph: statistics.median(r[ph] for r in runs[sc]) for ph in PHASES} for sc in SCENARIOS}


def run(repeats: int) -> dict:
    rows = {}
    with tempfile.TemporaryDirectory() as loops_cache:
        env = dict(os.environ, LAGRANGE_CACHE_DIR=loops_cache)
        env.pop("NUMBA_CACHE_DIR", None)
        subprocess.run([sys.executable, "-c", _LOOPS_ONLY], env=env, check=True)
        for name in PROBLEMS:
            for backend in BACKENDS:
                rows[(name, backend)] = measure(name, backend, repeats, loops_cache)
                print(f"{name} / {backend}: done", flush=True)
    return rows


def write(rows: dict, repeats: int) -> str:
    import numpy as np
    import sympy

    import lagrange

    try:
        import numba

        nbv = numba.__version__
    except ImportError:  # pragma: no cover
        nbv = "absent"
    lines = [
        "# Derivation cache: first run vs second run (fresh processes, side by side)",
        "",
        f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}, sympy {sympy.__version__}, numpy {np.__version__}, numba {nbv}, lagrange "
        f"{lagrange.__version__}. Medians of {repeats} fresh-process runs per scenario; other processes may load "
        "the machine, so read ratios.",
        "",
        "Each run: import, `build()` (the declaration), `System.derived` (derivation), `System.compile(params, "
        "backend=...)` (CSE + printing; numba: also the JIT of the model, or loading it from numba's cache) and "
        "`simulate` over t in [0, 0.5]. *cold*: empty cache (generic numba loops primed); *warm, cache off*: "
        "the same model again with `LAGRANGE_DERIVATION_CACHE=0` (the behaviour before the derivation cache); "
        "*warm*: the same model again, derivation cache on. Warm runs reproduce the cold run's final state and "
        "rhs bit for bit (checked).",
        "",
        "Seconds, derive + compile (the part the cache targets):",
        "",
        "| problem | backend | cold | warm, cache off | warm | cold / warm | cache off / warm |",
        "|---|---|---|---|---|---|---|",
    ]
    for (name, backend), row in rows.items():
        dc = {sc: row[sc]["derive"] + row[sc]["compile"] for sc in SCENARIOS}
        lines.append(f"| {name} | {backend} | {dc['cold']:.3f} | {dc['warm, cache off']:.3f} | {dc['warm']:.3f} | "
                     f"x{dc['cold'] / dc['warm']:.0f} | x{dc['warm, cache off'] / dc['warm']:.0f} |")
    lines += ["", "Seconds per phase (the whole run, for context: the import of lagrange and sympy dominates a "
              "warm run):", "",
              "| problem | backend | scenario | " + " | ".join(PHASES) + " | total |",
              "|---|---|---|" + "---|" * (len(PHASES) + 1)]
    for (name, backend), row in rows.items():
        for sc in SCENARIOS:
            ph = row[sc]
            lines.append(f"| {name} | {backend} | {sc} | " + " | ".join(f"{ph[k]:.3f}" for k in PHASES)
                         + f" | {sum(ph.values()):.2f} |")
    text = "\n".join(lines) + "\n"
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "derivation_cache.md").write_text(text)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    print(write(run(args.repeats), args.repeats))


if __name__ == "__main__":
    main()
