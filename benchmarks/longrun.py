"""Long runs (issue #23 item 7): the geometric integrators against the Taylor methods (lagrange's own and
heyoka.py's) at equal energy AND position error.

Problems (both conservative, autonomous, unconstrained):

* **Kepler**, e = 0.5, a = μ = 1 (period 2π), Cartesian coordinates (separable H, constant M), over 10⁴
  periods (``--quick``: 100). Reference: the closed form through Kepler's equation
  (:func:`lagrange.bench.problems.kepler_state`).
* **Double pendulum** (unit masses and rods, g = 9.81), q = (0.3, −0.2), at rest: regular (quasi-periodic)
  motion, so errors grow polynomially and a long run measures the method, not chaos; M depends on q (not
  separable: no Störmer–Verlet or composition). t ∈ [0, 2000] (``--quick``: 100). Reference: heyoka's Taylor
  method in extended precision (``np.longdouble``, tol = 1e-19).

Each method runs at several step sizes (fixed-step: verlet, its compositions verlet6/verlet8, gl4, gl6, dg —
all in the compiled numba loop) or tolerances (``method="taylor"``; heyoka default and compact mode). Every
run records 101 equally spaced states; the errors are the maxima over them of the relative energy error
``|E − E0|/|E0|`` and of the position error ``max_i |q_i − q_i,ref|``.

Timing: each run is warmed up first (numba JIT or cache load, heyoka's LLVM compilation, the Taylor method's
tape/compiled series — first-use costs are NOT counted; imports are not counted), then timed in rounds that
interleave all runs (A, B, C, …, A, B, C, …) so that the load of this shared machine hits them alike. CPU time
(``time.process_time``, this process) and wall time (``time.perf_counter``); the tables give medians. A run
whose first sample takes more than ``--long`` seconds (default 3) is timed once. Report ratios, not absolute
times: the machine is shared.

Writes ``benchmarks/results/longrun.md`` (tables), ``longrun.csv`` (every run) and ``longrun.png``
(work-precision: CPU time against energy error and against position error)::

    python benchmarks/longrun.py            # full run (about 10 minutes of CPU)
    python benchmarks/longrun.py --quick    # 100 Kepler periods, t = 100 (under a minute once compiled)
"""

from __future__ import annotations

import argparse
import csv
import math
import platform
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from lagrange.bench.heyoka_adapter import heyoka_available, heyoka_model, heyoka_version
from lagrange.bench.problems import kepler_state, kepler_system
from lagrange.examples import n_link_pendulum
from lagrange.integrate import registry

RESULTS = Path(__file__).parent / "results"
N_OUT = 101
#: tolerances of the Taylor runs (lagrange's; heyoka's are the same with machine ε for the last)
TOLS = (1e-6, 1e-8, 1e-10, 1e-13, 1e-15)


@dataclass
class Case:
    name: str
    title: str
    system: object
    params: dict
    y0: np.ndarray
    t_end: float
    reference: object  # callable(times) -> states (k, 2n)
    separable: bool
    fixed: dict  # method -> list of steps h
    tols: tuple
    model: object = None
    ref_note: str = ""


@dataclass
class Run:
    case: str
    label: str
    family: str
    setting: str
    go: object  # callable() -> (times, states)
    warm: object = None  # callable() for first use (JIT, cache load); None: a full run of ``go``
    cpu: list = field(default_factory=list)
    wall: list = field(default_factory=list)
    setup: float = 0.0
    energy: float = math.nan
    position: float = math.nan
    note: str = ""


def _ic(system, y0) -> dict:
    names = [c.func.__name__ for c in system.derived.coordinates]
    return {nm: v for nm, v in zip(names + [n + "_dot" for n in names], y0)}


def kepler_case(quick: bool) -> Case:
    periods = 100 if quick else 10_000
    y0 = kepler_state([0.0])[0]
    steps = {"verlet": (1000,), "verlet6": (100,), "verlet8": (100,) if quick else (50, 100), "gl4": (200,),
             "gl6": (100,), "dg": (200,)}
    return Case("kepler", f"Kepler, e = 0.5, {periods} periods (t = {2 * math.pi * periods:.6g})", kepler_system(),
                {"m": 1.0, "mu": 1.0}, y0, 2 * math.pi * periods, lambda tt: kepler_state(tt), True,
                {m: [2 * math.pi / k for k in ks] for m, ks in steps.items()},
                TOLS, ref_note="closed form (Kepler's equation)")


