"""What ``import lagrange`` costs, and what the first use of each part adds (issue #23 item 5).

Each case runs in a fresh interpreter (``python -c``), the cases interleaved (A, B, C, …, A, B, C, …) so
the load of the machine falls on all alike; reported: median wall time and median CPU time (user + system
of the child, ``resource.getrusage(RUSAGE_CHILDREN)``) over the repeats, interpreter start-up included (the
``python -c pass`` row is that start-up alone). Then ``python -X importtime -c "import lagrange"`` (and the
same for declaring a system): the ten largest cumulative import times, and which heavy packages are loaded.

Writes ``benchmarks/results/imports.md``. Run: ``python benchmarks/imports.py`` (about a minute) or
``--quick`` (3 repeats).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
HEAVY = ("sympy", "numpy", "scipy", "scipy.integrate", "numba", "matplotlib", "pandas", "symengine", "heyoka")
DECLARE = ("import lagrange as lg; x = lg.coordinates('x'); k = lg.parameters('k'); "
           "s = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2); s.derived")
CASES = {
    "python -c pass (interpreter start-up)": "pass",
    "import lagrange": "import lagrange",
    "import lagrange; lagrange.__version__": "import lagrange; lagrange.__version__",
    "declare + derive a 1-DOF system (sympy loads)": DECLARE,
    "import sympy, numpy": "import sympy, numpy",
    "import sympy, numpy, scipy.integrate (what `import lagrange` cost before lazy imports)":
        "import sympy, numpy, scipy.integrate",
    "import heyoka (peer)": "import heyoka",
}


def _child(code: str) -> tuple[float, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)
    wall = time.perf_counter() - w
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _loaded(code: str) -> list[str]:
    probe = f"{code}\nimport sys, json\nprint(json.dumps(sorted(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", probe], check=True, capture_output=True, text=True).stdout
    mods = set(json.loads(out.strip().splitlines()[-1]))
    return [h for h in HEAVY if h in mods]


def _importtime(code: str, top: int = 10) -> list[tuple[str, float, float]]:
    """(module, self ms, cumulative ms) of the ``top`` largest cumulative import times."""
    err = subprocess.run([sys.executable, "-X", "importtime", "-c", code], check=True, capture_output=True,
                         text=True).stderr
    rows = []
    for line in err.splitlines():
        if not line.startswith("import time:") or "self [us]" in line:
            continue
        self_us, cum_us, name = (part.strip() for part in line[len("import time:"):].split("|"))
        rows.append((name.strip(), int(self_us) / 1e3, int(cum_us) / 1e3))
    return sorted(rows, key=lambda r: -r[2])[:top]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="3 repeats instead of 9")
    args = ap.parse_args()
    repeats = 3 if args.quick else 9
    walls: dict = {name: [] for name in CASES}
    cpus: dict = {name: [] for name in CASES}
    for _ in range(repeats):  # interleaved: every case once per round
        for name, code in CASES.items():
            try:
                w, c = _child(code)
            except subprocess.CalledProcessError:  # e.g. heyoka not installed
                continue
            walls[name].append(w)
            cpus[name].append(c)
    lines = [
        "# `import lagrange`: what it costs and what loads",
        "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores (shared with other jobs: medians of {repeats} "
        f"fresh processes, cases interleaved), Python {platform.python_version()}.",
        "",
        "Wall and CPU (user + system) time of a whole fresh `python -c ...` process, interpreter start-up "
        "included (first row: start-up alone).",
        "",
        "| case | wall (median) | CPU (median) | heavy packages loaded |",
        "|---|---|---|---|",
    ]
    for name, code in CASES.items():
        if not walls[name]:
            lines.append(f"| {name} | not installed | | |")
            continue
        heavy = ", ".join(_loaded(code)) or "none"
        lines.append(f"| {name} | {statistics.median(walls[name]) * 1e3:.0f} ms | "
                     f"{statistics.median(cpus[name]) * 1e3:.0f} ms | {heavy} |")
    for title, code in (("import lagrange", "import lagrange"), ("declare + derive a 1-DOF system", DECLARE)):
        lines += ["", f"## `python -X importtime`: {title} (ten largest cumulative)", "",
                  "| module | self | cumulative |", "|---|---|---|"]
        lines += [f"| {name} | {s:.1f} ms | {c:.1f} ms |" for name, s, c in _importtime(code)]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "imports.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
