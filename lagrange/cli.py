"""The ``lagrange`` command line: parses arguments and calls the library (no logic of its own).

Errors are one line on stderr and a non-zero exit (2 for bad input, 3 for an internal failure);
set ``LAGRANGE_DEBUG=1`` to see tracebacks.
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np

from . import __version__
from .errors import LagrangeError, SpecError

__all__ = ["main"]


def _kv(items, what) -> dict:
    out = {}
    for item in items or []:
        if "=" not in item:
            raise SpecError(f"--{what} expects name=value, got {item!r}")
        k, v = item.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            raise SpecError(f"--{what} {k}: {v!r} is not a number") from None
    return out


def _cmd_problems(args) -> int:
    from .corpus.registry import all_problems

    probs = [p for p in all_problems() if args.chapter is None or p.chapter == args.chapter]
    if not probs:
        print(f"no problems in chapter {args.chapter}")
        return 0
    chapter = None
    for p in probs:
        if p.chapter != chapter:
            chapter = p.chapter
            print(f"\nChapter {chapter}")
        dyn = "" if p.simulation is not None else "  [no dynamics]"
        print(f"  {p.id:<22} {p.title}{dyn}")
    if args.chapter is None:
        from .discrete.greenspan import EXAMPLES

        print("\nGreenspan's tetrahedral top (simulate with --model rigid|molecular)")
        for ex in EXAMPLES.values():
            extra = "" if ex.masses == (1.0, 1.0, 1.0, 1.0) else f", masses {ex.masses}"
            print(f"  greenspan-{ex.number:<12} V = {ex.V:g}, alpha = {ex.alpha_deg:g} deg{extra}")
    print(f"\n{len(probs)} problem(s)")
    return 0


def _cmd_derive(args) -> int:
    from .printing import format_equations, latex
    from .spec.loader import load_spec

    spec = load_spec(args.spec)
    system = spec.system
    if spec.problem is not None and hasattr(spec.problem, "title"):
        print(f"{spec.problem.id}: {spec.problem.title} ({spec.problem.source})")
    if system is None:
        print("this problem has no equations of motion (its answers are checked by `lagrange verify`)")
        return 0
    if args.latex:
        for eq in system.equations():
            print(latex(eq))
    else:
        print(format_equations(system))
    ign = system.ignorable_coordinates()
    if ign:
        from .printing import pretty

        print("\nignorable coordinates (conserved momenta):")
        for q, p in ign.items():
            print(f"  {q.func.__name__}: p = {pretty(p)}")
    return 0


def _cmd_simulate(args) -> int:
    from .spec.loader import load_spec

    if args.model is not None and not args.spec.lower().startswith("greenspan-"):
        raise SpecError("--model applies to greenspan-N only")
    if args.model == "molecular":
        return _greenspan_molecular(args)
    spec = load_spec(args.spec)
    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion to simulate")
    params = {**spec.params, **_kv(args.param, "param")}
    initial = {**spec.initial, **_kv(args.initial, "initial")}
    t_end = args.t_end if args.t_end is not None else spec.t_end
    if t_end is None:
        raise SpecError(f"{args.spec}: no end time: pass --t-end")
    if not initial:
        raise SpecError(f"{args.spec}: no initial conditions (the problem has no dynamics to simulate)")
    options = dict(spec.options)
    options.update(method=args.method, rtol=args.rtol, atol=args.atol, backend=args.backend)
    if args.spec.lower().startswith("greenspan-"):
        return _greenspan_rigid(args, spec, float(t_end))
    if args.friction:
        options["friction"] = args.friction
    if not args.quiet:
        from .printing import format_equations

        if spec.problem is not None and hasattr(spec.problem, "title"):
            print(f"{spec.problem.id}: {spec.problem.title} ({spec.problem.source})")
        print(format_equations(spec.system))
        print()
    sol = spec.system.simulate(float(t_end), initial, params, **options)
    print(f"{spec.label}: {spec.system!r}")
    print(f"method {sol.method}, {sol.nfev} right-hand-side evaluations, {len(sol.t)} output points")
    names = sol.names
    final = ", ".join(f"{n}={v:.10g}" for n, v in zip(names, sol.y[-1]))
    print(f"state at t={sol.t[-1]:.6g}: {final}")
    label = "energy drift" if sol.work is None else "power-balance residual"
    print(f"{label} (relative): {sol.energy_error():.3e}")
    if args.plot:
        sol.plot(args.plot, title=spec.label)
        print(f"plot written to {args.plot}")
    if args.csv:
        sol.to_csv(args.csv)
        print(f"CSV written to {args.csv}")
    if args.animate:
        from .plot import animate

        animate(spec.system, sol, args.animate, title=spec.label)
        print(f"animation written to {args.animate}")
    return 0


def _greenspan_report(label, t, vertices, fell, fall_time, extra: str, plot: str | None) -> None:
    from .discrete.greenspan import summarize

    sm = summarize(t, vertices, fell, fall_time)
    print(f"{label}: t = 0 … {sm.t[-1]:.6g}, {len(sm.t)} recorded states")
    print(f"  P1 (contact point) ends at ({sm.P1[-1, 0]:.6f}, {sm.P1[-1, 1]:.6f})")
    print(f"  Pbar (geometric centre) ends at ({sm.Pbar[-1, 0]:.6f}, {sm.Pbar[-1, 1]:.6f}, {sm.Pbar[-1, 2]:.6f})")
    print(f"  height of Pbar between {sm.zbar_range[0]:.6f} and {sm.zbar_range[1]:.6f}")
    print(f"  the top falls at t = {fall_time:.6g}" if fell else "  the top does not fall")
    print(f"  {extra}")
    if plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(1, 3, figsize=(14, 4.2), constrained_layout=True)
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


def _greenspan_rigid(args, spec, t_end: float) -> int:
    from .discrete.greenspan import run_rigid

    _, sol, verts = run_rigid(spec.problem, t_end, rtol=args.rtol, atol=args.atol, backend=args.backend)
    fall = [float(e[0]) for e in sol.t_events if len(e)]
    _greenspan_report(f"{spec.label} (rigid model, 5 DOF, {sol.method})", sol.t, verts, bool(fall),
                      min(fall) if fall else None, f"energy error (relative): {sol.energy_error():.3e}", args.plot)
    return 0


def _greenspan_molecular(args) -> int:
    import time

    from .discrete.greenspan import EXAMPLES, run_molecular

    try:
        ex = EXAMPLES[int(args.spec.split("-", 1)[1])]
    except (ValueError, KeyError):
        raise SpecError(f"{args.spec!r}: Greenspan's examples are greenspan-1 … greenspan-14") from None
    t_end = args.t_end if args.t_end is not None else 110.0
    t0 = time.perf_counter()
    model, res = run_molecular(ex, t_end)
    wall = time.perf_counter() - t0
    E = model.energy(res.x, res.v)
    _greenspan_report(f"greenspan-{ex.number} (molecular model, discrete gradient, dt = 1e-5)", res.t, res.x,
                      res.fell, res.fall_time,
                      f"{res.steps} steps in {wall:.1f} s; relative energy drift {np.ptp(E) / abs(E[0]):.2e}",
                      args.plot)
    return 0


def _cmd_sweep(args) -> int:
    import time

    from .sweep import parse_range, sweep

    over = {}
    for item in args.over:
        if "=" not in item:
            raise SpecError(f"--over expects name=start:stop:num (or name=a,b,c), got {item!r}")
        name, rng = item.split("=", 1)
        over[name.strip()] = parse_range(rng.strip())
    common = dict(random=args.random, seed=args.seed, workers=args.workers, store=args.store, resume=args.resume,
                  progress=not args.no_progress)
    t0 = time.perf_counter()
    if args.spec.lower().startswith("greenspan"):
        from .sweep.greenspan_map import stability_task

        if set(over) - {"V", "alpha_deg"}:
            raise SpecError("greenspan sweeps take --over V=… and --over alpha_deg=… (spin and tilt in degrees)")
        task = stability_task(args.t_end or 110.0, rtol=args.rtol, atol=args.atol, backend=args.backend)
        table = sweep(task, over, **common)
    else:
        from .spec.loader import load_spec

        spec = load_spec(args.spec)
        if spec.system is None:
            raise SpecError(f"{args.spec}: this problem has no equations of motion to sweep")
        t_end = args.t_end if args.t_end is not None else spec.t_end
        if t_end is None:
            raise SpecError(f"{args.spec}: no end time: pass --t-end")
        options = {**spec.options, "method": args.method, "rtol": args.rtol, "atol": args.atol}
        table = sweep(spec.system, over, t_end=float(t_end), initial={**spec.initial, **_kv(args.initial, "initial")},
                      params={**spec.params, **_kv(args.param, "param")}, backend=args.backend, **common, **options)
    wall = time.perf_counter() - t0
    counts = table["status"].value_counts().to_dict()
    print(table.drop(columns=["run_id"]).to_string(max_rows=40))
    print(f"{len(table)} runs: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) +
          f"; {wall:.1f} s ({len(table) / wall:.2f} runs/s)")
    if args.out:
        if args.out.lower().endswith(".parquet"):
            table.to_parquet(args.out, index=False)
        else:
            table.to_csv(args.out, index=False)
        print(f"table written to {args.out}")
    return 0


def _cmd_bench(args) -> int:
    from .bench.suite import run_suite

    run_suite(args.problem, quick=args.quick, out=args.out, heyoka=not args.no_heyoka)
    return 0


def _cmd_check(args) -> int:
    from .gauss.check import check_spec
    from .spec.loader import load_spec

    result = check_spec(load_spec(args.spec), samples=args.samples, seed=args.seed, params=_kv(args.param, "param"))
    print(result)
    return 0 if result.ok or not result.applicable else 1


def _cmd_verify(args) -> int:
    from .corpus.registry import all_problems, get_problem

    probs = [get_problem(i) for i in args.ids] if args.ids else list(all_problems())
    if args.chapter is not None:
        probs = [p for p in probs if p.chapter == args.chapter]
    failed = 0
    for p in probs:
        for r in p.check():
            if not r.ok:
                failed += 1
                print(f"FAIL {p.id}: {r.answer}: {r.detail}")
            elif args.verbose:
                print(f"ok   {p.id}: {r.answer}")
    checks = sum(len(p.answers) for p in probs)
    print(f"{len(probs)} problems, {checks} answers checked, {failed} failed")
    return 1 if failed else 0


def _cmd_modes(args) -> int:
    import numpy as np
    import sympy

    from .analysis.small_oscillations import characteristic_roots, linearize, normal_modes
    from .conventions import t as t_sym
    from .printing import pretty
    from .spec.loader import load_spec

    spec = load_spec(args.spec)
    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion")
    system = spec.system
    eqs = system.derived
    operating = dict(getattr(spec.problem, "operating_point", None) or {})
    free = set().union(*[sympy.sympify(v).free_symbols for v in operating.values() if not isinstance(v, str)])
    names = sorted({p.name for p in eqs.parameters} | {s.name for s in free})  # e.g. a speed v of the operating point
    given = _kv(args.param, "param")
    unknown = sorted(set(given) - set(names))
    if unknown:
        raise SpecError(f"--param: unknown parameter(s) {', '.join(unknown)} "
                        f"(parameters: {', '.join(names) or 'none'})")
    params = {**{getattr(k, "name", str(k)): v for k, v in spec.params.items()}, **given}
    about = {**operating, **_kv(args.about, "about")}
    numeric = all(n in params for n in names)
    constrained = bool(eqs.m)
    shown = ", ".join(f"{getattr(k, 'name', k)} = {v}" for k, v in about.items()) or "q = 0"
    if not constrained:
        lin = linearize(system, about)
        bad = [nm for nm, X in (("a", lin.a), ("b", lin.b), ("c", lin.c)) if X.has(sympy.nan, sympy.zoo, sympy.oo)]
        if bad:
            raise SpecError(f"the equations are singular at {shown} ({', '.join(bad)} not finite): "
                            "choose another point")
        print(f"linearized about {shown}:  a s'' + b s' + c s = F")
        for label, mat in (("a", lin.a), ("b", lin.b), ("c", lin.c)):
            print(f"{label} =\n{pretty(mat)}")
        if lin.a.shape[0] <= 3 and all(v == 0 for v in lin.b) and lin.a.det() != 0:
            print(f"frequency equation |a w^2 - c| = 0:\n{pretty(sp_factor(lin.frequency_equation()))} = 0")
    if not numeric:
        missing = [n for n in names if n not in params]
        if constrained and eqs.n > 4:  # the symbolic route would take long on a big constrained system
            raise SpecError(f"give --param values for {', '.join(missing)}: a constrained system with {eqs.n} "
                            "coordinates is linearized numerically")
        if constrained:
            lin = linearize(system, about)
            _print_constrained(lin, pretty)
        residual = lin.acceleration if lin.acceleration is not None else tuple(lin.forcing)
        residual = [sympy.simplify(sympy.sympify(e).subs(t_sym, 0)) for e in residual]
        if any(e != 0 for e in residual):
            if not args.force:
                raise SpecError(f"the reference state ({shown}) is not an equilibrium: q'' (or F) = {residual} there; "
                                "choose an equilibrium (see `lagrange.equilibria`) or pass --force")
            print(f"warning: not an equilibrium: q'' (or F) = {residual}; linearized anyway (--force)")
        print(f"(give --param values for {', '.join(missing)} to get numbers)")
        return 0
    lin = linearize(system, about, params=params)
    if constrained:
        _print_constrained(lin, pretty)
    A, _ = lin.numeric_state()
    acc = np.abs(np.asarray(lin.acceleration, dtype=float))
    residual = float(acc.max()) if acc.size else 0.0
    moving = any(float(v) != 0 for v in lin.velocities.values())
    kind = "a steady motion" if moving else "an equilibrium"
    when = " (at t = 0; the forcing depends on t)" if not eqs.is_autonomous else ""
    print(f"{kind[kind.index(' ') + 1:]} check: max |q''| at the reference = {residual:.3g}{when}")
    if residual > 1e-8 * (1.0 + float(np.max(np.abs(A)))):
        if not args.force:
            raise SpecError(f"the reference state ({shown}) is not {kind}: the accelerations there are "
                            f"{np.array2string(np.asarray(lin.acceleration), precision=4)}; choose {kind} "
                            "(see `lagrange.equilibria`) or pass --force to linearize there anyway")
        print(f"warning: not {kind}; linearized anyway (--force)")
    roots = characteristic_roots(lin)
    print("\neigenvalues of the state matrix (characteristic roots):", np.array2string(roots, precision=8))
    tol = 1e-6 * max(1.0, float(np.max(np.abs(roots)))) if roots.size else 0.0
    print("stable (all real parts <= 0)" if np.all(roots.real <= tol) else "unstable (a root has a positive real part)")
    if lin.a is None:
        print("(non-holonomic: no second-order form, so no normal modes)")
        return 0
    a, b, c = lin.numeric()
    try:
        modes = normal_modes(lin)
    except LagrangeError as exc:
        print(f"no normal modes: {exc}")
        return 0
    print("angular frequencies:", np.array2string(modes.omega, precision=8))
    print("periods:", np.array2string(modes.periods, precision=8))
    print("mode shapes (columns, normalized to a):\n", np.array2string(modes.shapes, precision=6))
    if constrained:
        labels = ", ".join(str(getattr(q, "name", q)) for q in eqs.q)
        print(f"mode shapes in all coordinates ({labels}):\n", np.array2string(modes.full_shapes, precision=6))
    if np.any(b != 0):
        print("(b is not zero: the damped/gyroscopic characteristic roots above govern the motion)")
    return 0


def _print_constrained(lin, pretty) -> None:
    from .model.coordinates import coordinate_name

    speeds = ", ".join(f"{coordinate_name(v.args[0])}_dot" for v in lin.speeds)
    print(f"constrained system, linearized on the constraint manifold: independent coordinates "
          f"({', '.join(coordinate_name(q) for q in lin.coordinates)}), independent speeds ({speeds})")
    print("multipliers at the reference:", ", ".join(f"{k} = {v}" for k, v in lin.multipliers.items()))
    if lin.a is not None:
        for label, mat in (("a", lin.a), ("b", lin.b), ("c", lin.c)):
            print(f"{label} =\n{pretty(mat) if lin.params is None else mat}")
    else:
        shown = pretty(lin.A) if lin.params is None else lin.A
        print(f"state matrix (x = independent coordinates, then speeds):\n{shown}")


def sp_factor(e):
    from .simplification import factor

    return factor(e)


def _cmd_hamiltonian(args) -> int:
    from .analysis.hamilton import hamiltonian
    from .printing import pretty
    from .spec.loader import load_spec

    spec = load_spec(args.spec)
    if spec.system is None:
        raise SpecError(f"{args.spec}: this problem has no equations of motion")
    h = hamiltonian(spec.system)
    print(f"H =\n{pretty(h.H)}")
    for q, p, qd, pd in zip(h.q, h.p, h.qdot, h.pdot):
        print(f"\nd{q}/dt =\n{pretty(qd)}")
        print(f"d{p}/dt =\n{pretty(pd)}")
    return 0


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="lagrange",
        description="Derive Lagrange's equations the way Wells does, and simulate them.",
    )
    ap.add_argument("--version", action="version", version=f"lagrange {__version__}")
    sub = ap.add_subparsers(dest="command", required=True)

    p = sub.add_parser("problems", help="list the worked problems of the corpus by chapter")
    p.add_argument("--chapter", type=int, help="only this chapter")
    p.set_defaults(func=_cmd_problems)

    spec_help = "a problem id (see `lagrange problems`), a Python file defining `system`, or a TOML spec"
    p = sub.add_parser("derive", help="print Lagrange's equations of a system")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--latex", action="store_true", help="print LaTeX instead of text")
    p.set_defaults(func=_cmd_derive)

    p = sub.add_parser("simulate", help="integrate the equations of motion")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--t-end", type=float, help="end time (default: the spec's)")
    p.add_argument("--plot", help="write a PNG plot to this path")
    p.add_argument("--csv", help="write the trajectory to this CSV path")
    p.add_argument("--animate", help="write an animation (.gif, or .mp4 with ffmpeg) to this path")
    p.add_argument("--method", default="DOP853", help="DOP853 (default), RK45, RK23, LSODA, Radau, BDF or auto")
    p.add_argument("--rtol", type=float, default=1e-9)
    p.add_argument("--atol", type=float, default=1e-11)
    p.add_argument("--backend", default="python", help="python (default), numba, reference or auto")
    p.add_argument("--friction", choices=["events", "regularize"], help="treatment of sign() switches")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="override a parameter value")
    p.add_argument("--initial", action="append", metavar="NAME=VALUE", help="override an initial value (x, x_dot)")
    p.add_argument("-q", "--quiet", action="store_true", help="do not print the equations first")
    p.add_argument("--model", choices=["rigid", "molecular"], help="greenspan-N only: the model to run")
    p.set_defaults(func=_cmd_simulate)

    p = sub.add_parser("modes", help="linearize about an equilibrium: matrices, frequencies, mode shapes")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--about", action="append", metavar="q=VALUE",
                   help="reference coordinate values (default: the problem's operating point, else 0) and velocities "
                        "(q_dot=VALUE, for a steady motion)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter values for numbers")
    p.add_argument("--force", action="store_true", help="linearize even where the point is not an equilibrium")
    p.set_defaults(func=_cmd_modes)

    p = sub.add_parser("hamiltonian", help="print H and Hamilton's canonical equations")
    p.add_argument("spec", help=spec_help)
    p.set_defaults(func=_cmd_hamiltonian)

    p = sub.add_parser("sweep", help="run a grid or random sample of parameters/initial values, tabulate results")
    p.add_argument("spec", help=spec_help + "; or greenspan (the top's stability map over V and alpha_deg)")
    p.add_argument("--over", action="append", required=True, metavar="NAME=START:STOP:NUM",
                   help="a swept quantity (parameter, coordinate, q_dot) and its values (or NAME=a,b,c)")
    p.add_argument("--random", type=int, metavar="N", help="N Latin-hypercube points in the ranges instead of the grid")
    p.add_argument("--seed", type=int, default=0, help="seed of --random (default 0)")
    p.add_argument("--workers", type=int, help="worker processes (default: CPU count; 0: in this process)")
    p.add_argument("--out", help="write the table to this .csv (or .parquet) path")
    p.add_argument("--store", help="append each finished run to this .csv/.parquet store as it completes")
    p.add_argument("--resume", action="store_true", help="with --store: skip the runs already stored")
    p.add_argument("--t-end", type=float, help="end time (default: the spec's)")
    p.add_argument("--method", default="DOP853")
    p.add_argument("--rtol", type=float, default=1e-9)
    p.add_argument("--atol", type=float, default=1e-11)
    p.add_argument("--backend", default="python", help="python (default), numba, reference or auto")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="override a parameter value")
    p.add_argument("--initial", action="append", metavar="NAME=VALUE", help="override an initial value (x, x_dot)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("bench", help="work-precision benchmarks: error against time and evaluations, energy drift")
    p.add_argument("--problem", action="append", metavar="NAME",
                   help="double_pendulum, nlink, top, kepler, stiff, stick_slip or greenspan (default: all)")
    p.add_argument("--quick", action="store_true", help="short runs, two tolerances, python backend (seconds)")
    p.add_argument("--out", help="write workprecision.md, .json and one PNG per problem into this directory")
    p.add_argument("--no-heyoka", action="store_true", help="skip the heyoka.py comparison even if installed")
    p.set_defaults(func=_cmd_bench)

    p = sub.add_parser("check", help="compare Lagrange's accelerations with Gauss' principle at random states")
    p.add_argument("spec", help=spec_help)
    p.add_argument("--samples", type=int, default=5, help="number of random states (default 5)")
    p.add_argument("--seed", type=int, default=0, help="seed of the random states (default 0)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="override a parameter value")
    p.set_defaults(func=_cmd_check)

    p = sub.add_parser("verify", help="check corpus problems against the book's answers")
    p.add_argument("ids", nargs="*", help="problem ids (default: all)")
    p.add_argument("--chapter", type=int)
    p.add_argument("-v", "--verbose", action="store_true")
    p.set_defaults(func=_cmd_verify)
    return ap


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except LagrangeError as exc:
        print(f"lagrange: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # pragma: no cover
        return 130
    except Exception as exc:  # noqa: BLE001 - one line, never a traceback, unless debugging
        if os.environ.get("LAGRANGE_DEBUG"):
            raise
        print(f"lagrange: internal error: {type(exc).__name__}: {exc} (set LAGRANGE_DEBUG=1 for details)",
              file=sys.stderr)
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
