"""Planar N-link pendulum: lagrange against the plain sympy route, measured side by side in one run.

Plain route (what a user writes without lagrange): ``sympy.physics.mechanics.LagrangesMethod``,
``lambdify`` of M and f (numpy, no CSE) and ``numpy.linalg.solve`` inside the rhs, ``solve_ivp``.

Measured for N = 2, 5, 10 (``--n`` to change), t in [0, 10], q_i = 0.6(-1)^i/(i+1), u = 0, g = 9.81:

* derivation time (median of 3, sympy cache cleared before each);
* code-generation time;
* cost of one right-hand-side call from Python (median of 7 x timeit);
* integration with ``solve_ivp(DOP853)`` at rtol = atol = 1e-4 … 1e-10: wall time (median of 3) and final
  error against a reference (DOP853 at 1e-13 with the numba backend; its self-consistency against 1e-12
  is reported).

Writes ``benchmarks/results/nlink.md`` and ``benchmarks/results/nlink.png``. Run:
``python benchmarks/nlink.py`` (about 2–4 minutes on 2 cores).
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
import timeit
from pathlib import Path

import numpy as np
import scipy
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.core.cache import clear_cache

# derivation times are measured cold: the derivation cache (lagrange.codegen.derivation_cache) stays off
os.environ.setdefault("LAGRANGE_DERIVATION_CACHE", "0")

import lagrange
from lagrange.bench.sympy_route import plain_pendulum_route
from lagrange.examples import n_link_pendulum

RESULTS = Path(__file__).parent / "results"
TOLS = (1e-4, 1e-6, 1e-8, 1e-10)


def plain_route(n: int):
    """LagrangesMethod + lambdify (numpy, no cse) + np.linalg.solve: (derive_s, build_s, rhs)."""
    return plain_pendulum_route(n, cse=False)


def ours(n: int, backend: str):
    t0 = time.perf_counter()
    s = n_link_pendulum(n)
    _ = s.derived  # derivation happens here (memoized on the system)
    t1 = time.perf_counter()
    model = s.compile({"g": 9.81}, backend=backend)
    t2 = time.perf_counter()
    return t1 - t0, t2 - t1, model


def per_call(fun, y) -> float:
    fun(0.0, y)
    runs = timeit.repeat(lambda: fun(0.0, y), number=500, repeat=7)
    return statistics.median(runs) / 500


def integrate(fun, y0, tol):
    def once():
        return solve_ivp(fun, (0.0, 10.0), y0, method="DOP853", rtol=tol, atol=tol)

    once()
    times, res = [], None
    for _ in range(3):
        t0 = time.perf_counter()
        res = once()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), res


def median_of(f, k=3):
    vals = []
    for _ in range(k):
        clear_cache()
        vals.append(f())
    return statistics.median([v[0] for v in vals]), statistics.median([v[1] for v in vals]), vals[-1][2]


def run(ns):
    rows, wp = [], {}
    for n in ns:
        y0 = np.array([0.6 * (-1) ** i / (i + 1) for i in range(n)] + [0.0] * n)
        d_plain, b_plain, rhs_plain = median_of(lambda n=n: plain_route(n))
        d_py, b_py, m_py = median_of(lambda n=n: ours(n, "python"))
        clear_cache()
        d_nb, b_nb, m_nb = ours(n, "numba")  # first build includes the JIT
        yr = np.random.default_rng(n).uniform(-1, 1, 2 * n)
        assert np.allclose(rhs_plain(0.0, yr), m_py.fun(0.0, yr), rtol=1e-10, atol=1e-10), "routes disagree"
        assert np.allclose(m_nb.fun(0.0, yr), m_py.fun(0.0, yr), rtol=1e-12, atol=1e-12)
        c_plain, c_py, c_nb = per_call(rhs_plain, y0), per_call(m_py.fun, y0), per_call(m_nb.fun, y0)
        ref = solve_ivp(m_nb.fun, (0, 10), y0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
        ref2 = solve_ivp(m_nb.fun, (0, 10), y0, method="DOP853", rtol=1e-12, atol=1e-12).y[:, -1]
        consistency = float(np.max(np.abs(ref - ref2)))
        curves = {"plain": [], "lagrange python": [], "lagrange numba": []}
        for tol in TOLS:
            for label, fun in (("plain", rhs_plain), ("lagrange python", m_py.fun), ("lagrange numba", m_nb.fun)):
                wall, res = integrate(fun, y0, tol)
                err = float(np.max(np.abs(res.y[:, -1] - ref)))
                curves[label].append((tol, wall, err, res.nfev))
        wp[n] = (curves, consistency)
        rows.append(dict(n=n, d_plain=d_plain, d_py=d_py, b_plain=b_plain, b_py=b_py, b_nb=b_nb,
                         c_plain=c_plain, c_py=c_py, c_nb=c_nb))
        print(f"N={n}: derive {d_py:.2f}s vs {d_plain:.2f}s; rhs {c_py * 1e6:.1f}/{c_nb * 1e6:.2f} us vs "
              f"{c_plain * 1e6:.1f} us", flush=True)
    return rows, wp


def write(rows, wp):
    RESULTS.mkdir(parents=True, exist_ok=True)
    lines = [
        "# Planar N-link pendulum: lagrange vs the plain sympy route (one run, side by side)",
        "",
        f"Machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}, "
        f"sympy {sp.__version__}, numpy {np.__version__}, scipy {scipy.__version__}, lagrange {lagrange.__version__}"
        + _numba_version(),
        "",
        "Plain route = `sympy.physics.mechanics.LagrangesMethod` + `lambdify` (numpy, no CSE) + "
        "`np.linalg.solve` in the rhs. Ratios are plain / lagrange (higher is better for lagrange).",
        "",
        "## Derivation, code generation and one right-hand-side call",
        "",
        "| N | derive: lagrange | derive: plain | ratio | codegen: lagrange python | codegen: numba (JIT) "
        "| codegen: plain | rhs call: lagrange python | rhs call: lagrange numba | rhs call: plain "
        "| ratio python | ratio numba |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['n']} | {r['d_py']:.3f} s | {r['d_plain']:.3f} s | x{r['d_plain'] / r['d_py']:.1f} "
            f"| {r['b_py']:.3f} s | {r['b_nb']:.2f} s | {r['b_plain']:.3f} s "
            f"| {r['c_py'] * 1e6:.2f} us | {r['c_nb'] * 1e6:.2f} us | {r['c_plain'] * 1e6:.1f} us "
            f"| x{r['c_plain'] / r['c_py']:.1f} | x{r['c_plain'] / r['c_nb']:.0f} |"
        )
    lines += ["", "## Integration (solve_ivp DOP853, t in [0, 10]): wall time and final error", ""]
    for n, (curves, consistency) in wp.items():
        lines.append(f"N = {n} (reference DOP853 1e-13; agrees with 1e-12 to {consistency:.1e})")
        lines.append("")
        lines.append("| tol | plain: time / error / nfev | lagrange python | lagrange numba | speed-up python | "
                     "speed-up numba |")
        lines.append("|---|---|---|---|---|---|")
        for k, tol in enumerate(TOLS):
            p, q, r = curves["plain"][k], curves["lagrange python"][k], curves["lagrange numba"][k]
            lines.append(
                f"| {tol:.0e} | {p[1] * 1e3:.1f} ms / {p[2]:.1e} / {p[3]} | {q[1] * 1e3:.1f} ms / {q[2]:.1e} "
                f"| {r[1] * 1e3:.1f} ms / {r[2]:.1e} | x{p[1] / q[1]:.1f} | x{p[1] / r[1]:.1f} |"
            )
        lines.append("")
    (RESULTS / "nlink.md").write_text("\n".join(lines) + "\n")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(wp), figsize=(5 * len(wp), 4), constrained_layout=True, squeeze=False)
    for ax, (n, (curves, _)) in zip(axes[0], wp.items()):
        for label, pts in curves.items():
            ax.loglog([p[2] for p in pts], [p[1] * 1e3 for p in pts], "o-", label=label)
        ax.set_xlabel("final error (max norm)")
        ax.set_ylabel("wall time [ms]")
        ax.set_title(f"N = {n}, DOP853")
        ax.legend(fontsize="small")
    fig.savefig(RESULTS / "nlink.png", dpi=110)


def _numba_version() -> str:
    try:
        import numba

        return f", numba {numba.__version__}"
    except ImportError:
        return ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[2, 5, 10])
    args = ap.parse_args()
    rows, wp = run(args.n)
    write(rows, wp)
    print((RESULTS / "nlink.md").read_text())


if __name__ == "__main__":
    main()
