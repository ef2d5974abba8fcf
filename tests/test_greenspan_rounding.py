"""Greenspan's molecular top at the rounding floor: energy per step, translation invariance, the fixed centre,
the fixed-point solver and its Newton fallback, the fall time and the drift of P1 (issue #21, item 6).

Bounds come from the scheme: it conserves the energy exactly in exact arithmetic, and the loop rounds only
velocities (relative eps of |v|) and positions relative to the centre of mass (eps of the body's size), so
each step may move the energy by about eps·(T + |F|·R) ≈ 1e-14, far below eps·|E| ≈ 2.5e-10 (|E| ≈ 1.1e6 is
dominated by the pair potential). Recovering velocities as 2(x₁ − x₀)/dt − v₀, as before, costs
eps·|x|/dt ≈ 2e-11 in v, i.e. about 3·eps·|E| per step at the origin and 300·eps·|E| a distance 100 away;
the bound used below, 0.05·eps·|E| per step, separates the two by two orders of magnitude and more.
"""

import numpy as np
import pytest
import sympy as sp

from lagrange.discrete import greenspan as gs
from lagrange.discrete.pair_dg import PairSystem
from lagrange.errors import InitialConditionError, IntegrationError, LagrangeError

EPS = np.finfo(float).eps
SHIFT = np.array([100.0, -100.0, 0.0])


@pytest.fixture
def top():  # function scope: built inside the session's isolated cache (tests/conftest.py), compiled once
    ex = gs.EXAMPLES[1]
    return gs.molecular_model(ex.masses), *gs.initial_vertices(ex)


def _centre(res, masses):
    return np.einsum("i,kic->kc", masses, res.x) / masses.sum()


@pytest.mark.parametrize("offset", [np.zeros(3), SHIFT], ids=["origin", "translated by 100"])
def test_energy_per_step_at_the_rounding_floor(top, offset):
    model, x0, v0 = top
    res = model.integrate(x0 + offset, v0, dt=1e-5, steps=2000, record_every=1)
    E = model._energy(res.x - offset, res.v)  # extended precision: the energy of the states themselves
    scale = EPS * abs(float(E[0]))
    assert float(np.max(np.abs(np.diff(E)))) <= 0.05 * scale  # every step
    assert float(np.max(np.abs(E - E[0]))) <= 0.05 * scale  # and no drift over the run
    assert res.energy_drift <= 0.05 * scale and res.energy_drift_ulps < 0.05  # what the result reports


@pytest.mark.slow  # 31 s: in the slow run, which CI runs too
def test_translation_changes_nothing_and_the_centre_stays_fixed(top):
    """The same run a distance 100 from the origin follows the same trajectory relative to its centre of mass
    (to the rounding of the translated initial state), the horizontal centre of mass of the homogeneous top
    (zero horizontal momentum) stays fixed to 1e-12 in both runs, and the tip stays exactly on the plane."""
    model, x0, v0 = top
    assert np.array_equal(v0.sum(axis=0)[:2], [0.0, 0.0])  # the paper's spin has no horizontal momentum
    a = model.integrate(x0, v0, dt=1e-5, steps=20_000, record_every=100)
    b = model.integrate(x0 + SHIFT, v0, dt=1e-5, steps=20_000, record_every=100)
    ca, cb = _centre(a, model.masses), _centre(b, model.masses)
    assert np.max(np.abs(ca[:, :2] - ca[0, :2])) < 1e-12
    assert np.max(np.abs(cb[:, :2] - cb[0, :2])) < 1e-12
    assert np.max(np.abs((a.x - ca[:, None]) - (b.x - cb[:, None]))) < 1e-12
    assert np.max(np.abs(a.v - b.v)) < 1e-12 * 2600  # × the stiffest frequency, √(4k/m) ≈ 2600
    assert abs(a.energy_drift - b.energy_drift) <= 0.05 * EPS * abs(float(a.energy[0]))
    assert np.all(a.x[:, 0, 2] == 0.0) and np.all(b.x[:, 0, 2] == 0.0)
    assert a.newton_steps == 0 and a.fixed_point_iterations >= 20_000


