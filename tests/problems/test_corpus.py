"""The whole corpus against the book: every answer of every problem, and every default simulation."""

import numpy as np
import pytest

from lagrange.corpus import all_problems

PROBLEMS = all_problems()


def _cases(problems):
    """One case per problem; problems tagged "slow" (tens of seconds to derive, e.g. the bicycle) run with -m slow."""
    return [pytest.param(p, id=p.id, marks=[pytest.mark.slow] if "slow" in p.tags else []) for p in problems]


def test_corpus_is_substantial():
    assert len(PROBLEMS) >= 2
    ids = [p.id for p in PROBLEMS]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize("problem", _cases(PROBLEMS))
def test_book_answers(problem):
    assert problem.answers, f"{problem.id} states no book answer"
    failures = [f"{r.answer}: {r.detail}" for r in problem.check() if not r.ok]
    assert not failures, "\n".join(failures)


WITH_DYNAMICS = [p for p in PROBLEMS if p.simulation is not None]


@pytest.mark.parametrize("problem", _cases(WITH_DYNAMICS))
def test_default_simulation_runs_and_balances_energy(problem):
    sim = problem.simulation
    sol = problem.system.simulate(sim.t_end, sim.initial, sim.params, **dict(sim.options))
    assert sol.success
    assert np.all(np.isfinite(sol.y))
    # h - h0 - ∫ dh/dt is zero for a consistent model: a force counted twice or with the wrong sign fails
    assert sol.energy_error() < 1e-5, f"power balance residual {sol.energy_error():.2e}"