def pendulum_case(quick: bool) -> Case:
    t_end = 100.0 if quick else 2000.0
    system = n_link_pendulum(2)
    steps = {"gl4": (0.02,), "gl6": (0.05, 0.025) if not quick else (0.05,), "dg": (0.005,)}
    case = Case("double_pendulum", f"double pendulum, q = (0.3, −0.2) at rest (regular motion), t ∈ [0, {t_end:g}]",
                system, {"g": 9.81}, np.array([0.3, -0.2, 0.0, 0.0]), t_end, None, False,
                {m: list(hs) for m, hs in steps.items() if hs}, TOLS)
    if heyoka_available():
        case.reference = _heyoka_reference(case)
        case.ref_note = "heyoka Taylor in extended precision (np.longdouble, tol 1e-19)"
    return case


def _heyoka_reference(case: Case):
    import heyoka as hy

    hm = heyoka_model(case.system, case.params)
    ta = hy.taylor_adaptive(hm.odes, np.asarray(case.y0, dtype=np.longdouble), tol=np.longdouble(1e-19),
                            fp_type=np.longdouble)
    cache: dict = {}

    def ref(times):
        key = (len(times), float(times[-1]))
        if key not in cache:
            ta.time = np.longdouble(0.0)
            ta.state[:] = np.asarray(case.y0, dtype=np.longdouble)
            cache[key] = np.array(ta.propagate_grid(np.asarray(times, dtype=np.longdouble))[-1], dtype=float)
        return cache[key]

    return ref


def _energy(case: Case, t, Y) -> float:
    E = case.model.diagnostics(t, Y)["energy"]
    E0 = case.model.diagnostics(np.zeros(1), case.y0[None, :])["energy"][0]
    return float(np.max(np.abs(E - E0)) / abs(E0))


def _position(case: Case, t, Y) -> float:
    n = len(case.y0) // 2
    R = case.reference(np.asarray(t))
    return float(np.max(np.abs(Y[:, :n] - R[:, :n])))


def lagrange_runs(case: Case) -> list[Run]:
    system, ic, params, T = case.system, _ic(case.system, case.y0), case.params, case.t_end
    model = case.model
    grid = np.linspace(0.0, T, N_OUT)
    runs = []
    for method, hs in case.fixed.items():
        entry = registry.find(method)
        if entry is None:
            continue
        for h in hs:
            steps = int(round(T / h))
            steps -= steps % (N_OUT - 1)  # records at the output grid (every stride-th step)

            def go(method=method, steps=steps):
                sol = system.simulate((0.0, T), ic, params, method=method, step=T / steps, model=model,
                                      loop="compiled", n_points=N_OUT)
                return sol.t, sol.y

            def warm(method=method, steps=steps):  # load or compile the loop and the model's pieces
                system.simulate((0.0, 100 * T / steps), ic, params, method=method, step=T / steps, model=model,
                                loop="compiled", n_points=2)

            runs.append(Run(case.name, f"{method} h={T / steps:.3g}", f"{method} (order {entry.order}, fixed step)",
                            f"h={T / steps:.3g}", go, warm))
    for tol in case.tols:
        def go(tol=tol):
            sol = system.simulate((0.0, T), ic, params, method="taylor", rtol=tol, atol=tol, model=model, t_eval=grid)
            return sol.t, sol.y

        runs.append(Run(case.name, f"taylor tol={tol:g}", "lagrange taylor (compiled series)", f"tol={tol:g}", go))
    return runs


def heyoka_runs(case: Case) -> list[Run]:
    if not heyoka_available():
        return []
    hm = heyoka_model(case.system, case.params)
    grid = np.linspace(0.0, case.t_end, N_OUT)
    runs = []
    for compact in (False, True):
        mode = "compact" if compact else "default"
        for tol in (*TOLS[:-1], 2.0**-52):
            holder = {}

            def go(tol=tol, compact=compact, holder=holder):
                if "ta" not in holder:
                    holder["ta"], holder["build"] = hm.integrator(case.y0, tol, compact=compact)
                Y, _ = hm.propagate(holder["ta"], case.y0, grid)
                return grid, Y

            setting = "tol=eps" if tol == 2.0**-52 else f"tol={tol:g}"
            runs.append(Run(case.name, f"heyoka {mode} {setting}", f"heyoka {mode} mode", setting, go))
    return runs


