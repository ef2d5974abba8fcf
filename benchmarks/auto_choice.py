"""``method="auto"`` against every applicable adaptive method on the benchmark problems (issue #23 item 3).

For each problem of :mod:`lagrange.bench.problems` (double pendulum, Kepler, 5-link pendulum, stiff damped double
pendulum, heavy top, stick-slip belt, Greenspan's rigid top; the full run adds the 10-link pendulum) and each
tolerance, ``simulate(method=m)`` runs for ``auto`` and every adaptive method of the registry that accepts the
request (a method that refuses it is listed as refused; RK23 and heyoka are left out), python backend, default
loop. Times are CPU (``time.process_time``) and wall (``time.perf_counter``).

* **first call** — the first run of the method in a process, measured in a fresh python process (this script with
  ``--child``) in which no method has run before it: ``import``, the derivation, the python code generation, the
  Taylor tape (of a structural system's expanded equations: derived here too, as any taylor run stores them, so auto
  finds them at hand) and loading the C interpreter are done first and not counted; the child then warms what every
  method shares with one short RK23 run (``t_end/1000``: option checks, the initial state, the python model, the
  Trajectory; not counted) and times the first call at each tolerance in turn. A survey child first runs every other
  method (taylor, DOP853, RK45, LSODA, Radau, BDF) one after the other: the methods whose first call there is within
  3× of the fastest are the contenders; then ``auto`` and each contender run alone in their own child, ``--trials``
  times (5 in the full run), and the figure is the median of those solo trials (the ratio of the fastest trials is
  given too: noise on this shared machine only slows a run down). The other methods (which cannot be the best) show
  their survey figure (trials 0). Auto's first call includes its own first-use costs and those of the method it
  picks.
* **median** — in the main process, interleaved rounds of auto and the contenders (each round starts one
  method later, so no method always runs right after the same one): the median CPU and wall time of rounds
  1…R (round 0 is not timed); a method whose repeats have cost 5 s CPU stops after 3.
* **decision** — :func:`lagrange.integrate.auto.choose` alone (finite differences, bound or eigenvalues,
  choice; model already built): median CPU of 21 calls, and its share of auto's median run.
* **error** — of the first call in the first trial: max-norm of the state error at the problem's measurement
  times against its closed form or a tight reference (the problem's reference method at rtol 1e-12 / 1e-13).

Writes ``benchmarks/results/auto_choice.md`` and every sample to ``auto_choice.json``. Run::

    python benchmarks/auto_choice.py            # full: rtol 1e-6 and 1e-9, 5 trials, 21 rounds, + nlink10
    python benchmarks/auto_choice.py --quick    # short horizons, rtol 1e-9, 1 trial, 7 rounds, auto/taylor/DOP853
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from lagrange.bench.problems import get_problem
from lagrange.codegen.numeric import NumericModel
from lagrange.errors import LagrangeError
from lagrange.integrate import auto
from lagrange.integrate.prepare import initial_state
from lagrange.integrate.registry import METHODS
from lagrange.integrate.run import _needs, simulate

RESULTS = Path(__file__).parent / "results"
OTHERS = ("taylor",) + tuple(m.name for m in METHODS if m.adaptive and m.name not in ("heyoka", "RK23", "taylor"))
#: --quick: auto and the methods it picks on these problems (LSODA too on the stiff one)
QUICK_OTHERS = ("taylor", "DOP853")
#: a method stops repeating after 3 rounds once its repeats have cost this much CPU (seconds)
ROUND_BUDGET = 5.0
#: later first-call trials only for methods whose first call was within this factor of the fastest
CONTENDER = 3.0


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


def _run(system, problem, method, rtol, times, t_end=None):
    return simulate(system, problem.t_end if t_end is None else t_end, problem.initial, problem.params,
                    method=method, rtol=rtol, atol=rtol * problem.atol_scale,
                    t_eval=times if t_end is None else None, **problem.options)


def _first_calls(system, problem, methods, tolerances, times) -> dict:
    """In a child process: warm the shared first-use costs with a short RK23 run, then the first call of each
    method at each tolerance: ``{"method|rtol": [cpu, wall, y at the measurement times, label] or "refused: ..."}``."""
    _run(system, problem, "RK23", 1e-6, None, t_end=problem.t_end * 1e-3)
    out = {}
    for rtol in tolerances:
        for m in methods:
            try:
                sol, cpu, wall = _clock(lambda m=m, rtol=rtol: _run(system, problem, m, rtol, times))
                out[f"{m}|{rtol!r}"] = [cpu, wall, sol.y.tolist(), sol.method]
            except LagrangeError as exc:
                out[f"{m}|{rtol!r}"] = f"refused: {type(exc).__name__}"
    return out


def _tape(system) -> None:
    """The Taylor tape of the expanded equations (shared setup, like the derivation): for a structural system
    (the 10-link pendulum) its expanded equations are derived too, as a taylor run would — so auto finds them
    at hand (``System.expanded_at_hand``) as it would on any later run of the model (on-disk cache)."""
    try:
        NumericModel.tape_for(system.expanded)
    except LagrangeError:
        pass


def _child(name: str, methods: list[str], tolerances, quick: bool) -> dict:
    """The first calls of ``methods`` in a fresh python process (this script with ``--child``): JSON back."""
    cmd = [sys.executable, __file__, "--child", name, "--methods", ",".join(methods),
           "--rtols", ",".join(repr(r) for r in tolerances)] + (["--quick"] if quick else [])
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    lines = done.stdout.strip().splitlines()
    if done.returncode or not lines:
        raise RuntimeError(f"first-call child failed ({' '.join(cmd)}):\n{done.stderr[-2000:]}")
    return json.loads(lines[-1])


def _child_main(name: str, methods: list[str], tolerances, quick: bool) -> None:
    from lagrange.integrate.taylor import available_interpreter

    available_interpreter()
    problem = get_problem(name, quick=quick)
    system = problem.build()
    eqs = system.derived
    NumericModel.build(eqs, problem.params)
    _tape(system)
    print(json.dumps(_first_calls(system, problem, methods, tolerances, problem.times())))


def _decision(system, problem, rtol) -> tuple[float, str]:
    """Median CPU seconds of auto's decision alone (model already built), and the choice."""
    eqs = system.derived
    model = NumericModel.build(eqs, problem.params)
    y0 = initial_state(eqs.coordinates, problem.initial)
    needs = _needs(eqs, [], NumericModel.switches_of(eqs), None) | {"dense_output": ""}
    samples, name = [], ""
    for _ in range(21):
        (name, _why), cpu, _ = _clock(lambda: auto.choose(eqs, model.fun, 0.0, y0, t_end=problem.t_end, rtol=rtol,
                                                          backend="python", needs=needs))
        samples.append(cpu)
    return statistics.median(samples), name


