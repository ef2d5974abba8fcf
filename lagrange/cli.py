"""The ``lagrange`` command line: parses arguments and calls the library (no logic of its own).

Errors are one line on stderr and a non-zero exit (2 for bad input, 3 for an internal failure, 4 for a
simulation that reached its end but failed its own accuracy checks (:mod:`lagrange.results.verdict`), 130 after
Ctrl-C: ``simulate --csv`` then writes the trajectory computed up to the interrupt);
set ``LAGRANGE_DEBUG=1`` to see tracebacks. A closed pipe (``lagrange simulate ex3.4 | head -2``) ends the
command quietly. Nothing heavy is imported before the arguments are parsed (``lagrange --help`` and
``lagrange problems`` load no sympy, numpy or scipy: the problem list comes from the corpus index,
:mod:`lagrange.corpus.index`). Progress of long work goes to stderr (:mod:`lagrange.progress`) when it is
a terminal, unless ``--no-progress`` or ``-q``.

Every option is honoured or refused for every kind of spec (TOML file, Python file, corpus problem,
``greenspan-N``): the spec's values are defaults and the flags given override them
(:mod:`lagrange.spec.options`).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from contextlib import contextmanager

from . import __version__
from .errors import IntegrationInterrupted, LagrangeError, SpecError
from .integrate.methods import ADAPTIVE, FIXED_STEP
from .spec.options import check_names, merge_run_options, parse_assignments

__all__ = ["main"]

#: code-generation backends (:data:`lagrange.codegen.numeric.BACKENDS`, checked by the CLI test)
BACKENDS = ("python", "numba", "reference", "auto")
_MOLECULAR_PARAMS = ("A", "g")


def _kv(items, what) -> dict:
    return parse_assignments(items, what)


def _progress(args):
    from .progress import reporting

    return reporting(not (getattr(args, "no_progress", False) or getattr(args, "quiet", False)))


def _input_values(spec, args, params: dict) -> dict:
    """The spec's input values with ``--input`` overrides, the parameters' values substituted into expressions
    (which then hold t alone); ``{}`` when neither gives any (simulate then names any input left without a
    value). Parameters used only by the input values are removed from ``params`` (the system has none such)."""
    values = {**spec.inputs, **_kv(getattr(args, "input", None), "input")}
    out, used = {}, set()
    for name, value in values.items():
        if hasattr(value, "free_symbols"):
            used |= {s.name for s in value.free_symbols}
            value = value.subs({s: params[s.name] for s in value.free_symbols if s.name in params})
        out[name] = value
    own = {s.name for s in spec.system.derived.parameters}
    for name in used - own:
        params.pop(name, None)
    return out


def _input_parameters(spec) -> set:
    """Names used by the spec's input expressions that are not parameters of the system."""
    used = set().union(*(({s.name for s in v.free_symbols} if hasattr(v, "free_symbols") else set())
                         for v in spec.inputs.values()))
    return used - {s.name for s in spec.system.derived.parameters} - {"t"}


def _cmd_problems(args) -> int:
    from .corpus import index

    probs = index.entries(args.chapter)
    if not probs:
        chapters = sorted({e["chapter"] for e in index.entries()})
        raise SpecError(f"no problems in chapter {args.chapter} (chapters {chapters[0]}–{chapters[-1]})")
    chapter = None
    for p in probs:
        if p["chapter"] != chapter:
            chapter = p["chapter"]
            print(f"\nChapter {chapter}")
        dyn = "" if p["dynamics"] else "  [no dynamics]"
        print(f"  {p['id']:<22} {p['title']}{dyn}")
    if args.chapter is None:
        print("\nGreenspan's tetrahedral top (simulate with --model rigid|molecular)")
        for ex in index.greenspan_examples():
            masses = tuple(ex["masses"])
            extra = "" if masses == (1.0, 1.0, 1.0, 1.0) else f", masses {masses}"
            print(f"  greenspan-{ex['number']:<12} V = {ex['V']:g}, alpha = {ex['alpha_deg']:g} deg{extra}")
    print(f"\n{len(probs)} problem(s)")
    return 0


def _cmd_derive(args) -> int:
    import textwrap

    from .printing import display_equations, format_equations, format_momenta, latex, terminal_width

    spec = _load(args.spec)
    system = spec.system
    width = terminal_width()
    if spec.problem is not None and hasattr(spec.problem, "title"):
        print(textwrap.fill(f"{spec.problem.id}: {spec.problem.title} ({spec.problem.source})", width))
    if system is None:
        print("this problem has no equations of motion (its answers are checked by `lagrange verify`)")
        return 0
    if args.latex:
        for eq in display_equations(system):
            print(latex(eq))
    else:
        print(format_equations(system, width, full=args.full))
    momenta = format_momenta(system, width)
    if momenta:
        print("\n" + momenta)
    return 0


def _run_flags(args) -> dict:
    return {k: getattr(args, k, None) for k in ("method", "step", "rtol", "atol", "backend", "friction")}


def _name_of(key) -> str:
    """The name of a params/initial key: a string, a Symbol, a coordinate q(t) or its derivative."""
    from .conventions import VELOCITY_SUFFIX
    from .model.coordinates import coordinate_name, is_coordinate

    if isinstance(key, str):
        return key
    if is_coordinate(key):
        return coordinate_name(key)
    if getattr(key, "is_Derivative", False) and is_coordinate(key.expr):
        return coordinate_name(key.expr) + VELOCITY_SUFFIX
    return getattr(key, "name", str(key))


def _state_names(system) -> list[str]:
    from .conventions import VELOCITY_SUFFIX
    from .model.coordinates import coordinate_name

    names = [coordinate_name(q) for q in system.coordinates]
    return names + [n + VELOCITY_SUFFIX for n in names]