def test_non_homogeneous_centre_moves_with_its_momentum():
    """Example 13 (m2 = 1.005, m3 = 0.95): Σ m v ≠ 0, so the centre of mass moves uniformly at Σ m v / Σ m
    (horizontal momentum is conserved: the plane and gravity act vertically)."""
    ex = gs.EXAMPLES[13]
    run = gs.run_molecular(ex, 0.2, record_every=1000, offset=SHIFT)
    res, m = run.result, run.model.masses
    c = _centre(res, m)
    _, v0 = gs.initial_vertices(ex)
    u = (m @ v0)[:2] / m.sum()
    assert np.linalg.norm(u) > 1e-2
    assert np.max(np.abs(c[:, :2] - (c[0, :2] + res.t[:, None] * u))) < 1e-12


def test_fixed_point_newton_fallback_and_forced_solvers(top):
    model, x0, v0 = top
    fp = model.integrate(x0, v0, dt=1e-5, steps=5000, record_every=5000)
    assert fp.solver == "fixed point" and fp.newton_steps == 0
    assert 5000 <= fp.fixed_point_iterations <= 4 * 5000
    nw = model.integrate(x0, v0, dt=1e-5, steps=5000, record_every=5000, solver="newton")
    assert nw.solver == "Newton" and nw.newton_steps == 5000 and nw.fixed_point_iterations == 0
    assert np.max(np.abs(fp.x - nw.x)) < 1e-12 and np.max(np.abs(fp.v - nw.v)) < 1e-9  # one solution, two solvers
    # dt = 1e-3: the contraction dt²·k/(2m) ≈ 3 > 1 (k ≈ 1.7e6 per pair): the fixed point diverges
    with pytest.raises(IntegrationError, match=r"step 1 \(t = 0 → 0.001\).*fixed-point"):
        model.integrate(x0, v0, dt=1e-3, steps=50, solver="fixed-point")
    big = model.integrate(x0, v0, dt=1e-3, steps=200, record_every=10)
    assert big.newton_steps >= 190 and "Newton on" in big.solver and big.newton_iterations >= big.newton_steps
    assert big.energy_drift <= 0.05 * EPS * abs(float(big.energy[0]))  # Newton solves the same exact scheme
    assert "fixed-point iterations per step" in big.solver_report()


def test_bad_input_is_refused(top):
    model, x0, v0 = top
    moving = v0.copy()
    moving[0, 2] = 0.1
    with pytest.raises(InitialConditionError, match="particle 0 coordinate z is fixed"):
        model.integrate(x0, moving, dt=1e-5, steps=10)
    with pytest.raises(InitialConditionError, match="solver='gauss'"):
        model.integrate(x0, v0, dt=1e-5, steps=10, solver="gauss")
    with pytest.raises(InitialConditionError, match="dt must be positive"):
        model.integrate(x0, v0, dt=float("nan"), steps=10)
    with pytest.raises(InitialConditionError, match=r"x0 must have shape \(4, 3\)"):
        model.integrate(x0[:3], v0, dt=1e-5, steps=10)
    low = x0.copy()
    low[2, 2] = -0.1
    with pytest.raises(InitialConditionError, match="watched particle 2 starts at z = -0.1"):
        model.integrate(low, v0, dt=1e-5, steps=10, fall_particles=[1, 2, 3])
    with pytest.raises(InitialConditionError, match="horizontal translation"):
        gs.run_molecular(gs.EXAMPLES[1], 1e-3, offset=(0.0, 0.0, 1.0))
    r = sp.Symbol("r", positive=True)
    with pytest.raises(LagrangeError, match="masses"):
        PairSystem([1.0, -1.0], 1 / r, r)


