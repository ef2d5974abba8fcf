"""``method="auto"`` against every applicable adaptive method on the benchmark problems (issue #23 item 3).

For each problem of :mod:`lagrange.bench.problems` (double pendulum, Kepler, 5-link pendulum, stiff damped double
pendulum, heavy top, stick-slip belt, Greenspan's rigid top; the full run adds the 10-link pendulum) and each
tolerance, ``simulate(method=m)`` runs for ``auto`` and every adaptive method of the registry that accepts the
request (a method that refuses it is listed as refused), python backend, default loop, in ONE process,
interleaved (auto, taylor, DOP853, …, auto, taylor, …). Per method:

* **first call**: the first run of the method in the process — its own first-use costs included (the generated
  Jacobian of the implicit methods, loading the Taylor interpreter; auto's decision). Auto runs first in the
  first round, so any shared first-use cost is charged to auto.
* **median**: median CPU (``time.process_time``) and wall (``time.perf_counter``) time of the later repeats.
* **error**: max-norm of the state error at the problem's measurement times against its closed form or a
  tight reference (the problem's reference method at rtol 1e-12 / 1e-13).

Not counted (shared by every method, done once before timing, reported in the setup column): ``import``,
the derivation, the python code generation of the right-hand side and the Taylor tape. The time of auto's
decision alone (finite-difference Jacobian + eigenvalues + the choice, :func:`lagrange.integrate.auto.choose`)
is measured separately (median CPU of 5 calls).

Writes ``benchmarks/results/auto_choice.md``. Run::

    python benchmarks/auto_choice.py            # full: rtol 1e-6 and 1e-9, 3 repeats, + nlink10
    python benchmarks/auto_choice.py --quick    # short horizons, rtol 1e-9, 1 repeat (about a minute)
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from pathlib import Path

import numpy as np

from lagrange.bench.problems import get_problem
from lagrange.codegen.numeric import NumericModel
from lagrange.errors import LagrangeError
from lagrange.integrate import auto
from lagrange.integrate.registry import METHODS
from lagrange.integrate.run import _needs, simulate

RESULTS = Path(__file__).parent / "results"
METHOD_NAMES = ("auto",) + tuple(m.name for m in METHODS if m.adaptive and m.name not in ("heyoka", "RK23"))
#: --quick: auto and the methods it chooses between (RK45, Radau and BDF only in the full run)
QUICK_NAMES = ("auto", "taylor", "DOP853", "LSODA")
#: a method whose first call takes longer (CPU seconds) is not repeated (its median is its first call)
SLOW_FIRST = 3.0


def _clock(fn):
    c0, w0 = time.process_time(), time.perf_counter()
    out = fn()
    return out, time.process_time() - c0, time.perf_counter() - w0


def _reference(problem, system, times):
    if problem.exact is not None:
        return problem.exact(times)
    tight = 1e-12 if problem.reference_method != "DOP853" else 1e-13
    sol = simulate(system, problem.t_end, problem.initial, problem.params, method=problem.reference_method,
                   rtol=tight, atol=tight * problem.atol_scale, t_eval=times, **problem.options)
    return sol.y


def _decision_seconds(system, problem, rtol) -> tuple[float, str]:
    """Median CPU seconds of auto's decision alone (model already built), and the choice."""
    eqs = system.derived
    model = NumericModel.build(eqs, problem.params)
    y0 = np.array([problem.initial[k] for k in _state_names(eqs)], dtype=float)
    needs = _needs(eqs, [], NumericModel.switches_of(eqs), None)
    samples, name = [], ""
    for _ in range(5):
        (name, _why), cpu, _ = _clock(lambda: auto.choose(eqs, model.fun, 0.0, y0, t_end=problem.t_end, rtol=rtol,
                                                          backend="python", needs=needs))
        samples.append(cpu)
    return statistics.median(samples), name


def _state_names(eqs) -> list[str]:
    names = [c.func.__name__ for c in eqs.coordinates]
    return names + [f"{n}_dot" for n in names]


def bench_problem(name: str, *, quick: bool, tolerances, repeats: int) -> list[dict]:
    from lagrange.integrate.taylor import available_interpreter

    available_interpreter()  # load the C tape interpreter once (shared by taylor and auto's taylor runs)
    methods = QUICK_NAMES if quick else METHOD_NAMES
    problem = get_problem(name, quick=quick)
    _, setup_cpu, _ = _clock(lambda: (problem.build().derived))
    system = problem.build()
    eqs = system.derived
    _, build_cpu, _ = _clock(lambda: NumericModel.build(eqs, problem.params))
    try:
        NumericModel.tape_for(eqs)
    except LagrangeError:
        pass
    times = problem.times()
    ref = _reference(problem, system, times)
    rows = []
    for rtol in tolerances:
        atol = rtol * problem.atol_scale
        stats = {m: {"first": None, "cpu": [], "wall": [], "error": None, "label": "", "refused": ""}
                 for m in methods}
        for rep in range(repeats + 1):
            for m in methods:
                if stats[m]["refused"] or (rep and stats[m]["first"][0] > SLOW_FIRST):
                    continue
                try:
                    sol, cpu, wall = _clock(lambda m=m, rtol=rtol, atol=atol: simulate(
                        system, problem.t_end, problem.initial, problem.params, method=m, rtol=rtol, atol=atol,
                        t_eval=times, **problem.options))
                except LagrangeError as exc:
                    stats[m]["refused"] = type(exc).__name__
                    continue
                if rep == 0:
                    stats[m]["first"] = (cpu, wall)
                    stats[m]["error"] = float(np.max(np.abs(sol.y - ref)))
                    stats[m]["label"] = sol.method
                else:
                    stats[m]["cpu"].append(cpu)
                    stats[m]["wall"].append(wall)
        decision, choice = _decision_seconds(system, problem, rtol)
        rows.append({"problem": name, "rtol": rtol, "setup_cpu": setup_cpu + build_cpu, "decision_cpu": decision,
                     "choice": choice, "stats": stats})
        print(_table([rows[-1]]), flush=True)
    return rows