def measure(runs: list[Run], case_of: dict, rounds: int, long_s: float) -> None:
    """Warm up every run (timed as ``setup``), measure its errors (a first full run, timed as the first sample
    when the warm-up was short), then ``rounds`` interleaved rounds."""
    for r in runs:
        c0 = time.process_time()
        try:
            if r.warm is not None:
                r.warm()
                r.setup = time.process_time() - c0
                w0, c0 = time.perf_counter(), time.process_time()
            t, Y = r.go()
            if r.warm is not None:
                r.cpu.append(time.process_time() - c0)
                r.wall.append(time.perf_counter() - w0)
        except Exception as exc:  # a failing method is a result too: say so in the table
            r.note = f"{type(exc).__name__}: {str(exc)[:120]}"
            r.go = None
            print(f"  {r.case:16s} {r.label:28s} FAILED {r.note}", flush=True)
            continue
        if r.warm is None:
            r.setup = time.process_time() - c0
        case = case_of[r.case]
        r.energy, r.position = _energy(case, t, Y), _position(case, t, Y)
        print(f"  {r.case:16s} {r.label:28s} first {r.setup:8.3f} s  dE {r.energy:.2e}  dq {r.position:.2e}",
              flush=True)
    for _ in range(rounds):
        for r in runs:
            if r.go is None or (r.cpu and r.cpu[0] > long_s):
                continue
            w0, c0 = time.perf_counter(), time.process_time()
            r.go()
            r.cpu.append(time.process_time() - c0)
            r.wall.append(time.perf_counter() - w0)


def _fmt_t(s: float) -> str:
    return "—" if not s == s else (f"{s * 1e3:.3g} ms" if s < 1 else f"{s:.3g} s")


def write(cases: list[Case], runs: list[Run], out: Path, args) -> None:
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "longrun.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["problem", "run", "family", "setting", "cpu_median_s", "wall_median_s", "samples",
                    "first_use_cpu_s", "energy_error", "position_error", "note"])
        for r in runs:
            w.writerow([r.case, r.label, r.family, r.setting, _median(r.cpu), _median(r.wall), len(r.cpu),
                        f"{r.setup:.4g}", f"{r.energy:.3e}", f"{r.position:.3e}", r.note])
    import numba
    import scipy

    lines = ["# Long runs: geometric integrators against Taylor (lagrange `taylor`, heyoka)", "",
             f"Generated by `python benchmarks/longrun.py{' --quick' if args.quick else ''}` "
             f"({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}). Python {platform.python_version()}, "
             f"numpy {np.__version__}, scipy {scipy.__version__}, numba {numba.__version__}, "
             f"heyoka {heyoka_version() or 'not installed'}; {platform.processor() or platform.machine()}, "
             "2 cores shared with other work.", "",
             "Times: medians of interleaved rounds (A, B, C, …, A, B, C, …) of CPU time (`time.process_time`) and "
             "wall time (`time.perf_counter`); runs longer than "
             f"{args.long:g} s were timed once. First use (numba JIT or cache load, heyoka's LLVM compilation, the "
             "Taylor series' compilation) and imports are NOT in the times; the `first use` column is the CPU time "
             "of the warm-up run, which includes them (fixed-step methods: a warm-up of 100 steps; their first full "
             "run is then their first sample). Errors: maximum over 101 equally spaced output times of the "
             "relative energy error |E − E0|/|E0| and of the position error max_i |q_i − q_i,ref|. Fixed-step "
             "methods run in the compiled numba loop.", ""]
    for case in cases:
        rows = [r for r in runs if r.case == case.name]
        lines += [f"## {case.title}", "", f"Reference: {case.ref_note}.", "",
                  "| run | CPU (median) | wall (median) | samples | first use (CPU) | energy error | position error |"
                  " CPU / heyoka at ≤ same errors |",
                  "|---|---|---|---|---|---|---|---|"]
        hey = [r for r in rows if r.label.startswith("heyoka") and r.cpu]
        for r in rows:
            ratio = _ratio(r, hey)
            lines.append(f"| {r.label} | {_fmt_t(_median(r.cpu))} | {_fmt_t(_median(r.wall))} | {len(r.cpu)} | "
                         f"{_fmt_t(r.setup)} | {r.energy:.1e} | {r.position:.1e} | {ratio} |"
                         + (f" {r.note}" if r.note else ""))
        lines += ["", "Last column: this run's CPU time over the CPU time of the cheapest heyoka run (either mode) "
                  "whose energy AND position errors are both no larger than this run's (— when no heyoka run is that "
                  "coarse: then every heyoka run is more accurate on both counts).", ""]
        lines += _summary(case, rows)
    (out / "longrun.md").write_text("\n".join(lines) + "\n")
    _plot(cases, runs, out)