def test_fall_time_and_p1_drift_in_both_models():
    """Example 10 (V = 1) falls: both models report it, at the same time to the elastic compliance, and the
    fallen vertex is on the plane at that time; the drift of P1 is reported by both and agrees."""
    ex = gs.EXAMPLES[10]
    rigid = gs.run_rigid(ex, 5.0)
    rs = rigid.summary
    assert rs.fell and rs.fall_time == rigid.fall_time and 1.0 < rs.fall_time < 3.0
    assert rs.t[-1] == rs.fall_time and float(rigid.trajectory.t[-1]) < rs.fall_time  # the event state appended
    fall, y = rigid._fall()
    z_fall = gs._vertex_function(rigid.system)(y[:5])[1:, 2]
    assert fall == rs.fall_time and abs(min(z_fall)) < 1e-9  # the fallen vertex is on the plane then
    run = gs.run_molecular(ex, 5.0, record_every=1000)
    ms = run.summary
    assert ms.fell and ms.fall_time == run.result.fall_time == pytest.approx(rs.fall_time, abs=2e-3)
    # the molecular fall time interpolates the crossing inside the last step
    assert run.result.t[-1] == ms.fall_time and ms.fall_time <= run.result.steps * 1e-5
    assert ms.fall_time > (run.result.steps - 1) * 1e-5
    assert np.allclose(ms.P1_drift, ms.P1[-1] - ms.P1[0]) and np.allclose(rs.P1_drift, rs.P1[-1] - rs.P1[0])
    assert np.linalg.norm(ms.P1_drift - rs.P1_drift) < 1e-3
    lines = rs.report()
    assert lines[0].startswith(f"the top falls at t = {rs.fall_time:.6g}") and lines[1].startswith("P1 drift: (")


@pytest.mark.slow
def test_energy_drift_over_two_million_steps_translated():
    """2,000,000 steps (t = 20) of example 1, 100 from the origin: energy within 0.25 ulp of |E|, the centre
    of mass fixed to 1e-12 (the 11,000,000-step run of the paper is in benchmarks/greenspan_solver.py)."""
    ex = gs.EXAMPLES[1]
    run = gs.run_molecular(ex, 20.0, record_every=20_000, offset=SHIFT)
    res = run.result
    assert res.newton_steps == 0 and res.steps == 2_000_000
    assert res.energy_drift_ulps < 0.25
    c = _centre(res, run.model.masses)
    assert np.max(np.abs(c[:, :2] - c[0, :2])) < 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("number", [11, 13])
def test_p1_drift_rate_of_a_non_homogeneous_top_is_its_momentum(number):
    """The contact point's loops ride on the centre of mass, which moves at Σ m v / Σ m (horizontal momentum
    is conserved); over the paper's t = 110 the reported drift rate (least-squares slope of P1(t)) matches it
    to 2 % (what is left is the loops', bounded, contribution). Example 1 (homogeneous, zero momentum):
    a rate 50 times smaller than example 11's."""
    ex = gs.EXAMPLES[number]
    s = gs.run_rigid(ex, 110.0, backend="numba", rtol=1e-9, atol=1e-11).summary
    assert not s.fell and "does not fall by t = 110" in s.report()[0]
    m = np.array(ex.masses)
    _, v0 = gs.initial_vertices(ex)
    u = (m @ v0)[:2] / m.sum()
    assert np.linalg.norm(s.P1_drift_rate - u) < 0.02 * np.linalg.norm(u)
    if number == 11:
        homogeneous = gs.run_rigid(gs.EXAMPLES[1], 110.0, backend="numba", rtol=1e-9, atol=1e-11).summary
        assert np.linalg.norm(homogeneous.P1_drift_rate) < 0.02 * np.linalg.norm(u)


@pytest.mark.slow  # the rigid model through the CLI derives its system (tens of CPU seconds when not cached)
def test_cli_prints_fall_drift_energy_and_solver(capsys):
    from lagrange.cli import main

    assert main(["simulate", "greenspan-10", "--model", "molecular", "--t-end", "2.5", "-q"]) == 0
    out = capsys.readouterr().out
    fall = float(out.split("the top falls at t = ")[1].split()[0])
    assert 1.8 < fall < 1.9 and "(a weighted vertex reaches the plane z = 0)" in out
    assert "P1 drift: (" in out and "solver: fixed point; 2.00 fixed-point iterations per step" in out
    ulps = float(out.split(" ulp of |E|")[0].rsplit("(relative ", 1)[1].split(", ")[1])
    assert 0 <= ulps < 0.05
    assert main(["simulate", "greenspan-10", "--t-end", "2.5", "-q"]) == 0
    out = capsys.readouterr().out
    rigid_fall = float(out.split("the top falls at t = ")[1].split()[0])
    assert rigid_fall == pytest.approx(fall, abs=2e-3) and "P1 drift: (" in out