def _values(args, spec, label: str) -> tuple[dict, dict]:
    """(params, initial): the spec's values by name, overridden by --param/--initial (names checked)."""
    params, initial = _kv(args.param, "param"), _kv(args.initial, "initial")
    check_names(params, [p.name for p in spec.system.parameters] + sorted(_input_parameters(spec)), "param", label)
    check_names(initial, _state_names(spec.system), "initial", label)
    return ({**{_name_of(k): v for k, v in spec.params.items()}, **params},
            {**{_name_of(k): v for k, v in spec.initial.items()}, **initial})


def _load(spec: str):
    """``load_spec(spec)``, but a mistyped problem id is answered from the index before anything heavy loads."""
    from pathlib import Path

    if Path(spec).suffix.lower() not in (".toml", ".py") and not _is_greenspan(spec):
        from .corpus.index import unknown_id_error

        error = unknown_id_error(spec)
        if error is not None:
            raise error
    from .progress import heartbeat
    from .spec.loader import load_spec

    with heartbeat(f"loading {spec}"):
        return load_spec(spec)


_PLOT_SUFFIXES = (".png", ".pdf", ".svg", ".jpg", ".jpeg", ".eps", ".ps", ".tif", ".tiff", ".webp")
_OUTPUTS = {"plot": _PLOT_SUFFIXES, "csv": None, "animate": (".gif", ".mp4"), "out": (".csv", ".parquet"),
            "store": (".csv", ".parquet")}


def _check_outputs(args) -> None:
    """Refuse an output path whose folder does not exist or whose suffix cannot be written, before any work."""
    from pathlib import Path

    for attr, suffixes in _OUTPUTS.items():  # suffixes None: any name
        value = getattr(args, attr, None)
        if not isinstance(value, str):
            continue
        path = Path(value)
        if attr == "out" and args.command == "bench":  # a folder, created when missing
            if path.exists() and not path.is_dir():
                raise SpecError(f"--out {value}: exists and is not a folder (bench writes several files into it)")
            continue
        flag = f"--{attr}"
        if suffixes is not None and path.suffix.lower() not in suffixes:
            raise SpecError(f"{flag} {value}: write a {' or '.join(suffixes)} file")
        folder = path.parent if str(path.parent) else Path(".")
        if not folder.is_dir():
            raise SpecError(f"{flag} {value}: the folder {folder} does not exist")
        if not os.access(folder, os.W_OK):
            raise SpecError(f"{flag} {value}: the folder {folder} is not writable")


def _is_greenspan(spec: str) -> bool:
    return spec.strip().lower().startswith("greenspan")


def _refuse(args, names: dict[str, str], why: str) -> None:
    """SpecError for the first of ``names`` (attribute → "flag" or "flag: hint") given on the command line."""
    for attr, text in names.items():
        value = getattr(args, attr, None)
        if value not in (None, False, []):
            flag, _, hint = text.partition(": ")
            raise SpecError(f"{flag} does not apply to {why}" + (f" ({hint})" if hint else ""))


def _cmd_methods(args) -> int:
    from .integrate.registry import table

    print(table())
    return 0


def _cmd_simulate(args) -> int:
    if args.list_methods:
        return _cmd_methods(args)
    if args.spec is None:
        raise SpecError("simulate needs a spec (a problem id, a Python file or a TOML spec), or --list-methods")
    if args.model is not None and not args.spec.lower().startswith("greenspan-"):
        raise SpecError("--model applies to greenspan-N only")
    if args.model == "molecular":
        return _greenspan_molecular(args)
    return _simulate(args)


def _simulate(args) -> int:
    from .progress import heartbeat

    spec = _load(args.spec)
    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion to simulate")
    label = spec.label or args.spec
    params, initial = _values(args, spec, label)
    t_end = args.t_end if args.t_end is not None else spec.t_end
    if t_end is None:
        raise SpecError(f"{args.spec}: no end time: pass --t-end")
    if not initial:
        raise SpecError(f"{args.spec}: no initial conditions (the problem has no dynamics to simulate): pass "
                        f"--initial for each of {', '.join(_state_names(spec.system))}")
    options = merge_run_options(spec.options, _run_flags(args), label)
    if args.spec.lower().startswith("greenspan-"):
        return _greenspan_rigid(args, spec, float(t_end), params, initial, options)
    if not args.quiet:
        from .printing import format_equations

        if spec.problem is not None and hasattr(spec.problem, "title"):
            print(f"{spec.problem.id}: {spec.problem.title} ({spec.problem.source})")
        print(format_equations(spec.system))
        print()
    inputs = _input_values(spec, args, params)
    if inputs:
        options["inputs"] = inputs
    with heartbeat(f"integrating {label} to t = {float(t_end):g} with {options['method']}"), _partial_csv(args):
        sol = spec.system.simulate(float(t_end), initial, params, **options)
    print(f"{_printable(spec.label)}: {spec.system!r}")
    print(f"method {sol.method}, {sol.nfev} right-hand-side evaluations, {len(sol.t)} output points")
    tol = (f"step {options['step']:g}" if options["method"] in FIXED_STEP
           else f"rtol {options.get('rtol', 1e-9):g}, atol {options.get('atol', 1e-11):g}")
    friction = f", friction {options['friction']}" if "friction" in options else ""
    print(f"settings: {tol}, backend {options.get('backend', 'python')}{friction}")
    final = ", ".join(f"{n}={v:.10g}" for n, v in zip(sol.names, sol.y[-1]))
    print(f"state at t={sol.t[-1]:.6g}: {final}")
    label_e = "energy drift" if sol.work is None else "power-balance residual"
    print(f"{label_e} (relative): {sol.energy_error():.3e}")
    _outputs(args, spec, sol)
    return _verdict_status(sol)


#: the exit status of a run that reached its end but failed its own accuracy checks (lagrange.results.verdict)
INACCURATE_EXIT = 4