def bench_problem(name: str, *, quick: bool, tolerances, rounds: int, trials: int) -> list[dict]:
    from lagrange.integrate.taylor import available_interpreter

    available_interpreter()  # load the C tape interpreter once (shared by taylor and auto's taylor runs)
    problem = get_problem(name, quick=quick)
    others = OTHERS if not quick else QUICK_OTHERS + (("LSODA",) if name == "stiff" else ())
    _, setup_cpu, _ = _clock(lambda: (problem.build().derived))
    system = problem.build()
    eqs = system.derived
    _, build_cpu, _ = _clock(lambda: NumericModel.build(eqs, problem.params))
    _tape(system)
    times = problem.times()
    # first calls: fresh child processes (this one has not run any method yet either). Trial 0: every other
    # method in one child (which could be the best, their errors, the first calls of the rest); then each
    # contender and auto alone in its own child, `trials` times.
    survey: dict[str, list] = {}
    refused: dict[str, str] = {}
    for key, value in _child(name, list(others), tolerances, quick).items():
        if isinstance(value, str):
            refused[key] = value
        else:
            survey[key] = value
    contenders = set()
    for rtol in tolerances:
        ran = {m: survey[f"{m}|{rtol!r}"][0] for m in others if f"{m}|{rtol!r}" in survey}
        fastest = min(ran.values(), default=0.0)
        contenders |= {m for m in ran if ran[m] <= CONTENDER * fastest}
    solo = ["auto"] + [m for m in others if m in contenders]
    first: dict[str, list] = {}
    for _trial in range(trials):
        for m in solo:
            for key, value in _child(name, [m], tolerances, quick).items():
                if isinstance(value, str):
                    refused[key] = value
                else:
                    first.setdefault(key, []).append(value)
    ref = _reference(problem, system, times)
    rows = []
    for rtol in tolerances:
        methods = tuple(m for m in solo if f"{m}|{rtol!r}" not in refused)
        stats = {}
        for m in ("auto",) + others:
            key = f"{m}|{rtol!r}"
            samples = first.get(key) or ([survey[key]] if key in survey else [])
            stats[m] = {"first": _median_pair(samples), "trials": len(first.get(key, [])), "cpu": [], "wall": [],
                        "error": None, "label": "", "refused": refused.get(key, ""),
                        "first_samples": [x[:2] for x in first.get(key, [])]}
            if samples:  # error and label of the first call (the first sample's)
                stats[m]["error"] = float(np.max(np.abs(np.array(samples[0][2]) - ref)))
                stats[m]["label"] = samples[0][3]
        repeated = methods
        for rep in range(rounds + 1):  # round 0: each method's first use in this process, not timed
            k = rep % len(repeated)  # each round starts one method later: no method always follows the same one
            for m in repeated[k:] + repeated[:k]:
                s = stats[m]
                if len(s["cpu"]) >= 3 and sum(s["cpu"]) > ROUND_BUDGET:
                    continue
                _, cpu, wall = _clock(lambda m=m, rtol=rtol: _run(system, problem, m, rtol, times))
                if rep:
                    s["cpu"].append(cpu)
                    s["wall"].append(wall)
        decision, choice = _decision(system, problem, rtol)
        rows.append({"problem": name, "rtol": rtol, "setup_cpu": setup_cpu + build_cpu, "decision_cpu": decision,
                     "choice": choice, "stats": stats})
        print(_table([rows[-1]]), flush=True)
    return rows


