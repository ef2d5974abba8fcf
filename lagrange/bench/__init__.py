"""Work-precision benchmarks (``lagrange bench``) and the horizon of validity of chaotic trajectories.

* :mod:`~lagrange.bench.problems` — the benchmark problems (System, parameters, initial state, truth);
* :mod:`~lagrange.bench.runner` — timing (median of repeats) and error measurement, one curve per method;
* :mod:`~lagrange.bench.longrun` — energy error against time over long runs;
* :mod:`~lagrange.bench.first_result` — time to first result, cold, in fresh processes;
* :mod:`~lagrange.bench.sympy_route`, :mod:`~lagrange.bench.heyoka_adapter` — the peers compared;
* :mod:`~lagrange.bench.report`, :mod:`~lagrange.bench.suite` — Markdown/JSON/PNG report;
* :mod:`~lagrange.bench.horizon` — :func:`validity_horizon` and the finite-time Lyapunov exponent;
* :mod:`~lagrange.bench.hard` — the hard cases (``lagrange bench --hard``): every method against an independent
  reference, with each run's own verdict and the runs that are silently wrong.
"""

from .horizon import ValidityHorizon, validity_horizon
from .problems import PROBLEMS, BenchProblem, get_problem
from .suite import run_suite

__all__ = ["PROBLEMS", "BenchProblem", "get_problem", "run_suite", "validity_horizon", "ValidityHorizon"]
