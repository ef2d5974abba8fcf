r"""Energy error against time over long runs of conservative problems.

For each method one run over ``problem.long_t_end`` recording about ``n_points`` states; the relative
energy error :math:`|E(t) − E(0)|/|E(0)|` (E = T + V, the Jacobi integral of these autonomous systems).
The symplectic methods (implicit midpoint, Gauss–Legendre, Störmer–Verlet) keep it bounded; the discrete
gradient keeps it at the Newton tolerance; adaptive explicit methods drift (roughly linearly in t).
"""

from __future__ import annotations

import time

import numpy as np

from ..errors import LagrangeError
from .common import EnergyRun, _numba_ok, initial_vector
from .problems import BenchProblem

__all__ = ["energy_runs"]


def _fixed_energy(problem: BenchProblem, system, model, method: str, h: float, n_points: int,
                  loop: str) -> EnergyRun:
    kw = dict(method=method, step=h, model=model, loop=loop)
    if loop == "compiled":  # load or JIT-compile the pieces and the kernel, untimed
        system.simulate((0.0, h), problem.initial, problem.params, n_points=2, **kw)
    t0 = time.perf_counter()
    sol = system.simulate((0.0, problem.long_t_end), problem.initial, problem.params, n_points=n_points + 1, **kw)
    wall = time.perf_counter() - t0
    label = f"{method}{' compiled loop' if loop == 'compiled' else ''} h={h:g}"
    return EnergyRun(label, sol.t, _relative(model, sol.t, sol.y), wall)


def _relative(model, t, Y) -> np.ndarray:
    E = model.diagnostics(t, Y)["energy"]
    return np.abs(E - E[0]) / abs(E[0])


def _simulate_energy(problem, system, model, label, n_points, **kw) -> EnergyRun:
    times = np.linspace(0.0, problem.long_t_end, n_points + 1)
    t0 = time.perf_counter()
    sol = system.simulate((0.0, problem.long_t_end), problem.initial, problem.params, model=model, t_eval=times,
                          **kw)
    wall = time.perf_counter() - t0
    return EnergyRun(label, sol.t, _relative(model, sol.t, sol.y), wall)


def _heyoka_energy(problem, system, model, n_points) -> EnergyRun:
    from .heyoka_adapter import heyoka_model

    hm = heyoka_model(system, problem.params)
    y0 = initial_vector(problem, system)
    ta, _ = hm.integrator(y0, 2.0**-52)
    times = np.linspace(0.0, problem.long_t_end, n_points + 1)
    t0 = time.perf_counter()
    Y, _ = hm.propagate(ta, y0, times)
    wall = time.perf_counter() - t0
    return EnergyRun("heyoka (tol = machine ε)", times, _relative(model, times, Y), wall)


def energy_runs(problem: BenchProblem, system, *, quick: bool = False, heyoka: bool = True,
                n_points: int = 400) -> tuple[list, list]:
    """Long runs of ``problem`` (conservative, with ``long_t_end``): ``(runs, notes)``.

    Methods: the geometric fixed-step methods at ``problem.long_steps[0]`` (implicit midpoint, GL4, discrete
    gradient, Störmer–Verlet when separable; GL4 only when ``quick``), stepped in Python and, with numba, by
    the compiled loop, DOP853 (numba backend with scipy's
    loop at rtol 1e-8 and 1e-10, and the compiled loop at 1e-8; python backend at 1e-8 when ``quick``) and
    heyoka at machine precision.
    """
    if not (problem.conservative and problem.geometric and problem.long_t_end):
        return [], []
    backend = "numba" if _numba_ok() and not quick else "python"
    model = system.compile(problem.params, backend=backend)
    scipy_loop = {"loop": "scipy"} if backend == "numba" else {}
    runs, notes = [], []
    fixed = ["gl4"] if quick else ["midpoint", "gl4", "dg"] + (["verlet"] if problem.separable else [])
    for loop in ("scipy", "compiled") if backend == "numba" else ("scipy",):
        for m in fixed:
            runs.append(_fixed_energy(problem, system, model, m, problem.long_steps[0], n_points, loop))
    for tol in (1e-8,) if quick else (1e-8, 1e-10):
        runs.append(_simulate_energy(problem, system, model, f"DOP853 {backend} rtol {tol:g}", n_points,
                                     method="DOP853", rtol=tol, atol=tol, backend=backend, **scipy_loop))
    if backend == "numba":
        try:
            runs.append(_simulate_energy(problem, system, model, "DOP853 numba compiled loop rtol 1e-8", n_points,
                                         method="DOP853", rtol=1e-8, atol=1e-8, backend=backend, loop="compiled"))
        except TypeError as exc:
            notes.append(f"compiled loop unavailable: {exc}")
    if heyoka:
        try:
            runs.append(_heyoka_energy(problem, system, model, n_points))
        except (LagrangeError, ImportError) as exc:
            notes.append(f"heyoka skipped: {exc}")
    return runs, notes