def _fmt(x: float | None) -> str:
    if x is None:
        return "—"
    return f"{x * 1e3:.3g} ms" if x < 1 else f"{x:.3g} s"


def _table(rows: list[dict]) -> str:
    out = []
    for r in rows:
        st = r["stats"]
        ran = {m: s for m, s in st.items() if s["first"] is not None}
        others = {m: s for m, s in ran.items() if m != "auto"}
        best_first = min(others, key=lambda m: others[m]["first"][0]) if others else None
        best_med = min(others, key=lambda m: statistics.median(others[m]["cpu"] or [others[m]["first"][0]])) \
            if others else None
        a = st["auto"]
        head = (f"### {r['problem']}, rtol {r['rtol']:g}: auto chose **{a['label'].split(' ')[0] or '—'}**; "
                f"decision alone {_fmt(r['decision_cpu'])} CPU; shared setup (derivation + codegen) "
                f"{_fmt(r['setup_cpu'])} CPU, not counted")
        out += [head, ""]
        if a["first"] is not None and best_first is not None:
            ratio_first = a["first"][0] / others[best_first]["first"][0]
            med = statistics.median(a["cpu"] or [a["first"][0]])
            ratio_med = med / statistics.median(others[best_med]["cpu"] or [others[best_med]["first"][0]])
            out += [f"auto / best other, CPU: first call ×{ratio_first:.2f} (best: {best_first}), "
                    f"median ×{ratio_med:.2f} (best: {best_med})", ""]
        out += ["| method | first call CPU | first call wall | median CPU | median wall | error |",
                "|---|---|---|---|---|---|"]
        for m, s in st.items():
            if s["refused"]:
                out.append(f"| {m} | refused ({s['refused']}) | | | | |")
                continue
            if s["first"] is None:
                continue
            med_c = statistics.median(s["cpu"]) if s["cpu"] else None
            med_w = statistics.median(s["wall"]) if s["wall"] else None
            out.append(f"| {m} | {_fmt(s['first'][0])} | {_fmt(s['first'][1])} | {_fmt(med_c)} | {_fmt(med_w)} | "
                       f"{s['error']:.1e} |")
        out.append("")
    return "\n".join(out)


def _summary(rows: list[dict]) -> str:
    lines = ["| problem | rtol | auto's choice | decision CPU | auto first / best first (CPU) | best other | "
             "auto median / best median (CPU) | auto error | best's error |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        st = r["stats"]
        others = {m: s for m, s in st.items() if m != "auto" and s["first"] is not None}
        a = st["auto"]
        if a["first"] is None or not others:
            continue
        bf = min(others, key=lambda m: others[m]["first"][0])
        bm = min(others, key=lambda m: statistics.median(others[m]["cpu"] or [others[m]["first"][0]]))
        amed = statistics.median(a["cpu"] or [a["first"][0]])
        omed = statistics.median(others[bm]["cpu"] or [others[bm]["first"][0]])
        lines.append(f"| {r['problem']} | {r['rtol']:g} | {a['label'].split(' ')[0]} | {_fmt(r['decision_cpu'])} | "
                     f"×{a['first'][0] / others[bf]['first'][0]:.2f} | {bf} | ×{amed / omed:.2f} ({bm}) | "
                     f"{a['error']:.1e} | {others[bf]['error']:.1e} |")
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--problem", action="append")
    ap.add_argument("--out", default=str(RESULTS / "auto_choice.md"))
    args = ap.parse_args()
    names = args.problem or ["double_pendulum", "kepler", "nlink", "stiff", "top", "stick_slip", "greenspan"]
    if not args.quick and not args.problem:
        names.append("nlink10")
    tolerances = (1e-9,) if args.quick else (1e-6, 1e-9)
    repeats = 1 if args.quick else 3
    t0 = time.perf_counter()
    rows = [r for n in names for r in bench_problem(n, quick=args.quick, tolerances=tolerances, repeats=repeats)]
    text = "\n".join([
        "# method=\"auto\" against every applicable method (benchmarks/auto_choice.py)", "",
        f"Machine: {platform.machine()}, {platform.system()} {platform.release()}, python "
        f"{platform.python_version()}; shared with other jobs (compare ratios, not absolute times). "
        f"{'Quick run (short horizons, 1 repeat)' if args.quick else 'Full run (3 repeats after the first call)'}; "
        f"total {time.perf_counter() - t0:.0f} s wall. Python backend, default loop; atol = rtol × the problem's "
        "scale. Imports, derivation, the python code generation and the Taylor tape are shared and not counted; "
        "the C tape interpreter is loaded before timing; each method's own first-use costs are in its first call "
        "(auto runs first in each round, so any other shared first-use cost falls on auto). Interleaved: every "
        f"round runs auto then each method once. A method whose first call exceeds {SLOW_FIRST:g} s CPU is not "
        "repeated." + (" Quick run: auto, taylor, DOP853 and LSODA only." if args.quick else ""), "",
        "## Summary", "", _summary(rows), "", "## Per problem", "", _table(rows)])
    Path(args.out).write_text(text)
    print(_summary(rows))


if __name__ == "__main__":
    main()