def _verdict_status(sol) -> int:
    """Print the run's verdict; the exit status: 0, or :data:`INACCURATE_EXIT` when a check failed."""
    if sol.verdict is None:
        return 0
    print(sol.verdict)
    return 0 if sol.verdict.ok else INACCURATE_EXIT


@contextmanager
def _partial_csv(args):
    """On Ctrl-C during the run: write the partial trajectory to ``--csv`` (when given) and say so in the
    interrupt's message, which :func:`main` prints on one line before exiting with 130."""
    try:
        yield
    except IntegrationInterrupted as exc:
        t_text = f" at t={exc.t:.6g}" if exc.t is not None else ""
        if args.csv and exc.partial is not None:
            exc.partial.to_csv(args.csv)
            exc.cli_message = f"interrupted{t_text}; the partial trajectory is written to {args.csv}"
        else:
            exc.cli_message = f"interrupted{t_text}"
        raise


def _outputs(args, spec, sol) -> None:
    if args.plot:
        sol.plot(args.plot, title=spec.system.name or spec.label)
        print(f"plot written to {args.plot}")
    if args.csv:
        sol.to_csv(args.csv)
        print(f"CSV written to {args.csv}")
    if args.animate:
        from .plot import animate
        from .progress import note

        note(f"writing the animation {args.animate}")
        animate(spec.system, sol, args.animate, title=spec.label)
        print(f"animation written to {args.animate}")


def _greenspan_report(label, t, vertices, fell, fall_time, extra: str, plot: str | None) -> None:
    from .discrete.greenspan import summarize

    sm = summarize(t, vertices, fell, fall_time)
    print(f"{label}: t = 0 … {sm.t[-1]:.6g}, {len(sm.t)} recorded states")
    print(f"  P1 (contact point) ends at ({sm.P1[-1, 0]:.6f}, {sm.P1[-1, 1]:.6f})")
    print(f"  Pbar (geometric centre) ends at ({sm.Pbar[-1, 0]:.6f}, {sm.Pbar[-1, 1]:.6f}, {sm.Pbar[-1, 2]:.6f})")
    print(f"  height of Pbar between {sm.zbar_range[0]:.6f} and {sm.zbar_range[1]:.6f}")
    for line in sm.report():
        print(f"  {line}")
    for line in extra.splitlines():
        print(f"  {line}")
    if plot:
        from .plot.trajectory import new_figure

        fig = new_figure(plot, figsize=(14, 4.2), layout="constrained")  # own Agg canvas: backend untouched
        ax = fig.subplots(1, 3)
        ax[0].plot(sm.P1[:, 0], sm.P1[:, 1], lw=0.7)
        ax[0].set_title("P1 in the plane")
        ax[0].set_aspect("equal")
        ax[1].plot(sm.Pbar[:, 0], sm.Pbar[:, 1], lw=0.7)
        ax[1].set_title("Pbar (x, y)")
        ax[1].set_aspect("equal")
        ax[2].plot(sm.t, sm.Pbar[:, 2], lw=0.7)
        ax[2].set_title("height of Pbar")
        ax[2].set_xlabel("t")
        fig.suptitle(label)
        fig.savefig(plot, dpi=120)
        print(f"plot written to {plot}")


def _greenspan_rigid(args, spec, t_end: float, params: dict, initial: dict, options: dict) -> int:
    from .discrete.greenspan import run_rigid
    from .progress import heartbeat, note

    _refuse(args, {"input": "--input: the top has no inputs"}, "Greenspan's top")
    if options["method"] in FIXED_STEP:
        raise SpecError(f"--method {options['method']}: the rigid Greenspan run stops when the top falls (an "
                        f"event), which the fixed-step methods do not support; use an adaptive method "
                        f"({', '.join(ADAPTIVE)})")
    options = {"rtol": 1e-10, "atol": 1e-12, **options}
    with heartbeat(f"integrating {spec.label} (rigid model) to t = {t_end:g} with {options['method']}"), \
            _partial_csv(args):
        rigid = run_rigid(spec.problem, t_end, params=params, initial=initial, **options)
    sol, verts, fall = rigid.trajectory, rigid.vertices, rigid.fall_time
    _greenspan_report(f"{spec.label} (rigid model, 5 DOF, {sol.method}, rtol {options['rtol']:g}, atol "
                      f"{options['atol']:g})", sol.t, verts, fall is not None, fall,
                      f"energy error (relative): {sol.energy_error():.3e}", args.plot)
    if args.csv:
        sol.to_csv(args.csv)
        print(f"CSV written to {args.csv}")
    if args.animate:
        from .plot import animate

        note(f"writing the animation {args.animate}")
        animate(spec.system, sol, args.animate, links=[(0, 1), (0, 2), (0, 3), (1, 2), (2, 3), (3, 1)],
                title=spec.label)
        print(f"animation written to {args.animate}")
    return _verdict_status(sol)


def _greenspan_example(spec: str):
    from .discrete.greenspan import EXAMPLES

    try:
        return EXAMPLES[int(spec.split("-", 1)[1])]
    except (ValueError, KeyError, IndexError):
        raise SpecError(f"{spec!r}: Greenspan's examples are greenspan-1 … greenspan-14") from None


