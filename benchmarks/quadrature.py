"""Quadrature of integrals kept in the equations: rule (Gauss–Legendre order × panels) against error and CPU.

The test case is the uniform disc sliding and spinning on a rough plane (Wells Prob. 6.24; ``problems/ch06_p6_24``),
radius 1, mass 1 and μN = 1, whose friction force and torque have closed forms in ε = v/(Rω) (Farkas et al. 2003,
``lagrange_problems._common.spinning_disc_friction``). For each rule of :class:`lagrange.codegen.quadrature.Rule`,
the compiled right-hand side gives ẍ = −F and θ̈ = −2T at ω = 1, v = ε; the table lists the largest relative error
of F and T over ε ∈ {0.2, 0.4, 0.653} (the instantaneous centre inside the disc: a kink of |v| and a jump of its
derivative inside the domain) and over ε ∈ {1.5, 3} (outside: an analytic integrand), and the CPU time of one
right-hand side call (python backend: numpy over all nodes; numba backend: loops), median of repeated calls.

Writes ``benchmarks/results/quadrature.md``. Run::

    python benchmarks/quadrature.py
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import sympy as sp
from lagrange_problems._common import spinning_disc_friction
from lagrange_problems.ch06_p6_24 import system

from lagrange.codegen.quadrature import DEFAULT_RULE, Rule

ROOT = Path(__file__).resolve().parents[1]

RULES = [Rule(4, 1), Rule(8, 1), Rule(16, 1), Rule(32, 1), Rule(4, 4), Rule(8, 2), Rule(8, 4), Rule(8, 8),
         Rule(16, 4), Rule(16, 8), Rule(8, 16)]
INSIDE = (0.2, 0.4, 0.653)
OUTSIDE = (1.5, 3.0)
PARAMS = {"M": 1.0, "R": 1.0, "f": 1 / np.pi}


def _closed(eps: float) -> tuple[float, float]:
    e = sp.Symbol("e", positive=True)
    F, T = spinning_disc_friction(e)
    return float(F.subs(e, eps).evalf(20)), float(T.subs(e, eps).evalf(20))


def _errors(model, eps_values) -> float:
    worst = 0.0
    for eps in eps_values:
        F, T = _closed(eps)
        # state [x, y, θ, ẋ, ẏ, θ̇]; turned by 0.37 rad so the nodes are not aligned with the velocity
        acc = np.asarray(model.rhs(0.0, np.array([0.0, 0.0, 0.37, eps, 0.0, 1.0]), model._pcall))
        worst = max(worst, abs(-acc[3] - F) / F, abs(-acc[5] / 2 - T) / T)  # M = 1; I = MR²/2
    return worst


def _cpu_per_call(model) -> float:
    y = np.array([0.0, 0.0, 0.37, 0.4, 0.1, 1.0])
    p = model._pcall
    samples = []
    for _ in range(7):
        k = 0
        t0 = time.process_time()
        while time.process_time() - t0 < 0.05:
            model.rhs(0.0, y, p)
            k += 1
        samples.append((time.process_time() - t0) / k)
    return float(np.median(samples))


def main() -> None:
    rows = []
    for rule in RULES:
        py = system.compile(PARAMS, backend="python", quadrature=rule)
        nb = system.compile(PARAMS, backend="numba", quadrature=rule)
        nb.rhs(0.0, np.zeros(6) + 0.5, nb._pcall)  # compile
        rows.append((rule, _errors(py, INSIDE), _errors(py, OUTSIDE), _errors(nb, INSIDE),
                     _cpu_per_call(py), _cpu_per_call(nb)))
        print(rows[-1], flush=True)
    lines = [
        "# Quadrature of integrals in generated code: rule against error and CPU",
        "",
        "Written by `benchmarks/quadrature.py` (see its docstring). Uniform disc (R = 1) sliding and spinning on a",
        "rough plane; friction force F and torque T from the compiled right-hand side against the closed forms of",
        "Farkas et al. (2003). *inside*: largest relative error over ε = v/(Rω) ∈ {0.2, 0.4, 0.653} (instantaneous",
        "centre inside the disc); *outside*: ε ∈ {1.5, 3}. CPU: one right-hand side call (three integrals over the",
        f"disc, one pass over the nodes), median. Default rule: {DEFAULT_RULE.panels} panels × {DEFAULT_RULE.order} "
        "points. The inner variable (the radius) is split",
        "where |v| is smallest along it: twice its points.",
        "",
        "| panels × order | points per variable | error inside (python) | error outside | error inside (numba) "
        "| CPU python | CPU numba |",
        "|---|---:|---:|---:|---:|---:|---:|",
    ]
    for rule, e_in, e_out, e_nb, c_py, c_nb in rows:
        mark = " (default)" if rule == DEFAULT_RULE else ""
        lines.append(f"| {rule.panels} × {rule.order}{mark} | {rule.size} | {e_in:.1e} | {e_out:.1e} "
                     f"| {e_nb:.1e} | {c_py * 1e6:.0f} µs | {c_nb * 1e6:.1f} µs |")
    out = ROOT / "benchmarks" / "results" / "quadrature.md"
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
