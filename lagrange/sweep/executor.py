"""Running the points of a sweep on an executor, surviving dead workers.

Any :class:`concurrent.futures.Executor` works: a :class:`~concurrent.futures.ProcessPoolExecutor` (the
default, one process per core), a thread pool, ``distributed.Client.get_executor()`` or a
``distributed.Client`` itself (adapted with ``client.get_executor(pure=False)``), or ``workers=0`` to run
in this process. At most ``2 × workers`` runs are in flight at a time, so rows arrive (and are stored) as
they finish.

Worker death
    A worker process that dies (a crash in compiled code, ``os._exit``, the OOM killer) breaks a process
    pool: every run in flight then fails with :class:`~concurrent.futures.process.BrokenProcessPool`,
    whichever killed it. Those runs are *suspects*: each is run again alone in a fresh one-process pool, so
    the one that kills its worker again is reported with ``status = "died"`` and the others complete;
    the runs not yet started continue in a fresh pool. Dask retries a task whose worker died on other
    workers and finally raises ``KilledWorker`` — for every task that happened to share the dying worker,
    healthy ones included. So a ``KilledWorker`` run is a suspect too: it is run again alone in a local
    one-process pool, and only a run that kills that process as well is reported ``died``.

Released tasks
    Each worker process unpickles a sweep's task once and keeps it (:func:`~lagrange.sweep.task.execute`);
    it keeps at most :data:`~lagrange.sweep.task.KEEP_TASKS` of them, and at the end of a sweep on a Dask
    client the task is released on every worker (``client.run``).

Ctrl-C
    A KeyboardInterrupt while waiting stops the sweep at once: runs not started are cancelled, the
    processes of an own pool are terminated (their runs in flight are lost; those finished are stored),
    and the KeyboardInterrupt propagates.
"""

from __future__ import annotations

import math
import os
from collections import deque
from collections.abc import Callable, Mapping
from concurrent.futures import FIRST_COMPLETED, BrokenExecutor, Executor, ProcessPoolExecutor, wait
from typing import Any

from .task import execute, release_task

__all__ = ["run_points", "as_executor"]

Job = tuple[str, Mapping[str, float]]


def as_executor(executor: Any) -> tuple[Executor, int | None]:
    """A concurrent.futures Executor for ``executor`` (a dask Client is adapted) and its worker count if known."""
    if type(executor).__module__.split(".")[0] == "distributed" and hasattr(executor, "get_executor"):
        nthreads = executor.nthreads()
        return executor.get_executor(pure=False), max(1, sum(nthreads.values()))
    if not isinstance(executor, Executor):
        raise TypeError(f"executor must be a concurrent.futures.Executor or a distributed.Client, got "
                        f"{type(executor).__name__}")
    return executor, getattr(executor, "_max_workers", None)


def _failed(rid: str, status: str, message: str) -> dict[str, Any]:
    return {"run_id": rid, "status": status, "error": message, "wall_time": math.nan}


def _drive(ex: Executor, payload, token: str, pending: deque, window: int,
           on_row: Callable[[dict], None]) -> tuple[list[Job], bool]:
    """Submit from ``pending`` keeping ``window`` runs in flight until done or the pool breaks.

    Returns (suspects: runs lost to a broken pool, broken)."""
    inflight: dict = {}
    suspects: list[Job] = []
    broken = False
    while inflight or (pending and not broken):
        while pending and not broken and len(inflight) < window:
            job = pending.popleft()
            try:
                inflight[ex.submit(execute, payload, token, *job)] = job
            except BrokenExecutor:
                pending.appendleft(job)
                broken = True
        if not inflight:
            break
        done, _ = wait(inflight, return_when=FIRST_COMPLETED)
        for fut in done:
            rid, _point = job = inflight.pop(fut)
            try:
                row = fut.result()
            except BrokenExecutor:
                suspects.append(job)
                broken = True
                continue
            except Exception as exc:  # noqa: BLE001 - infrastructure failures (pickling) become rows
                if type(exc).__name__ == "KilledWorker":  # maybe only a neighbour of the crash: isolate it
                    suspects.append(job)
                    continue
                row = _failed(rid, "error", f"{type(exc).__name__}: {exc}")
            on_row(row)
    return suspects, broken


def _isolate(suspects: list[Job], payload, token: str, workers: int, on_row: Callable[[dict], None]) -> None:
    """Run each suspect alone in its own one-process pool (``workers`` at a time)."""
    for start in range(0, len(suspects), workers):
        batch = suspects[start:start + workers]
        pools = [ProcessPoolExecutor(max_workers=1) for _ in batch]
        try:
            futures = [pool.submit(execute, payload, token, *job) for pool, job in zip(pools, batch)]
            for (rid, _), fut in zip(batch, futures):
                try:
                    row = fut.result()
                except BrokenExecutor as exc:
                    row = _failed(rid, "died", f"the worker process died while running this point "
                                               f"(again when run alone): {type(exc).__name__}: {exc}")
                on_row(row)
        finally:
            for pool in pools:
                pool.shutdown(wait=True, cancel_futures=True)


def run_points(payload, token: str, jobs: list[Job], *, executor=None, workers: int | None = None,
               on_row: Callable[[dict], None]) -> None:
    """Run every ``(run_id, point)`` of ``jobs`` and call ``on_row(row)`` as each finishes (in this process).

    ``payload`` is the pickled task (or the task itself with ``workers=0``); ``executor`` None means an own
    process pool of ``workers`` processes (default: the CPU count). See the module docstring for the
    recovery from worker deaths.
    """
    if workers == 0:
        for job in jobs:
            on_row(execute(payload, token, *job))
        return
    if workers is not None and workers < 0:
        raise ValueError(f"workers must be >= 0, got {workers}")
    own = executor is None
    ex, known = (ProcessPoolExecutor(max_workers=workers or os.cpu_count()), None) if own else as_executor(executor)
    n_workers = workers or known or getattr(ex, "_max_workers", None) or os.cpu_count() or 1
    pending = deque(jobs)
    try:
        while True:
            suspects, broken = _drive(ex, payload, token, pending, 2 * n_workers, on_row)
            if broken:
                if own:
                    ex.shutdown(wait=False, cancel_futures=True)
                ex, own = ProcessPoolExecutor(max_workers=n_workers), True  # a fresh pool for the rest
            if suspects:
                _isolate(suspects, payload, token, n_workers, on_row)
            if not broken or not pending:
                return
    except KeyboardInterrupt:
        if own:
            _stop(ex)
            own = False
        raise
    finally:
        if own:
            ex.shutdown(wait=True, cancel_futures=True)
        _release(executor, token)


def _stop(ex: Executor) -> None:
    """Cancel what has not started and terminate the processes of a pool (Ctrl-C: do not wait for them)."""
    processes = list((getattr(ex, "_processes", None) or {}).values())
    ex.shutdown(wait=False, cancel_futures=True)
    for proc in processes:
        if proc.is_alive():
            proc.terminate()
    for proc in processes:
        proc.join(timeout=5)


def _release(executor: Any, token: str) -> None:
    """Release the sweep's unpickled task on every worker of a Dask client (no-op for other executors)."""
    client = getattr(executor, "_client", executor)  # a Client, or the executor of one
    if type(client).__module__.split(".")[0] == "distributed" and hasattr(client, "run"):
        try:
            client.run(release_task, token)
        except Exception:  # noqa: BLE001 - a cluster that is shutting down: nothing left to release
            pass