def _greenspan_molecular(args) -> int:
    import time

    from .discrete.greenspan import A_PAIR, G, run_molecular
    from .progress import heartbeat

    why = "the molecular Greenspan model (a fixed-step discrete gradient, dt = --step, 12 Cartesian coordinates)"
    _refuse(args, {"rtol": "--rtol", "atol": "--atol", "backend": "--backend", "friction": "--friction",
                   "input": "--input: the top has no inputs",
                   "initial": "--initial: it starts from the paper's state; --model rigid takes --initial",
                   "animate": "--animate: the molecular model has no System to draw; --model rigid animates"},
            why)
    if args.method is not None and args.method.strip().lower() != "dg":
        raise SpecError(f"--method {args.method}: the molecular Greenspan model runs the discrete gradient (dg) "
                        "only; --model rigid takes the other methods")
    ex = _greenspan_example(args.spec)
    params = _kv(args.param, "param")
    check_names(params, _MOLECULAR_PARAMS, "param", f"greenspan-{ex.number} (molecular)")
    dt = args.step if args.step is not None else 1e-5
    t_end = args.t_end if args.t_end is not None else 110.0
    if dt > t_end:
        raise SpecError(f"--step {dt:g} is longer than the run (--t-end {t_end:g})")
    steps = max(1, int(round(t_end / dt)))
    t0 = time.perf_counter()
    with heartbeat(f"running {steps:,} discrete-gradient steps (the first run compiles the loop with numba, "
                   "one time)"):
        _, res = run_molecular(ex, t_end, dt=dt, A=params.get("A", A_PAIR), g=params.get("g", G),
                               record_every=max(1, round(steps / 2200)))  # ~2200 states, as the paper's run
    wall = time.perf_counter() - t0
    E0 = float(res.energy[0])
    _greenspan_report(f"greenspan-{ex.number} (molecular model, discrete gradient, dt = {dt:g})", res.t, res.x,
                      res.fell, res.fall_time,
                      f"{res.steps} steps in {wall:.1f} s; {res.solver_report()}\n"
                      f"energy drift max|E - E0| = {res.energy_drift:.3e} (relative {res.energy_drift / abs(E0):.2e}, "
                      f"{res.energy_drift_ulps:.1f} ulp of |E| = {abs(E0):.6g})",
                      args.plot)
    if args.csv:
        _molecular_csv(args.csv, res)
        print(f"CSV written to {args.csv}")
    return 0


def _molecular_csv(path: str, res) -> None:
    import csv

    cols = [f"{v}{i}_{c}" for v in ("x", "v") for i in range(1, 5) for c in "xyz"]
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["t", *cols])
        for k in range(len(res.t)):
            w.writerow([repr(float(res.t[k])), *(repr(float(u)) for u in res.x[k].ravel()),
                        *(repr(float(u)) for u in res.v[k].ravel())])


def _parse_over(items) -> dict:
    from .sweep import parse_range

    over = {}
    for item in items:
        if "=" not in item:
            raise SpecError(f"--over expects name=start:stop:num (or name=a,b,c), got {item!r}")
        name, rng = item.split("=", 1)
        over[name.strip()] = parse_range(rng.strip())
    return over


def _cmd_sweep(args) -> int:
    import time

    if args.resume and not args.store:
        raise SpecError("--resume needs --store (the store holds the runs to skip)")
    over = _parse_over(args.over)
    from .progress import active

    common = dict(random=args.random, seed=args.seed, workers=args.workers, store=args.store, resume=args.resume,
                  progress=active())
    t0 = time.perf_counter()
    table = _sweep_table(args, over, common)
    wall = time.perf_counter() - t0
    counts = table["status"].value_counts().to_dict()
    print(table.drop(columns=["run_id", "run_config"], errors="ignore").to_string(max_rows=40))
    print(f"{len(table)} runs: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) +
          f"; {wall:.1f} s ({len(table) / wall:.2f} runs/s)")
    if args.out:
        if args.out.lower().endswith(".parquet"):
            table.to_parquet(args.out, index=False)
        else:
            table.to_csv(args.out, index=False)
        print(f"table written to {args.out}")
    if "success" in table and bool(((table["status"] == "ok") & (table["success"] == False)).any()):  # noqa: E712
        print("some runs reached their end but failed their own accuracy checks (success False)")
        return INACCURATE_EXIT
    return 0


def _sweep_table(args, over: dict, common: dict):
    from .sweep import sweep

    if _is_greenspan(args.spec):
        from .sweep.greenspan_map import stability_task

        if args.spec.strip().lower() != "greenspan":
            raise SpecError(f"sweep {args.spec!r}: the Greenspan sweep is `lagrange sweep greenspan` (the stability "
                            "map of the rigid top over V and alpha_deg)")
        if set(over) - {"V", "alpha_deg"}:
            raise SpecError("greenspan sweeps take --over V=… and --over alpha_deg=… (spin and tilt in degrees)")
        _refuse(args, {"param": "--param", "initial": "--initial", "input": "--input"},
                "the Greenspan stability map (sweep V and alpha_deg with --over)")
        options = merge_run_options({"rtol": 1e-8, "atol": 1e-10}, _run_flags(args), "greenspan")
        if options["method"] in FIXED_STEP:
            raise SpecError(f"--method {options['method']}: the Greenspan map stops each run when the top falls "
                            "(an event); use an adaptive method")
        task = stability_task(args.t_end or 110.0, **{"backend": "python", **options})
        return sweep(task, over, **common)
    else:
        spec = _load(args.spec)
        if spec.system is None:
            raise SpecError(f"{args.spec}: this problem has no equations of motion to sweep")
        label = spec.label or args.spec
        t_end = args.t_end if args.t_end is not None else spec.t_end
        if t_end is None:
            raise SpecError(f"{args.spec}: no end time: pass --t-end")
        params, initial = _values(args, spec, label)
        options = merge_run_options(spec.options, _run_flags(args), label)
        backend = options.pop("backend", "python")
        swept_in_inputs = _input_parameters(spec) & set(over)  # parameters of input expressions
        inputs = _input_values(spec, args, {k: v for k, v in params.items() if k not in swept_in_inputs})
        params = {k: v for k, v in params.items() if k not in _input_parameters(spec)}
        if swept_in_inputs:
            from .sweep.task import InputExpressions

            options["setup"] = InputExpressions(inputs, sorted(swept_in_inputs))
        elif inputs:
            options["inputs"] = inputs
        return sweep(spec.system, over, t_end=float(t_end), initial=initial, params=params, backend=backend,
                      **common, **options)


