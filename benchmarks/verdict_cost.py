"""Cost of the accuracy verdict (lagrange.integrate.checks) next to the run it checks.

For n-link pendulums (t = 10, 1001 output points): the run alone (the engine called directly), then each
check on the finished trajectory — the energy check with the model's diagnostics function not yet built (its
first use builds it) and built, the Taylor checks, and the fixed-step estimate. Writes
benchmarks/results/verdict_cost.md.

    python benchmarks/verdict_cost.py
"""

from __future__ import annotations

import dataclasses
import time
import warnings
from pathlib import Path

import numpy as np

from lagrange import t
from lagrange.examples import n_link_pendulum
from lagrange.integrate.fixed import integrate_fixed, step_doubling_check
from lagrange.integrate.taylor import integrate_taylor, restarter
from lagrange.integrate.taylor_checks import taylor_checks
from lagrange.results.verdict import energy_check

OUT = Path(__file__).parent / "results" / "verdict_cost.md"


def _ms(f, repeats: int = 3) -> float:
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return 1e3 * best


def _row(links: int) -> str:
    s = n_link_pendulum(links)
    ic = {**{q: 0.5 for q in s.coordinates}, **{q.diff(t): 0.0 for q in s.coordinates}}
    sol = s.simulate(10, ic, {"g": 9.81}, method="taylor")
    y0, te = sol.initial[1], np.linspace(0, 10, 1001)
    run = _ms(lambda: integrate_taylor(sol.model, (0, 10), y0, te, rtol=1e-9, atol=1e-11))
    fresh = dataclasses.replace(sol, model=s.compile({"g": 9.81}))
    start = time.perf_counter()
    energy_check(fresh, 1e-9, 1e-11)
    cold = 1e3 * (time.perf_counter() - start)
    warm = _ms(lambda: energy_check(sol, 1e-9, 1e-11))

    def taylor():
        restart, order = restarter(sol.model, rtol=1e-9, atol=1e-11)
        taylor_checks(sol, restart, order, 1e-9, 1e-11)

    tay = _ms(taylor)
    dop = s.simulate(10, ic, {"g": 9.81})
    dop_run = _ms(lambda: s.simulate(10, ic, {"g": 9.81}, model=dop.model))
    gl = integrate_fixed(s, (0, 10), y0, {"g": 9.81}, method="gl4", step=0.01, model=sol.model)
    gl_run = _ms(lambda: integrate_fixed(s, (0, 10), y0, {"g": 9.81}, method="gl4", step=0.01, model=sol.model), 1)
    est = _ms(lambda: step_doubling_check(gl, method="gl4", step=0.01, t_span=(0, 10), y0=y0, compiled=False,
                                          rtol=1e-2, atol=1e-6), 1)
    return f"| {links} | {run:.1f} | {tay:.1f} | {dop_run:.1f} | {cold:.0f} | {warm:.2f} | {gl_run:.0f} | {est:.0f} |"


def main() -> None:
    warnings.simplefilter("ignore")
    rows = [_row(links) for links in (1, 3, 6)]
    text = "\n".join([
        "# Cost of the accuracy verdict (`python benchmarks/verdict_cost.py`)",
        "",
        "n-link pendulum, t = 10, 1001 output points; milliseconds, best of 3 (fixed-step: one run).",
        "",
        "| links | taylor run | Taylor checks | DOP853 run with its checks (model given) | "
        "energy check, diagnostics not built | energy check, built | gl4 run (h = 0.01, python loop) | "
        "step-doubling estimate |",
        "|---|---|---|---|---|---|---|---|",
        *rows,
        "",
        "The energy check's first use on a model builds the model's diagnostics function (a lambdify of T, V, h and",
        "their parts), which `energy_error()`, `to_csv()`, `plot()` and the CLI's report need anyway; after that it",
        "costs a fraction of a millisecond. The Taylor checks cost a fixed amount per sampled state, whatever the",
        "length of the run. The step-doubling estimate is a second run at twice the step.",
        ""])
    OUT.write_text(text, encoding="utf-8")
    print(text)


if __name__ == "__main__":
    main()
