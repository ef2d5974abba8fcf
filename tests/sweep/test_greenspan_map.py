"""The stability-map task of Greenspan's top against the direct rigid-model runs (independent fall events)."""

import math

import numpy as np
import pytest

import lagrange as lg
from lagrange.discrete import greenspan as gs
from lagrange.sweep.greenspan_map import stability_task


@pytest.mark.slow
def test_stability_task_agrees_with_run_rigid():
    task = stability_task(110.0, rtol=1e-10, atol=1e-12)
    table = lg.sweep(task, {"V": [1.0, 4.0], "alpha_deg": [15.0]}, workers=0, progress=False)
    fell10, not1 = table.iloc[0], table.iloc[1]
    _, sol, verts = gs.run_rigid(gs.EXAMPLES[10], 3.0)  # Greenspan's example 10: V = 1, α = 15°
    t_fall = min(float(e[0]) for e in sol.t_events if len(e))
    assert fell10["fell"] and math.isclose(fell10["fall_time"], t_fall, rel_tol=1e-8)
    zbar = verts.mean(axis=1)[:, 2]
    assert fell10["zbar_min"] <= zbar.min() + 1e-9  # sampled more finely and at the fall itself
    assert not not1["fell"] and math.isnan(not1["fall_time"]) and not1["t_final"] == 110.0
    assert not1["energy_error"] < 1e-8
    # the Pbar height formula (√6/4) R cos θ against the vertices of the direct run
    formula = gs.EDGE * np.sqrt(6) / 4 * np.cos(sol["theta"])
    assert np.allclose(formula, zbar, atol=1e-12)