def _cmd_bench(args) -> int:
    if args.hard:
        return _cmd_bench_hard(args)
    from .bench.problems import PROBLEMS
    from .bench.suite import run_suite

    unknown = [p for p in args.problem or [] if p not in PROBLEMS]
    if unknown:
        raise SpecError(f"--problem {', '.join(unknown)}: unknown benchmark problem (choose from "
                        f"{', '.join(PROBLEMS)})")
    run_suite(args.problem, quick=args.quick, out=args.out, heyoka=not args.no_heyoka)
    return 0


def _cmd_bench_hard(args) -> int:
    from .bench.hard import HARD_PROBLEMS, render_hard_markdown, run_hard_suite, write_hard_report

    unknown = [p for p in args.problem or [] if p not in HARD_PROBLEMS]
    if unknown:
        raise SpecError(f"--problem {', '.join(unknown)}: unknown hard case (choose from {', '.join(HARD_PROBLEMS)})")
    runs = run_hard_suite(args.problem, quick=args.quick, log=None if args.quiet else print)
    if args.out:
        paths = write_hard_report(runs, args.out, quick=args.quick)
        print(f"wrote {paths['md']} and {len(paths['png'])} PNG(s)")
    else:
        print(render_hard_markdown(runs, quick=args.quick))
    return 0


def _cmd_check(args) -> int:
    from .gauss.check import check_spec
    spec = _load(args.spec)
    params = _kv(args.param, "param")
    if spec.system is not None:
        check_names(params, [p.name for p in spec.system.parameters], "param", spec.label or args.spec)
    result = check_spec(spec, samples=args.samples, seed=args.seed, params=params)
    print(result)
    return 0 if result.ok or not result.applicable else 1


def _print_coverage(chapter: int | None) -> None:
    from .corpus import coverage

    rows = [r for r in coverage.chapter_coverage() if chapter is None or r.chapter == chapter]
    print("corpus coverage by chapter (misprints: problems recording a correction; [FULL]: the catalog's cases "
          "with a complete answer, see docs/coverage.md):")
    print(coverage.format_table(rows))


def _cmd_verify(args) -> int:
    from .corpus.registry import all_problems, get_problem
    from .progress import track

    if args.coverage:
        if args.ids:
            raise SpecError("verify --coverage prints the coverage of the whole corpus (or of --chapter); "
                            "give no problem ids with it")
        _print_coverage(args.chapter)
        return 0
    if args.ids:
        probs = [get_problem(i) for i in args.ids]
        if args.chapter is not None:
            probs = [p for p in probs if p.chapter == args.chapter]
    else:
        from .corpus import index

        if args.chapter is not None and not index.entries(args.chapter):
            raise SpecError(f"no problems in chapter {args.chapter}")
        if index.stale_modules():  # the index misses a changed module: load the whole corpus
            probs = [p for p in all_problems() if args.chapter is None or p.chapter == args.chapter]
        else:
            ids = [e["id"] for e in index.entries(args.chapter)]
            probs = [get_problem(i) for i in track(ids, desc="loading problems")]
    failed = 0
    for p in track(probs, desc="verifying"):
        for r in p.check():
            if not r.ok:
                failed += 1
                print(f"FAIL {p.id}: {r.answer}: {r.detail}")
            elif args.verbose:
                print(f"ok   {p.id}: {r.answer}")
    checks = sum(len(p.answers) for p in probs)
    print(f"{len(probs)} problems, {checks} answers checked, {failed} failed")
    if not args.ids:
        _print_coverage(args.chapter)
    return 1 if failed else 0


def _cmd_modes(args) -> int:
    spec = _load(args.spec)  # first: a mistyped id is answered from the index before sympy loads
    import sympy

    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion")
    system = spec.system
    eqs = system.derived
    operating = dict(getattr(spec.problem, "operating_point", None) or {})
    free = set().union(*[sympy.sympify(v).free_symbols for v in operating.values() if not isinstance(v, str)])
    own = sorted({p.name for p in eqs.parameters} | {s.name for s in free})  # e.g. a speed v of the operating point
    given = _kv(args.param, "param")
    valid = sorted(set(own) | _input_parameters(spec))
    unknown = sorted(set(given) - set(valid))
    if unknown:
        raise SpecError(f"--param: unknown parameter(s) {', '.join(unknown)} "
                        f"(parameters: {', '.join(valid) or 'none'})")
    params = {**{_name_of(k): v for k, v in spec.params.items()}, **given}
    input_names = [u.name for u in getattr(eqs, "inputs", ())]
    flags = _kv(args.input, "input")
    held = {**{_name_of(k): v for k, v in spec.inputs.items()}, **flags}
    wrong = sorted(set(held) - set(input_names))
    if wrong:
        raise SpecError(f"--input: unknown input(s) {', '.join(wrong)} (inputs: {', '.join(input_names) or 'none'})")
    about = {**operating, **_kv(args.about, "about")}
    missing = [n for n in own if n not in params]
    if missing:
        return _modes_symbolic(args, system, about, missing)
    from .analysis.modes_report import input_values_at_start, modes_report

    inputs = {**{n: 0.0 for n in input_names}, **input_values_at_start(held, params)}
    report = modes_report(system, {k: v for k, v in params.items() if k in own}, about, inputs=inputs,
                          force=args.force, near=_kv(args.near, "near") or None)
    if args.json:
        import json

        print(json.dumps(report.to_dict(), indent=2))
        return 0
    how = {n: "--input" if n in flags else "the spec's value at t = 0" if n in held else "no value given"
           for n in input_names}
    _print_report(report, args.digits, args.matrix, how)
    return 0


