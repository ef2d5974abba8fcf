"""``sweep``: run a system (or any task) over a grid or a random sample of points and tabulate the results."""

from __future__ import annotations

import sys
import uuid
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from ..errors import SweepError
from .executor import run_points
from .grid import grid_points, random_points, run_id
from .identity import check_point_names, reserved_columns, run_config
from .table import Store, require_pandas, to_frame
from .task import SimulationTask, dumps_task, state_name, state_names

__all__ = ["sweep", "Progress"]


class Progress:
    """A progress bar: tqdm when installed, else a ``done/total`` counter on stderr (nothing when off)."""

    def __init__(self, total: int, enabled: bool, desc: str = "sweep"):
        self.total, self.done, self.enabled = total, 0, enabled and total > 0
        self._bar = None
        if self.enabled:
            try:
                from tqdm import tqdm

                self._bar = tqdm(total=total, desc=desc, unit="run", file=sys.stderr)
            except ImportError:
                pass

    def update(self, status: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        if self._bar is not None:
            self._bar.update(1)
        else:
            end = "\n" if self.done == self.total else ""
            print(f"\r{self.done}/{self.total} runs", end=end, file=sys.stderr, flush=True)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()


def sweep(system, over: Mapping[str, Sequence[float] | str], *, t_end: float | None = None,
          initial: Mapping | None = None, params: Mapping | None = None, random: int | None = None,
          seed: int | None = 0, summaries: Sequence[Callable] = (), setup: Callable | None = None,
          events: Callable | None = None, backend: str = "python", executor: Any = None,
          workers: int | None = None, store: str | None = None, resume: bool = False,
          progress: bool = True, inputs: Mapping | None = None, **options):
    """Run ``system`` at every point of a grid (or a random sample) and return a tidy table, one row per run.

    Parameters
    ----------
    system : System, or any picklable callable ``task(point) -> {column: scalar}``
    over : ``{name: values}`` — values a sequence or ``"start:stop:num"``; names are parameters, inputs, coordinates
        or velocities (``"theta_dot"``), or anything ``setup`` understands; with a System, keys may also be the
        objects (``theta``, ``theta.diff(t)``, sympy's ``dynamicsymbols``, parameter symbols), read by name
    t_end, initial, params : the base run (the point's values override them); t_end is required for a System
    inputs : the base values of the system's inputs (:mod:`lagrange.model.inputs`; any form ``simulate`` takes);
        an ``over`` name that is an input sweeps its constant value; ``setup`` may return input values too (a
        parameter of an input's function), see :class:`~lagrange.sweep.task.SimulationTask`
    random : None for the full grid (every combination); N for N points of a Latin hypercube over the box
        [min, max] of each name's values (``seed`` makes it reproducible)
    summaries : functions of the :class:`~lagrange.results.trajectory.Trajectory` giving extra columns (a
        scalar, a dict of scalars or a 1-D array); the defaults are success, nfev, t_final, the final state
        ``final_<name>`` and energy_error (the relative power-balance residual)
    setup, events : see :class:`~lagrange.sweep.task.SimulationTask`
    backend : code generation backend of the model (compiled once here, shipped to the workers by source)
    executor : None (a process pool of ``workers`` processes, default the CPU count), any
        ``concurrent.futures.Executor``, or a ``distributed.Client`` (Dask cluster)
    workers : process count of the default pool; 0 runs everything in this process
    store : ``path.csv`` or ``path.parquet`` — each finished row is written as it completes
    resume : with ``store``: skip the runs already stored and compute only the rest. A stored row is reused
        only when its run id (the point) *and* its ``run_config`` (everything else that defines the run: the
        system's equations, base values, t_end, options, backend, functions; :mod:`lagrange.sweep.identity`)
        match; rows of another configuration are computed again (and replaced in the store)
    progress : show a progress bar (tqdm when installed, else a counter on stderr)
    options : further keyword arguments of :func:`lagrange.integrate.run.simulate` (method, rtol, atol, …)

    Returns
    -------
    pandas.DataFrame
        Columns ``run_id`` (a stable hash of the point), the point's names, ``status`` (``ok``, ``error``: the
        run raised, ``died``: its worker process died), ``error`` (the message), ``run_config`` (the key of
        the configuration), the results, ``wall_time``; rows in the order of the points. A failing run never
        stops the others. Swept names that are reserved columns are refused; a result column that would
        overwrite one (or a swept value) makes that run an ``error`` (:mod:`lagrange.sweep.identity`).
        Ctrl-C stops the sweep (KeyboardInterrupt) within about a second; the rows finished so far are in
        the store, and ``resume=True`` continues.

    Raises
    ------
    SweepError
        pandas missing (names the ``sweep`` extra), unknown names in ``over``, a swept name that is a reserved
        column, an unpicklable task, an existing store without ``resume=True``.

    Examples
    --------
    >>> import lagrange as lg
    >>> x = lg.coordinates("x"); k = lg.parameters("k")
    >>> osc = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2)
    >>> table = lg.sweep(osc, {"k": [1.0, 4.0]}, t_end=3.141592653589793, initial={"x": 1, "x_dot": 0},
    ...                  workers=0, progress=False)
    >>> table[["k", "status"]].values.tolist(), [round(v, 6) for v in table["final_x"]]
    ([[1.0, 'ok'], [4.0, 'ok']], [-1.0, 1.0])
    """
    require_pandas()
    if hasattr(system, "derived") and isinstance(over, Mapping):  # coordinates, velocities, symbols by object
        over = {state_name(system, k): v for k, v in over.items()}
    points = random_points(over, random, seed=seed) if random is not None else grid_points(over)
    names = list(points[0])
    if callable(system) and not hasattr(system, "derived"):
        if options or summaries or setup or events or initial or params or inputs:
            raise SweepError("a task callable takes only the points: simulate options, summaries, setup, "
                             "events, initial and params apply to a System")
        task = system
    else:
        if t_end is None:
            raise SweepError("sweeping a System needs t_end (and initial values, unless `over` or setup gives "
                             "them all)")
        task = SimulationTask(system, t_end, initial or {}, params, options=options, summaries=summaries,
                              setup=setup, events=events, backend=backend, first_point=points[0], inputs=inputs)
        task.check_point(points[0])
    reserved = reserved_columns(task, state_names(task.system) if isinstance(task, SimulationTask) else ())
    check_point_names(names, reserved)
    config = run_config(task)
    ids = [run_id(p) for p in points]
    if len(set(ids)) != len(ids):
        raise SweepError("the sweep has repeated points (equal values in `over`): every point must be distinct")
    box = Store(store, resume=resume) if store is not None else None
    if resume and box is None:
        raise SweepError("resume=True needs a store (store='path.csv' or 'path.parquet')")
    done = box.finished(config) if box is not None else set()
    todo = [(rid, p) for rid, p in zip(ids, points) if rid not in done]
    payload = task if workers == 0 else dumps_task(task)
    rows = {r["run_id"]: r for r in (box.rows() if box is not None else []) if r["run_id"] in done}
    bar = Progress(len(todo), progress)
    by_id = dict(zip(ids, points))

    def on_row(row: dict) -> None:
        row = {"run_id": row["run_id"], "run_config": config, **by_id[row["run_id"]],
               **{k: v for k, v in row.items() if k != "run_id"}}
        rows[row["run_id"]] = row
        if box is not None:
            box.append(row)
        bar.update(row["status"])

    try:
        run_points(payload, uuid.uuid4().hex, todo, executor=executor, workers=workers, on_row=on_row)
    finally:
        bar.close()
    return to_frame(rows.values(), names, order=ids)