def _median(xs) -> float:
    return statistics.median(xs) if xs else math.nan


def _ratio(r: Run, hey: list[Run]) -> str:
    if r.label.startswith("heyoka") or not r.cpu:
        return ""
    ok = [h for h in hey if h.energy <= max(r.energy, 1e-16) and h.position <= max(r.position, 1e-16)]
    if not ok:
        return "—"
    best = min(ok, key=lambda h: _median(h.cpu))
    return f"{_median(r.cpu) / _median(best.cpu):.3g}× ({best.label})"


def _summary(case: Case, rows: list[Run]) -> list[str]:
    """Per family: the most accurate run, and the cheapest heyoka run at least as accurate on both errors."""
    fams: dict = {}
    for r in rows:
        if r.cpu:
            fams.setdefault(r.family, []).append(r)
    out = ["Best of each family (its most accurate run by position error):", "",
           "| family | run | CPU | energy error | position error |", "|---|---|---|---|---|"]
    for fam, rs in fams.items():
        b = min(rs, key=lambda r: (r.position, _median(r.cpu)))
        out.append(f"| {fam} | {b.label} | {_fmt_t(_median(b.cpu))} | {b.energy:.1e} | {b.position:.1e} |")
    return out + [""]


def _plot(cases, runs, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(cases), 2, figsize=(12, 4.8 * len(cases)), squeeze=False)
    for row, case in zip(axes, cases):
        rows = [r for r in runs if r.case == case.name and r.cpu]
        fams = sorted({r.family for r in rows})
        for ax, key, what in ((row[0], "energy", "relative energy error"), (row[1], "position", "position error")):
            for i, fam in enumerate(fams):
                rs = sorted((r for r in rows if r.family == fam), key=lambda r: _median(r.cpu))
                ax.loglog([_median(r.cpu) for r in rs], [max(getattr(r, key), 1e-17) for r in rs],
                          "o-" if not fam.startswith("heyoka") else "s--", label=fam, color=f"C{i % 10}")
            ax.set_xlabel("CPU time per run [s] (median, first use excluded)")
            ax.set_ylabel(what)
            ax.set_title(f"{case.name}: {what}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
        row[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "longrun.png", dpi=110)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="100 Kepler periods, double pendulum to t = 100")
    ap.add_argument("--rounds", type=int, default=3, help="interleaved timing rounds (default 3)")
    ap.add_argument("--long", type=float, default=3.0, help="time runs whose first sample exceeds this once")
    ap.add_argument("--problem", action="append", choices=("kepler", "double_pendulum"))
    ap.add_argument("--out", default=str(RESULTS))
    args = ap.parse_args()
    makers = {"kepler": kepler_case, "double_pendulum": pendulum_case}
    cases = [makers[p](args.quick) for p in (args.problem or makers)]
    runs = []
    for case in cases:
        case.model = case.system.compile(case.params, backend="numba")
        if case.reference is None:
            print(f"{case.name}: no reference (heyoka missing), skipped")
            continue
        runs += lagrange_runs(case) + heyoka_runs(case)
    measure(runs, {c.name: c for c in cases}, args.rounds, args.long)
    write(cases, runs, Path(args.out), args)
    print((Path(args.out) / "longrun.md").read_text())


if __name__ == "__main__":
    main()