def _print_report(report, digits: int, matrix: bool, input_sources: dict) -> None:
    """The text form of a :class:`~lagrange.analysis.modes_report.ModesReport`."""
    from .analysis.operating_point import point_text
    from .model.coordinates import coordinate_name

    lin = report.linear
    print(lin.reference or f"linearized about {point_text(lin.about, digits)} (given)")
    moving = {coordinate_name(v.args[0]) + "_dot": x for v, x in lin.velocities.items() if float(x) != 0}
    if moving:
        print("reference velocities: " + ", ".join(f"{k} = {float(v):.{digits}g}" for k, v in moving.items()))
    for name, value in report.inputs.items():
        print(f"input {name} held at {value:.{digits}g} ({input_sources.get(name, 'given')}; --input {name}=VALUE "
              "to change)")
    if lin.is_constrained:
        speeds = ", ".join(coordinate_name(v.args[0]) + "_dot" for v in lin.speeds)
        print(f"constrained system, linearized on the constraint manifold: independent coordinates "
              f"({', '.join(map(coordinate_name, lin.coordinates))}), independent speeds ({speeds})")
        print("multipliers at the reference: " + ", ".join(f"{k} = {float(v):.{digits}g}"
                                                           for k, v in lin.multipliers.items()))
    check = f"max |q''| at the reference = {report.residual:.3g}"
    article = "a" if report.kind == "steady motion" else "an"
    print(f"{report.kind} check: {check}" if report.is_reference else
          f"warning: not {article} {report.kind} ({check}); linearized anyway (--force)")
    print()
    print(_modes_table(report, digits))
    print("stable (every real part <= 0)" if report.stable else "unstable (a root has a positive real part)")
    if matrix:
        print("\nstate matrix (x' = A x):")
        print(_table([[""] + list(report.state_labels)] + [[lab] + [f"{x:.{digits}g}" for x in row] for lab, row
                                                              in zip(report.state_labels, report.state_matrix)]))


def _modes_table(report, digits: int) -> str:
    import numpy as np

    def num(x: float) -> str:
        return "-" if x != x else "inf" if x == float("inf") else f"{x + 0.0:.{digits}g}"  # + 0.0: no "-0"

    def cpx(z: complex) -> str:
        if z.imag == 0:
            return num(z.real)
        return f"{num(z.real)} ± {num(abs(z.imag))}i"

    def amp(z: complex) -> str:
        if abs(z.imag) <= 1e-9 * max(1.0, abs(z)):
            return num(z.real)
        return f"{num(abs(z))}∠{num(float(np.degrees(np.angle(z))))}°"

    head = ["mode", "eigenvalue", "frequency", "damping ratio", "period"] + list(report.shape_coordinates)
    rows = [[str(k + 1), cpx(r.eigenvalue), num(r.frequency), num(r.damping_ratio), num(r.period)]
            + [amp(r.shape[c]) for c in report.shape_coordinates] for k, r in enumerate(report.rows)]
    note = ("(frequency ω = |Im λ|, damping ratio ζ = −Re λ/|λ|, period 2π/ω; the shape columns are each "
            "coordinate's amplitude, largest 1)")
    return _table([head] + rows) + "\n" + note


def _table(rows: list) -> str:
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows)


def _modes_symbolic(args, system, about: dict, missing: list) -> int:
    """Without numbers: Wells' symbolic a, b, c (and |a ω² − c| = 0) at the given point or the equilibrium."""
    import sympy

    from .analysis.modes_report import symbolic_residual
    from .analysis.operating_point import point_text
    from .analysis.small_oscillations import linearize
    from .printing import pretty

    eqs = system.derived
    if eqs.m and eqs.n > 4:  # the symbolic route would take long on a big constrained system
        raise SpecError(f"give --param values for {', '.join(missing)}: a constrained system with {eqs.n} "
                        "coordinates is linearized numerically")
    lin = linearize(system, about or None)
    print(lin.reference or f"linearized about {point_text(lin.about)}:  a s'' + b s' + c s = F")
    if eqs.m:
        _print_constrained(lin, pretty)
    else:
        bad = [nm for nm, X in (("a", lin.a), ("b", lin.b), ("c", lin.c)) if X.has(sympy.nan, sympy.zoo, sympy.oo)]
        if bad:
            raise SpecError(f"the equations are singular at {point_text(lin.about)} ({', '.join(bad)} not finite): "
                            "choose another point with --about")
        for label, mat in (("a", lin.a), ("b", lin.b), ("c", lin.c)):
            print(f"{label} =\n{pretty(mat)}")
        if lin.a.shape[0] <= 3 and all(v == 0 for v in lin.b) and lin.a.det() != 0:
            print(f"frequency equation |a w^2 - c| = 0:\n{pretty(sp_factor(lin.frequency_equation()))} = 0")
    residual = symbolic_residual(lin)
    if any(e != 0 for e in residual):
        if not args.force:
            raise SpecError(f"the reference state ({point_text(lin.about)}) is not an equilibrium: q'' (or F) = "
                            f"{residual} there; leave out --about to have the equilibrium found, give --param "
                            f"values for {', '.join(missing)} to have the equilibria near it listed, or pass --force")
        print(f"warning: not an equilibrium: q'' (or F) = {residual}; linearized anyway (--force)")
    print(f"(give --param values for {', '.join(missing)} to get numbers)")
    return 0


def _print_constrained(lin, pretty) -> None:
    from .model.coordinates import coordinate_name

    speeds = ", ".join(f"{coordinate_name(v.args[0])}_dot" for v in lin.speeds)
    print(f"constrained system, linearized on the constraint manifold: independent coordinates "
          f"({', '.join(coordinate_name(q) for q in lin.coordinates)}), independent speeds ({speeds})")
    print("multipliers at the reference:", ", ".join(f"{k} = {v}" for k, v in lin.multipliers.items()))
    if lin.a is not None:
        for label, mat in (("a", lin.a), ("b", lin.b), ("c", lin.c)):
            print(f"{label} =\n{pretty(mat)}")
    else:
        print(f"state matrix (x = independent coordinates, then speeds):\n{pretty(lin.A)}")


