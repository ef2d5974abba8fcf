"""Re-runs of the same model in a new process: lagrange (on-disk derivation, source and tape cache, numba
bundles) against heyoka.py (its on-disk JIT cache), cold and warm, side by side (issue #23 item 4).

Every run is a fresh interpreter that declares the model, integrates it over the problem's horizon with 1001
output times at rtol = atol = 1e-10 and prints its final state. Routes:

* ``lagrange taylor``: ``simulate(method="taylor")`` (python backend: the tape interpreted in C);
* ``lagrange DOP853``: ``simulate()`` (the default method and backend: scipy's DOP853 on generated Python);
* ``lagrange taylor numba`` / ``lagrange DOP853 numba``: ``backend="numba"`` (the compiled Taylor series / the
  compiled RK loop), double pendulum and top only (the 10-link model's numba JIT takes minutes when cold);
* ``heyoka default`` / ``heyoka compact``: heyoka used directly, as its documentation shows: the Lagrangian
  written with heyoka expressions, ``heyoka.lagrangian``, ``taylor_adaptive(tol=1e-10)`` in the default or
  ``compact_mode``, ``propagate_grid``. heyoka.py >= 7.10 keeps compiled LLVM modules in an on-disk cache
  (on by default); each route gets its own cache directory (``llvm_state.set_diskcache_path``). The 10-link
  pendulum runs compact mode only (its default-mode compile takes minutes cold).

Scenarios: *cold* — an empty model cache (lagrange: a copy of a cache that holds only the once-per-machine
pieces, the generic numba loops and the C interpreter, built by a priming run on another model; heyoka: an
empty disk cache); *warm* — a second process on the same cache. Per repeat the order is interleaved
(route A cold, A warm, route B cold, B warm, ...). CPU is the child's user + system time
(``resource.getrusage(RUSAGE_CHILDREN)``). *With imports*: the whole process, interpreter start and every
import counted; the lagrange child imports only ``lagrange`` (lazy), so exactly what the route loads is
counted (each run reports which of numpy, sympy, scipy.linalg, scipy.integrate, numba and symengine it
loaded). *Without imports*: heyoka's child reports the CPU spent up to the end of ``import heyoka, numpy``,
subtracted from its warm run; for lagrange a third process (warm too) imports, before the clock, exactly the
modules its plain warm run loaded and triggers sympy's deferred imports (its first ``Add``), and its CPU after
that is the column (lagrange's own submodules load during the run and are counted in it). JIT and compile
costs are always counted. The children import lagrange as a user's install has it: this source tree installed
with ``pip install --no-deps --target`` into a temporary directory (byte-compiled, with the C interpreter's
extension module; each run reports which C interpreter it loaded). ``--from-source`` runs the source tree
instead, byte-compiled first (``compileall``; without it ``PYTHONDONTWRITEBYTECODE=1``, set on this machine,
makes every fresh process recompile lagrange's sources: about 0.3 s of a warm re-run), where the C
interpreter is the library built at run time (finding it costs ``sysconfig``'s compiler lookup). Medians of
``--repeats`` runs; the ratio columns are the median of per-repeat ratios of runs made side by side; the
machine is shared, so read ratios.

Run ``python benchmarks/rerun.py`` (``--quick``: the double pendulum, taylor vs heyoka, one repeat, under a
minute; ``--taylor-only --repeats 7 --out rerun_taylor.md``: the taylor route against both heyoka modes on all
three problems, more repeats of the issue's target; ``--render``: the report again from the runs saved next to
it, ``<out>.json``). Writes ``benchmarks/results/rerun.md``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from lagrange.bench.first_result import byte_compile_lagrange

RESULTS = Path(__file__).parent / "results"
#: the third-party modules a lagrange run may load (reported by each run; the *w/o imports* run of a route
#: imports those its plain warm run loaded before the clock starts)
HEAVY = ("numpy", "sympy", "scipy.linalg", "scipy.integrate", "numba", "symengine")
PROBLEMS = ("double_pendulum", "nlink10", "top")
TOL = 1e-10

_MODELS = """
import math
def problem(name):
    if name == "top":
        return 5.0, [0.0, 0.6, 0.0, 1.0, 0.0, 60.0]
    n = 2 if name == "double_pendulum" else int(name[5:])
    return 10.0, [0.6 * (-1) ** i / (i + 1) for i in range(n)] + [0.0] * n
