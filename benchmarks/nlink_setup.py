"""Set-up cost of large N-link pendulums (issue #23 items 2 and 6): declare, derive and generate code, N = 10, 20, 50.

Each measurement runs in a fresh process (imports not counted: they happen before the clock starts; first use
is counted, caches off: ``LAGRANGE_DERIVATION_CACHE=0``), routes interleaved per N (A, B, C, A, B, C for
``--repeats`` > 1), CPU time (``time.process_time`` in the child) and wall time:

* ``lagrange (structural)`` / ``lagrange (expanded)``: ``n_link_pendulum(N, derivation=...)`` (declare),
  ``.derived`` (derive), ``.compile(backend="python")`` (CSE + printing). Structural: the kinematics of each
  bob differentiated, M and f assembled by the generated code (:mod:`lagrange.derive.structural`; the default,
  ``derivation="auto"``, from 6 coordinates on); expanded: T expanded and differentiated twice;
* ``lagrange (before)``: the same with the tree given by ``--before DIR`` (a checkout of the previous
  commit), for the before/after table;
* ``sympy``: ``LagrangesMethod`` + ``msubs`` (derive) and ``lambdify(cse=True)`` (codegen);
* ``heyoka``: ``heyoka.lagrangian`` (derive, from lagrange's declared T and V) and ``taylor_adaptive``
  construction (codegen: LLVM compile), compact mode.

A route over ``--timeout`` seconds is reported as such. Writes ``results/nlink_setup.md``. Run::

    python benchmarks/nlink_setup.py --quick            # N = 10, 20 (under a minute idle)
    python benchmarks/nlink_setup.py --before /tmp/base # N = 10, 20, 50 with the before column
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
HERE = Path(__file__).resolve().parent.parent

_CHILD = r"""
import json, os, sys, time
os.environ["LAGRANGE_DERIVATION_CACHE"] = "0"
route, n = sys.argv[1], int(sys.argv[2])
ROUTES_WITH_DERIVATION = ("lagrange (structural)", "lagrange (expanded)")
import sympy
import lagrange
from lagrange.examples import n_link_pendulum
try:
    import symengine  # imported up front: an import is not set-up work
except ImportError:
    pass
out = {}
def clock():
    return time.process_time(), time.perf_counter()
if route.startswith("lagrange"):
    kw = {"derivation": route.split("(")[1].rstrip(")")} if route in ROUTES_WITH_DERIVATION else {}
    c0 = clock(); s = n_link_pendulum(n, **kw); c1 = clock(); s.derived; c2 = clock()
    s.compile({"g": 9.81}, backend="python"); c3 = clock()
    stages = [("declare", c0, c1), ("derive", c1, c2), ("codegen", c2, c3)]
elif route == "sympy":
    from lagrange.bench.sympy_route import plain_pendulum_route
    c0 = clock(); plain_pendulum_route(n, cse=True); c1 = clock()
    stages = [("total", c0, c1)]
elif route == "heyoka":
    import heyoka
    from lagrange.bench.heyoka_adapter import heyoka_model
    s = n_link_pendulum(n); s.derived  # not timed: heyoka starts from lagrange's T and V
    c0 = clock(); hm = heyoka_model(s, {"g": 9.81}); c1 = clock()
    hm.integrator([0.1] * n + [0.0] * n, 1e-10, compact=True); c2 = clock()
    stages = [("derive", c0, c1), ("codegen", c1, c2)]
for name, a, b in stages:
    out[name] = [b[0] - a[0], b[1] - a[1]]
print(json.dumps(out))
"""


def run_child(route: str, n: int, timeout: float, before: str | None) -> dict | None:
    root = Path(before) if route == "lagrange (before)" else HERE
    env = dict(os.environ, PYTHONPATH=str(root / ".pp"))
    try:
        res = subprocess.run([sys.executable, "-c", _CHILD, route, str(n)], capture_output=True, text=True,
                             timeout=timeout, env=env, cwd=str(root))
    except subprocess.TimeoutExpired:
        return None
    if res.returncode != 0:
        raise RuntimeError(f"{route} N={n} failed:\n{res.stderr[-2000:]}")
    return json.loads(res.stdout.strip().splitlines()[-1])


def _fmt(v):
    return "—" if v is None else f"{v[0]:.2f} / {v[1]:.2f}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--links", default="10,20,50")
    ap.add_argument("--quick", action="store_true", help="N = 10, 20; no sympy above N = 10")
    ap.add_argument("--before", default=None, help="a tree (with .pp/) of the previous version")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--sympy-max", type=int, default=20, help="largest N for the sympy route")
    ap.add_argument("--out", default=str(RESULTS / "nlink_setup.md"))
    args = ap.parse_args()
    links = [10, 20] if args.quick else [int(v) for v in args.links.split(",")]
    routes = ["lagrange (structural)", "lagrange (expanded)"] + (["lagrange (before)"] if args.before else [])
    routes.append("sympy")
    try:
        import heyoka  # noqa: F401

        routes.append("heyoka")
    except ImportError:
        pass
    rows = []
    for n in links:
        samples: dict = {r: [] for r in routes}
        for _ in range(args.repeats):
            for r in routes:  # interleaved
                if r == "sympy" and (n > args.sympy_max or (args.quick and n > 10)):
                    continue
                samples[r].append(run_child(r, n, args.timeout, args.before))
        for r in routes:
            got = [s for s in samples[r] if s is not None]
            if not samples[r]:
                continue
            if not got:
                rows.append((n, r, None, f"over {args.timeout:.0f} s"))
                continue
            med = {k: [statistics.median(s[k][i] for s in got) for i in (0, 1)] for k in got[0]}
            rows.append((n, r, med, ""))
            print(n, r, med, flush=True)
    lines = ["# N-link pendulum set-up: declare, derive, generate code (CPU s / wall s)", "",
             __doc__.split("\n\n")[1].replace("\n", " "), "",
             "| N | route | declare | derive | codegen | total (CPU / wall) | note |", "|---|---|---|---|---|---|---|"]
    for n, r, med, note in rows:
        if med is None:
            lines.append(f"| {n} | {r} | — | — | — | — | {note} |")
            continue
        total = [sum(v[i] for v in med.values()) for i in (0, 1)]
        lines.append(f"| {n} | {r} | {_fmt(med.get('declare'))} | {_fmt(med.get('derive'))} | "
                     f"{_fmt(med.get('codegen'))} | **{_fmt(total)}** | "
                     f"{'derive + lambdify in one' if r == 'sympy' else note} |")
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
