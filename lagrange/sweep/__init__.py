"""Ensembles and parameter sweeps: many runs of one model, on this machine or a Dask cluster.

* :func:`sweep` — a grid or random sample of parameters and initial values → a tidy pandas table of per-run
  results (any ``concurrent.futures`` executor or a ``distributed.Client``; failures reported per run;
  resumable from a store). Needs the ``sweep`` extra (``pip install "lagrange-dynamics[sweep]"``).
* :func:`integrate_ensemble` — many initial states / parameter sets integrated together in one process,
  each member with its own step-size control, the stages evaluated for all members at once by
  :meth:`NumericModel.rhs_many <lagrange.codegen.numeric.NumericModel.rhs_many>`.

``lagrange.sweep`` (the attribute of the top-level package) is the function; import the rest from here:
``from lagrange.sweep import integrate_ensemble, grid_points``.
"""

from .driver import sweep
from .ensemble import EnsembleResult, integrate_ensemble
from .grid import grid_points, parse_range, random_points, run_id
from .task import SimulationTask

__all__ = ["sweep", "integrate_ensemble", "EnsembleResult", "grid_points", "random_points", "parse_range",
           "run_id", "SimulationTask"]
