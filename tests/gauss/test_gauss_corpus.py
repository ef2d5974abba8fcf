"""Every corpus problem whose kinematics are particles or rigid bodies: Lagrange's accelerations agree with
Gauss' principle at random states, and the balance laws hold along a short run (issue #8).

The full sweep is slow (every problem is derived); a representative subset runs by default. Problems
that cannot be checked are allowed only for the stated reasons, and the singular ones are confirmed
singular in the engine too — nothing is skipped silently.
"""

from functools import cache

import numpy as np
import pytest

from lagrange.corpus import all_problems, get_problem
from lagrange.gauss.check import check_problem, sample_parameters

#: problems tagged "slow" (the Whipple bicycle) are checked by their own tests; Gauss' symbolic check of four
#: rolling rigid bodies is not bounded yet, so they are left out here
PROBLEMS = [p for p in all_problems() if p.system is not None and "slow" not in p.tags]

# particle (ex3.4), dry friction sign() (ex6.1), rotating axes (p3.6), superfluous coordinates with a
# multiplier (sec1.9-multipliers), free two-body (p2.16-multipliers), lamina with I_z only (ex8.5, signed
# pseudo-masses), Euler-angle disk in a turning frame (p8.11), rotating earth frame (eq14.16)
FAST = ["ex3.4", "ex6.1", "p3.6", "sec1.9-multipliers", "p2.16-multipliers", "ex8.5", "p8.11", "eq14.16",
        "ex6.14"]  # ex6.14: dry friction starting with q2' < 0 (the power balance caught a wrong initial sign)

ALLOWED_REASONS = ("T given directly", "singular at every sampled state", "rough constraint")


@cache
def _check(pid):
    return check_problem(get_problem(pid), samples=3, seed=0)


def _assert_checked(pid):
    res = _check(pid)
    if not res.applicable:
        assert res.reason.startswith(ALLOWED_REASONS), f"{pid}: {res.reason}"
        if res.reason.startswith("singular"):
            _assert_engine_singular(get_problem(pid))
        return
    assert res.agrees, str(res)
    assert res.diagnostics is not None
    assert res.diagnostics.ok(res.balance_tol) or res.diagnostics.power_residual is None, str(res)


def _assert_engine_singular(problem):
    """The engine refuses these states too: its mass matrix (M, or M + AᵀA with constraints) is singular, or
    indefinite for unphysical random inertia data (its LDLᵀ solve raises)."""
    from lagrange.errors import SingularMassMatrixError

    system = problem.system
    params = dict(problem.simulation.params) if problem.simulation else sample_parameters(system, problem.ranges)
    model = system.compile(params)
    rng = np.random.default_rng(0)
    n = model.n
    for _ in range(3):
        y = rng.uniform(0.15, 0.85, 2 * n)
        M, _ = model.mass_and_forcing(0.5, y)
        if model.m:
            A = model.constraint_functions.matrix(0.5, y[:n])
            M = M + A.T @ A
        s = np.linalg.svd(M, compute_uv=False)
        if s[-1] <= 1e-10 * s[0]:
            continue
        with pytest.raises(SingularMassMatrixError):
            model.fun(0.5, y)


@pytest.mark.parametrize("pid", FAST)
def test_representative_problems_agree(pid):
    res = _check(pid)
    assert res.applicable, res.reason
    _assert_checked(pid)


@pytest.mark.slow
@pytest.mark.parametrize("pid", [p.id for p in PROBLEMS])
def test_every_problem_agrees(pid):
    _assert_checked(pid)


@pytest.mark.slow
def test_sweep_counts():
    counts: dict = {}
    for p in PROBLEMS:
        res = _check(p.id)
        key = "applicable" if res.applicable else res.reason.split(":")[0]
        counts[key] = counts.get(key, 0) + 1
    print(counts)
    assert counts["applicable"] >= 260  # 268 when written
    assert sum(counts.values()) == len(PROBLEMS)
