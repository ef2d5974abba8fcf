"""`lagrange derive ID` and `lagrange simulate ID` for every problem of the corpus (in-process, slow)."""

import pytest

from lagrange.cli import main
from lagrange.corpus import all_problems

#: problems tagged "slow" (the Whipple bicycle: ~30,000-operation equations) have dedicated tests of their own
#: (tests/problems/test_bicycle.py, `lagrange modes bicycle`); printing their full equations through `derive`
#: is not bounded yet (see the closing note of session 9), so they are left out of these corpus-wide loops
PROBLEMS = [p for p in all_problems() if "slow" not in p.tags]
DYNAMIC = [p for p in PROBLEMS if p.simulation is not None]


@pytest.mark.slow
@pytest.mark.parametrize("problem", PROBLEMS, ids=[p.id for p in PROBLEMS])
def test_derive_every_problem(problem, capsys):
    assert main(["derive", problem.id]) == 0
    out = capsys.readouterr().out
    assert problem.id in out


@pytest.mark.slow
@pytest.mark.parametrize("problem", DYNAMIC, ids=[p.id for p in DYNAMIC])
def test_simulate_every_dynamic_problem(problem, capsys):
    t_end = min(float(problem.simulation.t_end), 0.5)
    assert main(["simulate", problem.id, "--quiet", "--t-end", str(t_end)]) == 0
    out = capsys.readouterr().out
    assert "power-balance residual" in out or "energy drift" in out