"""

_LAGRANGE = _MODELS + """
import importlib, json, sys, time
c0 = time.process_time()
import lagrange as lg
name, method, backend = sys.argv[1], sys.argv[2], sys.argv[3]
for module in sys.argv[4].split(",") if len(sys.argv) > 4 and sys.argv[4] else ():
    importlib.import_module(module)  # the *w/o imports* run: what the plain run loaded, imported before the clock
if len(sys.argv) > 4:
    import sympy
    sympy.Symbol("a") + sympy.Symbol("b")  # sympy's deferred imports (sympy.tensor, ...) on its first Add
c1 = time.process_time()
t_end, y0 = problem(name)
if name == "top":
    psi, th, ph = lg.coordinates("psi theta phi")
    M, g, l, I1, I3 = lg.parameters("M g l I1 I3")
    body = lg.RigidBody(M, (I1, I1, I3), orientation=lg.EulerAngles(psi, th, ph), com=(0, 0, l))
    system = lg.System([psi, th, ph], bodies=[body], V=M * g * body.centre_of_mass[2], name="heavy symmetric top")
    params = {"M": 1.0, "g": 9.81, "l": 0.2, "I1": 0.05, "I3": 0.02}
else:
    from lagrange.examples import n_link_pendulum
    system = n_link_pendulum(len(y0) // 2)
    params = {"g": 9.81}
coords = system.coordinates
initial = dict(zip(list(coords) + [q.diff(lg.t) for q in coords], y0))
options = {} if method == "default" else {"method": method}
tr = system.simulate(t_end, initial, params, backend=backend, rtol=1e-10, atol=1e-10, n_points=1001, **options)
from lagrange.codegen.derivation_cache import statistics
from lagrange.codegen.c_interpreter import extension_path
print(json.dumps({"import_cpu": c1 - c0, "final": tr.y[-1, : len(y0) // 2].tolist(), "label": tr.method,
                  "c_interpreter": "extension module" if extension_path() else "library built at run time",
                  "cache": statistics(), "loaded": [m for m in "HEAVY".split(",") if m in sys.modules]}))
""".replace("HEAVY", ",".join(HEAVY))

_HEYOKA = _MODELS + """
import json, sys, time
c0 = time.process_time()
import heyoka as hy
import numpy as np
c1 = time.process_time()
name, mode, cache = sys.argv[1], sys.argv[2], sys.argv[3]
hy.llvm_state.set_diskcache_path(cache)
t_end, y0 = problem(name)
n = len(y0) // 2
qs = list(hy.make_vars(*[f"q{i}" for i in range(n)]))
qds = list(hy.make_vars(*[f"qd{i}" for i in range(n)]))
if name == "top":
    M, g, l, I1, I3 = 1.0, 9.81, 0.2, 0.05, 0.02
    psi, th, ph = qs
    dpsi, dth, dph = qds
    L = (I1 / 2 * (dth**2 + dpsi**2 * hy.sin(th) ** 2) + I3 / 2 * (dph + dpsi * hy.cos(th)) ** 2
         - M * g * l * hy.cos(th))
else:  # unit masses and rods, absolute angles from the downward vertical
    g = 9.81
    L, vx, vy, y = 0.0, 0.0, 0.0, 0.0
    for q, qd in zip(qs, qds):
        vx, vy, y = vx + hy.cos(q) * qd, vy + hy.sin(q) * qd, y - hy.cos(q)
        L = L + (vx**2 + vy**2) / 2 - g * y
ta = hy.taylor_adaptive(hy.lagrangian(L, qs, qds), y0, tol=1e-10, compact_mode=(mode == "compact"))
res = ta.propagate_grid(np.linspace(0.0, t_end, 1001))
print(json.dumps({"import_cpu": c1 - c0, "final": np.asarray(res[-1])[-1, :n].tolist(), "label": f"heyoka {mode}",
                  "cache_bytes": hy.llvm_state.get_diskcache_size()}))
"""

_PRIME = """
import lagrange as lg
x = lg.coordinates("x"); k = lg.parameters("k")
s = lg.System([x], T=x.diff(lg.t) ** 2 / 2, V=k * x**2 / 2)
import sys
routes = ({"method": "taylor"}, {"method": "taylor", "backend": "numba"}, {"backend": "numba"})
for options in routes[: int(sys.argv[1])]:
    s.simulate(1.0, {"x": 0.1, "x_dot": 0.0}, {"k": 1.0}, **options)
"""


def install_copy(tmp: str) -> str:
    """``pip install --no-deps --target <tmp>/site`` of this source tree: lagrange as a user's install has it
    (byte-compiled, with the C interpreter's extension module when a compiler is present); returns the
    directory. The dependencies are this interpreter's own."""
    site = os.path.join(tmp, "site")
    subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-deps",
                    "--target", site, str(Path(__file__).resolve().parents[1])], check=True)
    return site


def routes(name: str, quick: bool, taylor_only: bool = False) -> list[tuple[str, str, str]]:
    """``(label, kind, argument)`` of each route run on ``name`` (``taylor_only``: lagrange's taylor route
    against both heyoka modes)."""
    out = [("lagrange taylor", "lagrange", "taylor python")]
    if not (quick or taylor_only):
        out.append(("lagrange DOP853 (default)", "lagrange", "default python"))
        if name != "nlink10":
            out += [("lagrange taylor numba", "lagrange", "taylor numba"),
                    ("lagrange DOP853 numba loop", "lagrange", "DOP853 numba")]
    if name != "nlink10":
        out.append(("heyoka default", "heyoka", "default"))
    if not quick:
        out.append(("heyoka compact", "heyoka", "compact"))
    return out


def _child(kind: str, name: str, argument: str, cache: str, preimport: list[str] | None = None) -> dict:
    env = dict(os.environ, LAGRANGE_CACHE_DIR=cache)
    env.pop("NUMBA_CACHE_DIR", None)
    env.pop("LAGRANGE_DERIVATION_CACHE", None)
    if kind == "lagrange":
        argv = [sys.executable, "-c", _LAGRANGE, name, *argument.split()]
        if preimport is not None:
            argv.append(",".join(preimport))
    else:
        argv = [sys.executable, "-c", _HEYOKA, name, argument, cache]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    r = subprocess.run(argv, env=env, capture_output=True, text=True, cwd=os.path.dirname(cache))
    wall = time.perf_counter() - w0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise RuntimeError(f"{kind} {name} {argument}: {r.stderr[-2000:]}")
    out = json.loads(r.stdout.strip().splitlines()[-1])
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out | {"cpu": cpu, "wall": wall, "cpu_run": cpu - out["import_cpu"]}


def measure(name: str, quick: bool, repeats: int, primed: str, taylor_only: bool = False) -> dict:
    """``{label: {"cold": [runs], "warm": [runs]}}``, routes interleaved within each repeat."""
    runs: dict = {}
    for _ in range(repeats):
        for label, kind, argument in routes(name, quick, taylor_only):
            with tempfile.TemporaryDirectory() as tmp:
                cache = os.path.join(tmp, "cache")
                if kind == "lagrange":
                    shutil.copytree(primed, cache)
                else:
                    os.mkdir(cache, 0o700)
                cold = _child(kind, name, argument, cache)
                warm = _child(kind, name, argument, cache)
                # lagrange's *w/o imports*: a third run (warm too) that imports what the plain warm run loaded
                # before the clock; heyoka's child imports heyoka and numpy first anyway, so its warm run gives both
                bare = _child(kind, name, argument, cache, warm["loaded"]) if kind == "lagrange" else warm
            for run in (warm, bare):
                if kind == "lagrange" and run["cache"]["tape" if "taylor" in argument else "derived"]["hit"] < 1:
                    raise AssertionError(f"{label} {name}: the warm run missed the cache: {run['cache']}")
                if run["final"] != cold["final"]:
                    raise AssertionError(f"{label} {name}: the warm run differs from the cold run")
            entry = runs.setdefault(label, {"cold": [], "warm": [], "bare": []})
            entry["cold"].append(cold)
            entry["warm"].append(warm)
            entry["bare"].append(bare)
            print(f"{name:16s} {label:28s} cold {cold['cpu']:6.2f} s CPU  warm {warm['cpu']:6.2f} s CPU  "
                  f"w/o imports {bare['cpu_run']:5.2f} s CPU", flush=True)
    return runs


def _median(runs: list, field: str) -> float:
    return statistics.median(r[field] for r in runs)


def _paired_ratio(runs: list, ref_runs: list, field: str) -> float:
    """Median over repeats of run_i / ref_i (the two measured side by side in the same repeat)."""
    return statistics.median(a[field] / b[field] for a, b in zip(runs, ref_runs))


def _fastest(runs: list, field: str) -> float:
    """The least CPU of the repeats: the run least disturbed by the other jobs on the machine (noise only adds
    time to a deterministic workload; the estimator ``timeit`` recommends)."""
    return min(r[field] for r in runs)


def write(results: dict, quick: bool, repeats: int, flags: str = "") -> str:
    import heyoka
    import numba
    import sympy

    import lagrange

    interpreters = {run.get("c_interpreter") for runs in results.values() for label, route in runs.items()
                    if label.startswith("lagrange") for run in route.get("warm", [])} - {None}
    lines = [
        "# Re-runs in a new process: lagrange vs heyoka.py, cold and warm caches (issue #23 item 4)", "",
        f"`python benchmarks/rerun.py{' --quick' if quick else ''}{flags}`: {platform.machine()}, "
        f"{os.cpu_count()} CPUs shared with other jobs, Python {platform.python_version()}, lagrange "
        f"{lagrange.__version__}, sympy "
        f"{sympy.__version__}, numba {numba.__version__}, heyoka.py {heyoka.__version__}. Medians of {repeats} "
        "run(s) per cell, routes interleaved; every run is a fresh interpreter. rtol = atol = 1e-10, 1001 output "
        "times; final states agree between cold and warm runs bit for bit (checked). lagrange: "
        + ("this source tree, byte-compiled first as `pip install` does" if "--from-source" in flags else
           "installed with `pip install --no-deps --target` into a temporary directory, as a user's install has it "
           "(byte-compiled)")
        + f"; its C Taylor interpreter: {', '.join(sorted(interpreters)) or 'not reported'} (heyoka's, sympy's, "
        "numpy's and scipy's `.pyc` files come from their installs).", "",
        "*cold*: empty model cache (once-per-machine pieces primed: numba's generic loops, the C interpreter; "
        "heyoka: empty on-disk JIT cache). *warm*: a second process on the same cache (lagrange: derived "
        "equations, generated source, Taylor tape and numba bundles loaded; heyoka: its on-disk LLVM cache). "
        "Every run declares the model itself (lagrange: `System(...)`, which builds T from the bodies and "
        "validates the declaration; heyoka: the Lagrangian as heyoka expressions and `heyoka.lagrangian`). "
        "CPU = user + system of the child (getrusage RUSAGE_CHILDREN). *warm CPU (with imports)*: everything "
        "from interpreter start to exit — imports, declaration, cache key and load, compile/JIT, integration. "
        "*w/o imports*: the same minus the CPU spent up to the end of the imports: for heyoka `import heyoka, "
        "numpy` in the warm run; for lagrange a third process (warm as well) that imports, before the clock, "
        "`lagrange` and exactly the third-party modules the plain warm run loaded (column *warm run imports*) and "
        "triggers sympy's deferred imports (its first `Add`). JIT/compile costs are always counted. Ratio "
        "columns: lagrange / heyoka's fastest warm route in that column on the same problem, the median over "
        "repeats of the ratio of the two runs made side by side in one repeat (< 1: lagrange's re-run is "
        "cheaper). *fastest*: the least CPU of the repeats (the run least disturbed by other jobs: noise only "
        "adds time to these deterministic runs), and *fastest / heyoka's fastest*: that of the route over that of "
        "heyoka's fastest route — the steadier of the two estimates on this machine, where one and the same warm "
        "run scatters by ±0.2 s.", "",
        "| problem | route | warm run imports | cold CPU | warm CPU (with imports) | fastest warm (with imports) | "
        "warm CPU w/o imports | warm wall | warm / heyoka warm (with imports) | fastest / heyoka's fastest "
        "(with imports) | warm / heyoka warm (w/o imports) | final state vs heyoka |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, runs in results.items():
        heyoka_labels = [label for label in runs if label.startswith("heyoka")]
        best = min(heyoka_labels, key=lambda lb: _median(runs[lb]["warm"], "cpu"))
        best_bare = min(heyoka_labels, key=lambda lb: _median(runs[lb]["bare"], "cpu_run"))
        floor = min(_fastest(runs[lb]["warm"], "cpu") for lb in heyoka_labels)
        ref = np.array(runs[best]["warm"][0]["final"])
        for label, entry in runs.items():
            diff = float(np.max(np.abs(np.array(entry["warm"][0]["final"]) - ref)))
            loaded = ", ".join(entry["warm"][0].get("loaded", ["heyoka", "numpy"]))
            lines.append(
                f"| {name} | {label} | {loaded} | {_median(entry['cold'], 'cpu'):.2f} | "
                f"{_median(entry['warm'], 'cpu'):.2f} | {_fastest(entry['warm'], 'cpu'):.2f} | "
                f"{_median(entry['bare'], 'cpu_run'):.2f} | "
                f"{_median(entry['warm'], 'wall'):.2f} | {_paired_ratio(entry['warm'], runs[best]['warm'], 'cpu'):.2f}"
                f" | {_fastest(entry['warm'], 'cpu') / floor:.2f}"
                f" | {_paired_ratio(entry['bare'], runs[best_bare]['bare'], 'cpu_run'):.2f} | {diff:.1e} |")
    lines += ["", "heyoka's fastest warm route per problem and column is the reference of the ratio columns. The "
              "10-link pendulum is chaotic (errors grow ~1e5-fold over t = 10), so its final states differ between "
              "integrators at this tolerance; the double pendulum and the top agree."]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="double pendulum, taylor vs heyoka, one repeat")
    ap.add_argument("--taylor-only", action="store_true",
                    help="only lagrange's taylor route against heyoka's default and compact modes (more repeats "
                         "of the issue's target in the same time)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--problems", nargs="*", default=None)
    ap.add_argument("--out", default="rerun.md", help="file name under benchmarks/results/")
    ap.add_argument("--from-source", action="store_true",
                    help="run lagrange from this source tree (byte-compiled; the C interpreter is then the library "
                         "built at run time) instead of a copy installed with pip into a temporary directory")
    ap.add_argument("--render", action="store_true",
                    help="write the report again from the runs saved next to it (<out>.json), measuring nothing")
    args = ap.parse_args(argv)
    out = RESULTS / args.out
    saved = out.with_suffix(".json")
    if args.render:
        data = json.loads(saved.read_text())
        out.write_text(write(data["results"], data["quick"], data["repeats"], data["flags"]))
        print(out.read_text())
        return 0
    repeats = 1 if args.quick else args.repeats
    problems = args.problems or (("double_pendulum",) if args.quick else PROBLEMS)
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        if args.from_source:
            byte_compile_lagrange()  # as an installed package: every fresh process then loads .pyc files
            site = str(Path(__file__).resolve().parents[1])
        else:  # the children import lagrange as pip installs it (byte-compiled, the C extension built)
            site = install_copy(tmp)
        # (the children run in a scratch directory: `python -c` puts the working directory first on sys.path)
        os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, (site, os.environ.get("PYTHONPATH"))))
        primed = os.path.join(tmp, "primed")
        env = dict(os.environ, LAGRANGE_CACHE_DIR=primed)
        env.pop("NUMBA_CACHE_DIR", None)
        subprocess.run([sys.executable, "-c", _PRIME, "1" if args.quick else "3"], env=env, check=True, cwd=tmp)
        for entry in Path(primed).iterdir():  # keep only the once-per-machine pieces
            if entry.name.startswith(("derived_", "source_", "code_", "tape_")):
                entry.unlink()
        for name in problems:
            results[name] = measure(name, args.quick, repeats, primed, args.taylor_only)
    RESULTS.mkdir(exist_ok=True)
    flags = ((f" --taylor-only --repeats {repeats}" if args.taylor_only else "")
             + (" --from-source" if args.from_source else "")
             + (f" --out {args.out}" if args.out != "rerun.md" else ""))
    saved.write_text(json.dumps({"results": results, "quick": args.quick, "repeats": repeats, "flags": flags}))
    out.write_text(write(results, args.quick, repeats, flags))
    print(out.read_text())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