def _median_pair(samples: list) -> tuple[float, float] | None:  # samples: [cpu, wall, ...] per trial
    if not samples:
        return None
    return statistics.median(s[0] for s in samples), statistics.median(s[1] for s in samples)


def _fmt(x: float | None) -> str:
    if x is None:
        return "—"
    return f"{x * 1e3:.3g} ms" if x < 1 else f"{x:.3g} s"


def _med(s: dict) -> float | None:
    return statistics.median(s["cpu"]) if s["cpu"] else (s["first"][0] if s["first"] else None)


def _ratios(r: dict):
    """(best other by first call, auto first / its first, the same for the fastest trials, best other by
    median, auto median / its median)."""
    st = r["stats"]
    others = {m: s for m, s in st.items() if m != "auto" and s["first"] is not None and not s["refused"]}
    a = st["auto"]
    if a["first"] is None or not others:
        return None
    bf = min(others, key=lambda m: others[m]["first"][0])
    bm = min(others, key=lambda m: _med(others[m]))
    fastest = (min(x[0] for x in a["first_samples"]) / min(x[0] for x in st[bf]["first_samples"])
               if a["first_samples"] and st[bf]["first_samples"] else float("nan"))
    return bf, a["first"][0] / others[bf]["first"][0], fastest, bm, _med(a) / _med(others[bm])


def _table(rows: list[dict]) -> str:
    out = []
    for r in rows:
        st = r["stats"]
        a = st["auto"]
        med = _med(a)
        share = f" ({100 * r['decision_cpu'] / med:.1f} % of auto's median run)" if med else ""
        out += [f"### {r['problem']}, rtol {r['rtol']:g}: auto chose **{a['label'].split(' ')[0] or '—'}**; "
                f"decision alone {_fmt(r['decision_cpu'])} CPU{share}; shared setup (derivation + codegen) "
                f"{_fmt(r['setup_cpu'])} CPU, not counted", ""]
        ratios = _ratios(r)
        if ratios:
            bf, rf, rfast, bm, rm = ratios
            out += [f"auto / best other, CPU: first call ×{rf:.2f} (fastest trials ×{rfast:.2f}; best: {bf}), "
                    f"median ×{rm:.2f} (best: {bm})", ""]
        out += [f"auto's label: `{a['label']}`", "",
                "| method | first call CPU | first call wall | trials | first calls: fastest – slowest trial (CPU) | "
                "median CPU | median wall | error |",
                "|---|---|---|---|---|---|---|---|"]
        for m, s in st.items():
            if s["refused"]:
                out.append(f"| {m} | {s['refused']} | | | | | | |")
                continue
            if s["first"] is None:
                continue
            med_c = statistics.median(s["cpu"]) if s["cpu"] else None
            med_w = statistics.median(s["wall"]) if s["wall"] else None
            err = f"{s['error']:.1e}" if s["error"] is not None else "—"
            cpus = [x[0] for x in s["first_samples"]]
            spread = f"{_fmt(min(cpus))} – {_fmt(max(cpus))}" if cpus else "—"
            out.append(f"| {m} | {_fmt(s['first'][0])} | {_fmt(s['first'][1])} | {s['trials']} | {spread} | "
                       f"{_fmt(med_c)} | {_fmt(med_w)} | {err} |")
        out.append("")
    return "\n".join(out)


#: how to read the first-call columns (printed under the summary)
READING = ("How to read the first calls: noise on this shared machine only slows a run down, and the first "
           "calls of one and the same method in fresh processes are bimodal here (the fastest – slowest column: "
           "e.g. 18.7–30.1 ms for the 5-link Taylor run, no garbage collection during the call), so a median of a "
           "handful of trials lands in either mode by chance. The fastest trials' ratio is the estimate of what "
           "auto's first call costs over the best method's; the median of the trials is shown beside it.")