def sp_factor(e):
    from .simplification import factor

    return factor(e)


def _cmd_hamiltonian(args) -> int:
    from .analysis.hamilton import hamiltonian
    from .printing import pretty
    spec = _load(args.spec)
    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion")
    h = hamiltonian(spec.system)
    print(f"H =\n{pretty(h.H)}")
    for q, p, qd, pd in zip(h.q, h.p, h.qdot, h.pdot):
        print(f"\nd{q}/dt =\n{pretty(qd)}")
        print(f"d{p}/dt =\n{pretty(pd)}")
    return 0


def _positive(text: str) -> float:
    """argparse type: a positive finite number."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive finite number")
    return value


def _digits(text: str) -> int:
    """argparse type: significant digits, 1 to 17 (a double has no more)."""
    value = _count(1)(text)
    if value > 17:
        raise argparse.ArgumentTypeError(f"{text!r} is more than 17 (a double has about 16 significant digits)")
    return value


def _count(minimum: int):
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"{text!r} is less than {minimum}")
        return value

    return parse


def _method_help() -> str:
    from .integrate.registry import names

    return (f"integration method from the registry (case-insensitive; default: the spec's, else DOP853): adaptive "
            f"{', '.join(names(adaptive=True))}, or auto (chosen from the equations); fixed-step "
            f"{', '.join(names(adaptive=False))} (geometric, need --step). `lagrange methods` prints what each "
            "supports")


def _run_arguments(p: argparse.ArgumentParser) -> None:
    """The integration flags of simulate and sweep: default None, so the spec's values stand unless given."""
    p.add_argument("--t-end", type=_positive, help="end time (default: the spec's)")
    p.add_argument("--method", metavar="METHOD", help=_method_help())
    p.add_argument("--step", type=_positive, metavar="H",
                   help=f"step size of the fixed-step methods ({', '.join(FIXED_STEP)}; required by them, refused "
                        "by the adaptive ones); for greenspan-N --model molecular the time step (default 1e-5)")
    p.add_argument("--rtol", type=_positive, help="relative tolerance of the adaptive methods (default: the spec's, "
                   "else 1e-9)")
    p.add_argument("--atol", type=_positive, help="absolute tolerance (default: the spec's, else 1e-11)")
    p.add_argument("--backend", choices=BACKENDS, help="code generation: python (default), numba, reference or auto")
    p.add_argument("--friction", choices=["events", "regularize"], help="treatment of sign() switches (default "
                   "events)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="override a parameter value")
    p.add_argument("--initial", action="append", metavar="NAME=VALUE", help="override an initial value (x, x_dot)")
    p.add_argument("--input", action="append", metavar="NAME=VALUE", help="a constant value of an input")


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="lagrange",
        description="Derive Lagrange's equations the way Wells does, and simulate them.",
        epilog="Install: pip install lagrange-dynamics (the import name and this command are `lagrange`).",
    )
    ap.add_argument("--version", action="version", version=f"lagrange {__version__}")
    sub = ap.add_subparsers(dest="command", required=True)
    quiet = argparse.ArgumentParser(add_help=False)
    quiet.add_argument("--no-progress", action="store_true", help="no progress reports on stderr (they are shown "
                       "only when stderr is a terminal)")

    p = sub.add_parser("problems", help="list the worked problems of the corpus by chapter")
    p.add_argument("--chapter", type=int, help="only this chapter")
    p.set_defaults(func=_cmd_problems)

    spec_help = "a problem id (see `lagrange problems`), a Python file defining `system`, or a TOML spec"
    p = sub.add_parser("derive", parents=[quiet], help="print Lagrange's equations of a system")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--latex", action="store_true", help="print LaTeX instead of text")
    p.add_argument("--full", action="store_true", help="print every equation whole, however long (by default an "
                   "equation of more than 6,000 terms and factors is summarized in one line)")
    p.set_defaults(func=_cmd_derive)

    p = sub.add_parser("simulate", parents=[quiet], help="integrate the equations of motion",
                       description="Integrate the equations of motion. The spec's [simulate] values (method, "
                       "rtol, …) are the defaults; the flags given override them. The run checks its own "
                       "accuracy (power balance, constraint drift, for fixed-step methods a step-doubling error "
                       "estimate, for the Taylor method its local error) and prints the verdict.",
                       epilog="Exit status: 0 a run that passed its accuracy checks, 4 a run that reached its end "
                       "but failed them (the verdict names the check and what to try), 2 bad input, 3 internal "
                       "error, 130 interrupted.")
    p.add_argument("spec", nargs="?", help=spec_help + "; or greenspan-N (Greenspan's top, example N = 1 … 14)")
    p.add_argument("--list-methods", action="store_true", help="print the method registry (as `lagrange methods`) "
                   "and exit")
    p.add_argument("--plot", help="write a PNG plot to this path")
    p.add_argument("--csv", help="write the trajectory to this CSV path")
    p.add_argument("--animate", help="write an animation (.gif, or .mp4 with ffmpeg) to this path")
    _run_arguments(p)
    p.add_argument("-q", "--quiet", action="store_true", help="do not print the equations first; no progress")
    p.add_argument("--model", choices=["rigid", "molecular"], help="greenspan-N only: the model to run (molecular: "
                   "takes --t-end, --step, --param A=…/g=…, --plot, --csv)")
    p.set_defaults(func=_cmd_simulate)

    p = sub.add_parser("methods", help="the integration methods: family, order, what each supports")
    p.set_defaults(func=_cmd_methods)

    p = sub.add_parser("modes", help="linearize about an equilibrium: matrices, frequencies, mode shapes")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--about", action="append", metavar="q=VALUE",
                   help="reference coordinate values (default: the problem's operating point, else the "
                        "equilibrium found) and velocities (q_dot=VALUE, for a steady motion)")
    p.add_argument("--near", action="append", metavar="q=VALUE", help="without --about: start the equilibrium "
                   "search here (default: every coordinate 0)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter values for numbers")
    p.add_argument("--input", action="append", metavar="NAME=VALUE",
                   help="hold an input at this value (default: its spec value at t = 0, else 0)")
    p.add_argument("--digits", type=_digits, default=6, help="significant digits of the table, 1 to 17 (default 6)")
    p.add_argument("--json", action="store_true", help="print the report as JSON instead of the table")
    p.add_argument("--matrix", action="store_true", help="also print the state matrix, labelled by state")
    p.add_argument("--force", action="store_true", help="linearize even where the point is not an equilibrium")
    p.set_defaults(func=_cmd_modes)

    p = sub.add_parser("hamiltonian", parents=[quiet], help="print H and Hamilton's canonical equations")
    p.add_argument("spec", help=spec_help)
    p.set_defaults(func=_cmd_hamiltonian)

    p = sub.add_parser("sweep", parents=[quiet],
                       help="run a grid or random sample of parameters/initial values, tabulate results",
                       epilog="Exit status: 4 when a run reached its end but failed its own accuracy checks "
                       "(its success column is False), 2 bad input, 0 otherwise.")
    p.add_argument("spec", help=spec_help + "; or greenspan (the top's stability map over V and alpha_deg)")
    p.add_argument("--over", action="append", required=True, metavar="NAME=START:STOP:NUM",
                   help="a swept quantity (parameter, input, coordinate, q_dot) and its values (or NAME=a,b,c)")
    p.add_argument("--random", type=_count(1), metavar="N",
                   help="N Latin-hypercube points in the ranges instead of the grid")
    p.add_argument("--seed", type=int, default=0, help="seed of --random (default 0)")
    p.add_argument("--workers", type=_count(0), help="worker processes (default: CPU count; 0: in this process)")
    p.add_argument("--out", help="write the table to this .csv (or .parquet) path")
    p.add_argument("--store", help="append each finished run to this .csv/.parquet store as it completes")
    p.add_argument("--resume", action="store_true", help="with --store: skip the runs already stored")
    _run_arguments(p)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("bench", parents=[quiet],
                       help="work-precision benchmarks: error against time and evaluations, energy drift")
    p.add_argument("--problem", action="append", metavar="NAME",
                   help="double_pendulum, nlink, top, kepler, stiff, stick_slip or greenspan (default: all)")
    p.add_argument("--quick", action="store_true", help="short runs, two tolerances, python backend (a few minutes)")
    p.add_argument("--out", help="write workprecision.md, .json and one PNG per problem into this directory")
    p.add_argument("--no-heyoka", action="store_true", help="skip the heyoka.py comparison even if installed")
    p.add_argument("--hard", action="store_true",
                   help="the hard cases instead (squeezer, car_axis, double_pendulum, kepler, cone, stick_slip, "
                        "spherical_pole): every method, error, CPU, drift and each run's own verdict")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress reports")
    p.set_defaults(func=_cmd_bench)

    p = sub.add_parser("check", parents=[quiet],
                       help="compare Lagrange's accelerations with Gauss' principle at random states")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--samples", type=_count(1), default=5, help="number of random states (default 5)")
    p.add_argument("--seed", type=int, default=0, help="seed of the random states (default 0)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="override a parameter value")
    p.set_defaults(func=_cmd_check)

    p = sub.add_parser("verify", parents=[quiet], help="check corpus problems against the book's answers")
    p.add_argument("ids", nargs="*", help="problem ids (default: all)")
    p.add_argument("--chapter", type=int)
    p.add_argument("-v", "--verbose", action="store_true")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress reports")
    p.add_argument("--coverage", action="store_true",
                   help="only print the corpus coverage by chapter (printed after a check of all problems too)")
    p.set_defaults(func=_cmd_verify)
    return ap


def _silence_stdout() -> None:
    """After a closed pipe: point stdout at /dev/null so the interpreter's final flush cannot fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):  # pragma: no cover - stdout is not a real file
        pass


def _printable(value) -> str:
    from ._text import printable

    return printable(str(value), keep="\n")


def main(argv: list[str] | None = None) -> int:
    """Run the ``lagrange`` command; returns the exit status (0 ok, 1 a check failed, 2 bad input,
    3 internal error, 4 a simulation that failed its own accuracy checks, 130 interrupted by Ctrl-C, 141 the
    output pipe was closed)."""
    try:
        args = _parser().parse_args(argv)
        _check_outputs(args)
        with _progress(args):
            status = int(args.func(args) or 0)
        sys.stdout.flush()
        return status
    except BrokenPipeError:  # `lagrange simulate ex3.4 | head -2`: the reader is gone, stop quietly
        _silence_stdout()
        return 141
    except LagrangeError as exc:  # messages quote user strings: printed without their control characters
        print(f"lagrange: error: {_printable(exc)}", file=sys.stderr)
        return 2
    except OSError as exc:  # a file that cannot be read or written (checked up front where possible)
        print(f"lagrange: error: {_printable(exc)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:  # Ctrl-C: one line, exit 130 (simulate has written a partial --csv)
        print(f"lagrange: {getattr(exc, 'cli_message', 'interrupted')}", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - one line, never a traceback, unless debugging
        if os.environ.get("LAGRANGE_DEBUG"):
            raise
        print(f"lagrange: internal error: {type(exc).__name__}: {_printable(exc)} (set LAGRANGE_DEBUG=1 for details)",
              file=sys.stderr)
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
