"""Sweeps: throughput on 1 and 2 worker processes, a Dask LocalCluster against the local pool, the ensemble
integrator against per-member solve_ivp, and the stability map of Greenspan's top.

* Throughput: the same grid of Greenspan-top runs (rigid model, DOP853 rtol 1e-8, t = 110 or the fall)
  in this process, on a pool of 1 and of 2 worker processes (wall time of the whole ``lagrange.sweep``
  call: pool start, shipping the compiled model, runs).
* LocalCluster(n_workers=2, processes=True): the same grid, required to give the same table.
* Ensemble: k spring pendulums with random stiffness integrated by ``integrate_ensemble`` (numba
  ``rhs_many``) against a loop of ``solve_ivp`` on each (same method and tolerances: the same steps).
* Stability map: V × α grid of the top, which combinations fall within t = 110.

Writes ``benchmarks/results/sweep.md``, ``sweep_stability_map.csv`` and ``sweep_stability_map.png``. Run:
``python benchmarks/sweep.py`` (a few minutes on 2 cores) or ``--quick`` (a coarse map, about a minute).
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from pathlib import Path

import numpy as np
import pandas as pd
import sympy as sp
from scipy.integrate import solve_ivp

import lagrange as lg
from lagrange.sweep import integrate_ensemble
from lagrange.sweep.greenspan_map import stability_task

RESULTS = Path(__file__).parent / "results"


def _same(a: pd.DataFrame, b: pd.DataFrame) -> bool:
    try:
        pd.testing.assert_frame_equal(a.drop(columns=["wall_time"]), b.drop(columns=["wall_time"]))
        return True
    except AssertionError:
        return False


def throughput(task, over) -> tuple[list, bool, pd.DataFrame]:
    rows, tables = [], {}
    for label, kw in (("in this process (workers=0)", {"workers": 0}), ("process pool, 1 worker", {"workers": 1}),
                      ("process pool, 2 workers", {"workers": 2})):
        t0 = time.perf_counter()
        tables[label] = table = lg.sweep(task, over, progress=False, **kw)
        wall = time.perf_counter() - t0
        rows.append((label, len(table), wall, len(table) / wall, float(table["wall_time"].sum())))
        print(f"{label}: {len(table)} runs in {wall:.1f} s ({len(table) / wall:.2f} runs/s)", flush=True)
    same = all(_same(t, tables["process pool, 2 workers"]) for t in tables.values())
    return rows, same, tables["process pool, 2 workers"]


def on_cluster(task, over, local: pd.DataFrame) -> tuple[tuple, bool]:
    import distributed

    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None) as cl:
        with distributed.Client(cl) as client:
            t0 = time.perf_counter()
            table = lg.sweep(task, over, executor=client, progress=False)
            wall = time.perf_counter() - t0
    print(f"LocalCluster, 2 processes: {len(table)} runs in {wall:.1f} s; same table: {_same(table, local)}")
    return ("Dask LocalCluster, 2 worker processes", len(table), wall, len(table) / wall,
            float(table["wall_time"].sum())), _same(table, local)


def ensemble(k: int) -> dict:
    r, th = lg.coordinates("r theta")
    m, g, kk, r0 = lg.parameters("m g k r0")
    system = lg.System([r, th], bodies=[lg.Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                       V=-m * g * r * sp.cos(th) + kk * (r - r0) ** 2 / 2)
    model = system.compile({"m": 1, "g": 9.81, "k": 40, "r0": 1}, backend="numba")
    rng = np.random.default_rng(0)
    Y0 = np.column_stack([1 + 0.3 * rng.random(k), rng.random(k), np.zeros(k), rng.normal(size=k)])
    P = np.column_stack([np.full(k, 9.81), 10 + 90 * rng.random(k), np.ones(k), np.ones(k)])
    te = np.linspace(0, 10, 101)
    integrate_ensemble(model, 0.1, Y0[:2], P[:2])  # JIT / cache load of rhs_many
    t0 = time.perf_counter()
    res = integrate_ensemble(model, 10.0, Y0, P, t_eval=te, rtol=1e-9, atol=1e-11)
    t_ens = time.perf_counter() - t0
    t0 = time.perf_counter()
    err, same_nfev = 0.0, 0
    for i in range(k):
        alone = model.with_params(dict(zip(["g", "k", "m", "r0"], P[i])))
        sol = solve_ivp(alone.fun, (0, 10), Y0[i], method="DOP853", rtol=1e-9, atol=1e-11, t_eval=te)
        err = max(err, float(np.max(np.abs(sol.y.T - res.y[i]))))
        same_nfev += int(sol.nfev == res.nfev[i])
    t_loop = time.perf_counter() - t0
    print(f"ensemble of {k}: {t_ens:.2f} s vs solve_ivp loop {t_loop:.2f} s; max diff {err:.1e}")
    return dict(k=k, t_ens=t_ens, t_loop=t_loop, err=err, same_nfev=same_nfev, nfev=(int(res.nfev.min()),
                int(res.nfev.max())))


def plot_map(table: pd.DataFrame, path: Path, t_end: float) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ft = table.pivot(index="alpha_deg", columns="V", values="fall_time")
    fig, ax = plt.subplots(figsize=(7.5, 4.8), constrained_layout=True)
    V, A = ft.columns.to_numpy(), ft.index.to_numpy()
    mesh = ax.pcolormesh(V, A, np.log10(ft.to_numpy()), shading="nearest", cmap="viridis_r")
    stays = ~table.pivot(index="alpha_deg", columns="V", values="fell").to_numpy(dtype=bool)
    vv, aa = np.meshgrid(V, A)
    ax.plot(vv[stays], aa[stays], "s", ms=5, mfc="white", mec="0.4", ls="", label=f"does not fall by t = {t_end:g}")
    from lagrange.discrete.greenspan import EXAMPLES

    ex = [e for e in EXAMPLES.values() if e.V <= V.max() and e.masses == (1.0, 1.0, 1.0, 1.0)]
    ax.plot([e.V for e in ex], [e.alpha_deg for e in ex], "r*", ms=11, ls="", label="Greenspan's examples 1, 4, 7, 10")
    fig.colorbar(mesh, ax=ax, label="log10 fall time")
    ax.set_xlabel("spin speed V of P2, P3, P4")
    ax.set_ylabel("initial tilt α [deg]")
    ax.set_title("Greenspan's tetrahedral top (rigid model): which tops fall")
    ax.legend(loc="upper left", fontsize=8)
    fig.savefig(path, dpi=110)


def write(tp, same_local, cluster, same_cluster, ens, table, wall_map, args, grid_sub) -> None:
    fell = table[table["fell"]]
    lines = [
        "# Sweeps: throughput, Dask cluster, ensemble integrator, and a stability map", "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}. "
        "Re-run with `python benchmarks/sweep.py` (the machine was shared with other jobs when this was run:"
        " absolute times are indicative; the speed-up between 1 and 2 workers depends on it).", "",
        "## Throughput: Greenspan's top over a grid", "",
        f"Task: the rigid top (5 DOF, DOP853 rtol {args.rtol:g}) from spin V and tilt α until t = {args.t_end:g} "
        f"or the fall; grid V ∈ {grid_sub['V']}, α ∈ {grid_sub['alpha_deg']} "
        f"({len(grid_sub['V']) * len(grid_sub['alpha_deg'])} runs). Wall time of the whole `lagrange.sweep` call "
        "(starting the pool, shipping the compiled model by source, the runs); "
        "CPU is the sum of the runs' own times in the workers.", "",
        "| executor | runs | wall time | runs/s | Σ run times |", "|---|---|---|---|---|",
    ]
    for label, n, wall, rate, cpu in [*tp, cluster]:
        lines.append(f"| {label} | {n} | {wall:.2f} s | {rate:.2f} | {cpu:.2f} s |")
    lines += ["", f"Every executor gives the identical table (all columns but wall_time): local pools "
              f"{'yes' if same_local else 'NO'}, Dask LocalCluster against the local pool "
              f"{'yes' if same_cluster else 'NO'}.", "",
              "## Ensemble integrator", "",
              f"{ens['k']} spring pendulums (random stiffness 10–100), t ∈ [0, 10], DOP853 rtol 1e-9, numba backend: "
              f"`integrate_ensemble` {ens['t_ens']:.2f} s against a loop of `solve_ivp` {ens['t_loop']:.2f} s "
              f"(×{ens['t_loop'] / ens['t_ens']:.1f}). Each member keeps its own step size (nfev from "
              f"{ens['nfev'][0]} to {ens['nfev'][1]}); {ens['same_nfev']}/{ens['k']} members took exactly "
              f"solve_ivp's steps, largest difference of the outputs {ens['err']:.1e}.", "",
              "## Stability map", "",
              f"Grid V ∈ [{table['V'].min():g}, {table['V'].max():g}] ({table['V'].nunique()} values) × α ∈ "
              f"[{table['alpha_deg'].min():g}°, {table['alpha_deg'].max():g}°] ({table['alpha_deg'].nunique()} "
              f"values), {len(table)} runs on 2 workers in {wall_map:.1f} s; {len(fell)} fall within t = "
              f"{args.t_end:g}, all statuses: {table['status'].value_counts().to_dict()}. "
              "Table: `sweep_stability_map.csv`; plot: `sweep_stability_map.png`.", "",
              "Smallest spin that does not fall, per tilt:", "", "| α | V | falls below it at t ≤ |", "|---|---|---|"]
    for a, grp in table.groupby("alpha_deg"):
        stays = grp[~grp["fell"].astype(bool)]
        vmin = stays["V"].min() if len(stays) else float("nan")
        below = grp[grp["V"] < vmin]["fall_time"].max() if len(stays) else grp["fall_time"].max()
        lines.append(f"| {a:g}° | {vmin:g} | {below:.3g} |")
    (RESULTS / "sweep.md").write_text("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a coarse map and a smaller throughput grid")
    ap.add_argument("--t-end", type=float, default=110.0)
    ap.add_argument("--rtol", type=float, default=1e-8)
    args = ap.parse_args()
    task = stability_task(args.t_end, rtol=args.rtol, atol=args.rtol * 1e-2)
    sub = {"V": [1.0, 2.0, 3.0, 4.0], "alpha_deg": [15.0, 30.0, 45.0]}
    if args.quick:
        sub = {"V": [1.0, 4.0], "alpha_deg": [15.0, 45.0]}
    tp, same_local, local = throughput(task, sub)
    cluster, same_cluster = on_cluster(task, sub, local)
    ens = ensemble(50 if args.quick else 200)
    V = np.linspace(0.5, 6.0, 12 if args.quick else 23)
    A = np.linspace(5.0, 50.0, 4 if args.quick else 10)
    t0 = time.perf_counter()
    table = lg.sweep(task, {"V": V, "alpha_deg": A}, workers=2)
    wall_map = time.perf_counter() - t0
    RESULTS.mkdir(parents=True, exist_ok=True)
    table.to_csv(RESULTS / "sweep_stability_map.csv", index=False)
    plot_map(table, RESULTS / "sweep_stability_map.png", args.t_end)
    write(tp, same_local, cluster, same_cluster, ens, table, wall_map, args, sub)
    print((RESULTS / "sweep.md").read_text())


if __name__ == "__main__":
    main()