def _summary(rows: list[dict]) -> str:
    lines = ["| problem | rtol | auto's choice | decision CPU (share of auto's run) | auto first / best first (CPU; "
             "median of trials) | fastest trial / fastest trial | best first | auto median / best median (CPU) | "
             "best median | auto error | best's error |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        ratios = _ratios(r)
        if not ratios:
            continue
        bf, rf, rfast, bm, rm = ratios
        a = r["stats"]["auto"]
        lines.append(f"| {r['problem']} | {r['rtol']:g} | {a['label'].split(' ')[0]} | {_fmt(r['decision_cpu'])} "
                     f"({100 * r['decision_cpu'] / _med(a):.1f} %) | ×{rf:.2f} | ×{rfast:.2f} | {bf} | ×{rm:.2f} | "
                     f"{bm} | {a['error']:.1e} | {r['stats'][bf]['error']:.1e} |")
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--problem", action="append")
    ap.add_argument("--trials", type=int, default=None, help="first-call trials (fresh child processes) per method")
    ap.add_argument("--rounds", type=int, default=None, help="interleaved rounds for the medians")
    ap.add_argument("--out", default=str(RESULTS / "auto_choice.md"))
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("--methods", help=argparse.SUPPRESS)
    ap.add_argument("--rtols", help=argparse.SUPPRESS)
    ap.add_argument("--render", action="store_true",
                    help="rewrite --out from its .json (every sample) without measuring: the run's header is kept")
    args = ap.parse_args()
    if args.child:
        _child_main(args.child, args.methods.split(","), tuple(float(r) for r in args.rtols.split(",")), args.quick)
        return
    if args.render:
        out = Path(args.out)
        rows = json.loads(out.with_suffix(".json").read_text())
        head = out.read_text().split("\n## Summary", 1)[0]
        out.write_text("\n".join([head, "## Summary", "", _summary(rows), "", READING, "", "## Per problem", "",
                                  _table(rows)]))
        return
    names = args.problem or ["double_pendulum", "kepler", "nlink", "stiff", "top", "stick_slip", "greenspan"]
    if not args.quick and not args.problem:
        names.append("nlink10")
    tolerances = (1e-9,) if args.quick else (1e-6, 1e-9)
    trials = args.trials or (1 if args.quick else 5)
    rounds = args.rounds or (7 if args.quick else 21)
    t0 = time.perf_counter()
    rows = [r for n in names for r in bench_problem(n, quick=args.quick, tolerances=tolerances, rounds=rounds,
                                                   trials=trials)]
    mode = (f"{'Quick run (short horizons; auto, taylor, DOP853, and LSODA on stiff)' if args.quick else 'Full run'}"
            f": {trials} first-call trial(s), {rounds} interleaved rounds for the medians")
    text = "\n".join([
        "# method=\"auto\" against every applicable method (benchmarks/auto_choice.py)", "",
        f"Machine: {platform.machine()}, {platform.system()} {platform.release()}, {os.cpu_count()} logical cores, "
        f"python {platform.python_version()}; shared with other jobs (compare ratios, not absolute times). {mode}; "
        f"total {time.perf_counter() - t0:.0f} s wall. Python backend, default loop; atol = rtol × the problem's "
        "scale. CPU = `time.process_time` of the process that ran the call; wall = `time.perf_counter`.", "",
        "What is counted: **first call** = the first `simulate` of that method in a fresh python process, after the "
        "shared setup (imports, derivation, python code generation, Taylor tape, C interpreter loaded: not "
        "counted; for the structural 10-link model its expanded equations as well, which auto weighs Taylor "
        "with when they are at hand) and one short RK23 run that warms what every method shares (not counted). "
        "A survey process runs "
        f"every other method in turn; those within {CONTENDER:g}× of the fastest first call there are the "
        "contenders; auto and each contender then run alone in their own fresh process, once per trial: median "
        "of the trials (trials 0 = the survey figure, for methods that cannot be the best). Each method's own "
        "first-use costs are in its first call (auto's include those of the method it picks). **Median** = "
        "interleaved rounds of auto and the contenders in one process, each round starting one method later, "
        f"round 0 not timed; a method whose repeats cost {ROUND_BUDGET:g} s CPU stops after 3. **Decision** = "
        "`lagrange.integrate.auto.choose` alone on a built model (median of 21 calls).", "",
        "## Summary", "", _summary(rows), "", READING, "", "## Per problem", "", _table(rows)])
    Path(args.out).write_text(text)
    Path(args.out).with_suffix(".json").write_text(json.dumps(rows, indent=1))  # every sample
    print(_summary(rows))


if __name__ == "__main__":
    main()
