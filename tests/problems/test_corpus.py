"""The whole corpus against the book: every answer of every problem, and every default simulation."""

import numpy as np
import pytest

from lagrange.corpus import all_problems

PROBLEMS = all_problems()


def _cases(problems):
    """One case per problem; problems tagged "slow" (tens of seconds to derive, e.g. the bicycle) run with -m slow."""
    return [pytest.param(p, id=p.id, marks=[pytest.mark.slow] if "slow" in p.tags or p.id in HEAVY else [])
            for p in problems]


#: problems whose checks take over ~8 s in the default run (measured in CI): run with -m slow (issue #20)
HEAVY = {"ex13.7a", "p11.9", "p16.7", "ex11.2", "p7.13", "p11.6", "p17.10", "ex16.3", "p11.7", "ex11.5", "p11.10"}


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
