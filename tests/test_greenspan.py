"""Greenspan's tetrahedral top: the conservative discrete-gradient integrator and the two models."""

import mpmath
import numpy as np
import pytest
import sympy as sp

from lagrange.discrete import greenspan as gs
from lagrange.discrete.pair_dg import PairSystem, divided_difference


def test_divided_difference_is_rewritten_without_cancellation():
    r = sp.Symbol("r", positive=True)
    phi = 1e6 * (-1 / r**3 + 1 / r**5)
    D, Db, exact = divided_difference(phi, r)
    assert exact
    a, b = sp.symbols("a b", positive=True)
    assert not sp.fraction(sp.together(D))[1].has(b - a)
    f = sp.lambdify((a, b), D)
    with mpmath.workdps(60):
        a0 = mpmath.mpf("1.29")
        b0 = a0 + mpmath.mpf("1e-13")
        exact_value = (1e6 * (-1 / b0**3 + 1 / b0**5) - 1e6 * (-1 / a0**3 + 1 / a0**5)) / (b0 - a0)
    naive = ((float(phi.subs(r, 1.29 + 1e-13)) - float(phi.subs(r, 1.29))) / 1e-13)
    assert abs(f(1.29, 1.29 + 1e-13) - float(exact_value)) < 1e-12 * abs(float(exact_value))
    assert abs(naive - float(exact_value)) > 1e-6 * abs(float(exact_value))  # the naive quotient is ruined


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_energy_and_momenta_conserved_to_rounding():
    """Stiff pair forces (A = 1e6), 300,000 steps: energy to rounding, horizontal momentum and the vertical
    angular momentum exactly (the plane's reaction and gravity are vertical)."""
    model = gs.molecular_model()
    x0, v0 = gs.initial_vertices(gs.EXAMPLES[5])
    res = model.integrate(x0, v0, dt=1e-5, steps=300_000, record_every=10_000)
    E = model.energy(res.x, res.v)
    assert np.ptp(E) / abs(E[0]) < 1e-12
    P = res.v.sum(axis=1)  # unit masses
    scale = np.abs(res.v).sum(axis=(1, 2)).max()  # Σ|m v|: v += dt F/m rounds to eps·|v| per step
    assert np.max(np.abs(P[:, :2] - P[0, :2])) < 1e-12 * scale
    Lz = np.sum(res.x[:, :, 0] * res.v[:, :, 1] - res.x[:, :, 1] * res.v[:, :, 0], axis=1)
    assert np.ptp(Lz) < 1e-9 * abs(Lz[0])
    assert np.max(np.abs(res.x[:, 0, 2])) == 0.0  # the tip stays on the plane


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_fixed_coordinate_and_non_rational_potential():
    r = sp.Symbol("r", positive=True)
    ps = PairSystem([1.0, 1.0], 50 * (r - 1) ** 2 + sp.exp(-r), r)  # non-rational: guarded quotient
    assert not ps.exact
    x0 = np.array([[0.0, 0, 0], [1.2, 0, 0]])
    v0 = np.array([[0.0, 0.3, 0], [0.0, -0.3, 0]])
    res = ps.integrate(x0, v0, dt=1e-3, steps=20_000, record_every=1000)
    E = ps.energy(res.x, res.v)
    assert np.ptp(E) / abs(E[0]) < 1e-9


@pytest.mark.parametrize("number", [pytest.param(1, marks=pytest.mark.slow), 5])  # example 1: 33 s, in the slow run
def test_rigid_and_molecular_models_agree(number):
    """Over t = 5 the 5-DOF rigid top and the 4-particle molecular top differ only by the elastic
    compliance of the stiff pair potential (~1e-5 in position)."""
    out = gs.compare_models(gs.EXAMPLES[number], 5.0)
    assert out["max_P1_difference"] < 1e-3
    assert out["max_Pbar_difference"] < 1e-3
    assert out["molecular_energy_drift"] < 1e-12
    assert out["rigid_energy_error"] < 1e-8


def test_the_slow_top_falls_in_both_models():
    ex = gs.EXAMPLES[10]  # V = 1: too slow to stay up
    _, sol, _ = gs.run_rigid(ex, 10.0)
    fall = [float(e[0]) for e in sol.t_events if len(e)]
    assert fall and fall[0] < 5
    _, mol = gs.run_molecular(ex, 10.0)
    assert mol.fell and mol.fall_time == pytest.approx(fall[0], abs=0.05)


@pytest.mark.slow  # over ~9 s in the default run: moved to the slow set (issue #20: default run < 10 min)
def test_external_potential_conserves_energy():
    """Two particles on a stiff spring in an anharmonic external well U = x⁴/4 + y²: energy to rounding."""
    r = sp.Symbol("r", positive=True)
    X, Y, Z = sp.symbols("x y z", real=True)
    ps = PairSystem([1.0, 2.0], 100 * (r - 1) ** 2 / 2, r, external=X**4 / 4 + Y**2 + sp.cos(Z),
                    external_weights=[1.0, 0.5])
    x0 = np.array([[0.3, 0.1, 0.0], [1.2, -0.2, 0.4]])
    v0 = np.array([[0.0, 0.5, 0.1], [0.2, -0.1, 0.0]])
    res = ps.integrate(x0, v0, dt=1e-3, steps=50_000, record_every=1000)
    E = ps.energy(res.x, res.v)
    assert np.ptp(E) / abs(E[0]) < 1e-9  # to the Newton tolerance (1e-13 per step) accumulated over 50,000 steps
