"""The Whipple bicycle against Meijaard et al. (2007): linear coefficient matrices, Table 2 eigenvalues, weave and
capsize speeds, and the nonlinear model's self-stability.

Truth is the published benchmark (values in ``lagrange_problems.bench_bicycle.PUBLISHED``). The linearization
here is our own (``lean_steer_matrix``: central differences with a Richardson step of the compiled constrained
dynamics, on the constraint manifold), independent of ``lagrange.characteristic_roots``;
``test_characteristic_roots_api`` checks the same published numbers through that public API (exact
complex-step Jacobians on the constraint manifold).

Deriving and compiling the model takes tens of seconds, so every test that needs it is marked slow and shares
one compiled model per session.
"""

import numpy as np
import pytest
import sympy as sp
from lagrange_problems import bench_bicycle as bike
from scipy.optimize import brentq

import lagrange as lg
from lagrange import t
from lagrange.corpus import LazySystem, get_problem

PUB = bike.PUBLISHED


@pytest.fixture(scope="session")
def model():
    return bike.PROBLEM.system.compile(bike.PARAMS)


def _sorted(ev):
    ev = np.asarray(ev, dtype=complex)
    return ev[np.lexsort((ev.imag, np.round(ev.real, 8)))]


# --- fast: the declaration ---------------------------------------------------------------------------------


def test_problem_is_registered_and_lazy():
    p = get_problem("bicycle")
    assert p is bike.PROBLEM
    assert isinstance(p.system, LazySystem)
    assert set(p.operating_point) >= {bike.phi, bike.delta, bike.theta_R.diff(t)}
    assert p.operating_point[bike.theta_R.diff(t)] == -bike.v / bike.SYMBOLS["r_R"]
    assert p.operating_point[bike.x.diff(t)] == bike.v


def test_declaration_builds_with_non_integrable_rolling_constraints():
    # a fresh System (the problem's is built lazily): four bodies, four rolling constraints that the Frobenius
    # test finds non-integrable (no IntegrableConstraintWarning) and one holonomic ground contact
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error", lg.IntegrableConstraintWarning)
        system = bike.whipple_bicycle()
    kinds = [c.kind for c in system.constraints]
    assert kinds == ["nonholonomic"] * 4 + ["holonomic"]
    assert not any(c.integrable for c in system.constraints)
    assert [b.name for b in system.bodies] == ["rear wheel", "rear frame", "front frame", "front wheel"]
    assert all(isinstance(b.orientation, lg.RotationSequence) for b in system.bodies)
    # upright, straight running satisfies every constraint (the operating point is on the manifold)
    point = bike.operating_point(sp.Rational(5), bike.BENCHMARK)
    values = {bike.SYMBOLS[k]: val for k, val in bike.BENCHMARK.items()}
    values[bike.lam] = sp.pi / 10
    for c in system.constraints:
        assert sp.simplify(c.velocity.subs(point).subs(values)) == 0, c.name
    contact = system.constraints[-1].position  # the front wheel touches the ground in the reference configuration
    assert sp.simplify(contact.subs(point).subs(values)) == 0


def test_rear_rolling_constraint_is_the_general_formula():
    # the hand-simplified rear constraint equals the velocity of the wheel's material contact point
    # (hub velocity + ω × (contact − hub)) written out in full, at random states
    x, y, psi, phi, theta, theta_R = bike.x, bike.y, bike.psi, bike.phi, bike.theta, bike.theta_R
    r = bike.SYMBOLS["r_R"]
    ez, ey, ex = sp.Matrix([0, 0, 1]), sp.Matrix([0, 1, 0]), sp.Matrix([1, 0, 0])
    Y, Rr = lg.rot_z(psi), lg.rot_x(phi)
    hub = sp.Matrix([x, y, 0]) - r * Y * Rr * ez
    omega = (psi.diff(t) * ez + phi.diff(t) * Y * ex + (theta.diff(t) + theta_R.diff(t)) * Y * Rr * ey)
    slip = Y.T * (hub.diff(t) + omega.cross(r * Y * Rr * ez))
    hand = [sp.cos(psi) * x.diff(t) + sp.sin(psi) * y.diff(t) + r * (theta.diff(t) + theta_R.diff(t)),
            -sp.sin(psi) * x.diff(t) + sp.cos(psi) * y.diff(t)]
    rng = np.random.default_rng(3)
    atoms = sorted((slip[0] + slip[1]).atoms(sp.Derivative), key=str) + [x, y, psi, phi, theta, theta_R, r]
    for _ in range(5):
        point = {a: float(v) for a, v in zip(atoms, rng.uniform(-2, 2, len(atoms)))}
        for k in range(2):
            assert abs(float(slip[k].subs(point)) - float(hand[k].subs(point))) < 1e-12
    assert abs(float(slip[2].subs(point))) < 1e-12  # the vertical component vanishes identically


# --- slow: linearization against the paper -----------------------------------------------------------------


def _accelerations_per_torque(model):
    """(φ̈, δ̈) per unit roll and steer torque at the upright state at rest (no gravity torque there): the
    columns of the inverse of the paper's M."""
    n = model.n
    idx = [list(model.equations.coordinates).index(q) for q in (bike.phi, bike.delta)]

    def response(m):
        return np.asarray(m.dynamics(0.0, np.zeros(2 * n), m.params))[[n + i for i in idx]]

    base = response(model)
    cols = [response(model.with_params({name: 1.0})) - base for name in ("T_phi", "T_delta")]
    return np.array(cols).T


@pytest.mark.slow
def test_linear_coefficient_matrices_match_the_paper(model):
    g = 9.81
    B = _accelerations_per_torque(model)  # M⁻¹
    M = np.linalg.inv(B)
    np.testing.assert_allclose(M, PUB["M"], rtol=0, atol=1e-9 * 80.8)
    A0 = bike.lean_steer_matrix(model, 0.0)
    K0 = -M @ A0[2:, :2] / g
    np.testing.assert_allclose(K0, PUB["K0"], rtol=0, atol=1e-9 * 81)
    v = 3.0
    Av = bike.lean_steer_matrix(model, v)
    K2 = (-M @ Av[2:, :2] - g * K0) / v**2
    C1 = -M @ Av[2:, 2:] / v
    np.testing.assert_allclose(K2, PUB["K2"], rtol=0, atol=1e-8 * 77)
    np.testing.assert_allclose(C1, PUB["C1"], rtol=0, atol=1e-9 * 34)


@pytest.mark.slow
def test_eigenvalues_match_table_2(model):
    worst = 0.0
    for speed, published in PUB["eigenvalues"].items():
        got = _sorted(np.linalg.eigvals(bike.lean_steer_matrix(model, float(speed))))
        want = _sorted(published)
        rel = np.max(np.abs(got - want) / np.maximum(np.abs(want), 1.0))
        worst = max(worst, rel)
        assert rel < 1e-10, f"v = {speed}: {got} against Table 2 {want}"
    assert worst > 0  # really compared numbers (not two empty arrays)


@pytest.mark.slow
def test_weave_and_capsize_speeds(model):
    def abscissa(speed):
        return float(np.max(np.linalg.eigvals(bike.lean_steer_matrix(model, speed)).real))

    weave = brentq(abscissa, 4.0, 5.0, xtol=1e-13)
    capsize = brentq(abscissa, 5.5, 6.5, xtol=1e-13)
    assert abs(weave - PUB["weave_speed"]) < 1e-10 * PUB["weave_speed"]
    assert abs(capsize - PUB["capsize_speed"]) < 1e-10 * PUB["capsize_speed"]
    assert abscissa(3.0) > 0 > abscissa(5.0) and abscissa(7.0) > 0


def _lean_envelope(speed, t_end, roll_rate):
    sysm = bike.PROBLEM.system
    initial = {**bike.operating_point(speed, bike.BENCHMARK), bike.phi.diff(t): roll_rate}
    sol = sysm.simulate(t_end, initial, bike.PARAMS, rtol=1e-9, atol=1e-9)
    assert sol.success
    idx = list(sysm.coordinates).index(bike.phi)
    lean = np.abs(sol.y[:, idx])
    tt = sol.t
    early, late = lean[tt <= 1.0].max(), lean[tt >= t_end - 1.0].max()
    assert sol.max_constraint_violation() < 1e-8  # rolling and ground contact hold along the run
    return early, late


@pytest.mark.slow
def test_nonlinear_run_is_self_stable_at_5_and_weaves_away_at_3(model):
    early, late = _lean_envelope(5.0, 6.0, 0.3)
    assert late < 0.35 * early, f"at 5 m/s the lean should decay: {early:.3g} -> {late:.3g}"
    early, late = _lean_envelope(3.0, 3.0, 0.02)
    assert late > 3 * early, f"at 3 m/s the weave should grow: {early:.3g} -> {late:.3g}"


def _api_roots(system, speed):
    """The four lean/steer roots: every root but the structural zeros (ignorable coordinates, forward speed),
    which characteristic_roots deflates exactly — so they are exact zeros even at the capsize speed, where the
    capsize root itself crosses zero."""
    about = bike.operating_point(speed, bike.BENCHMARK)
    roots = np.asarray(lg.characteristic_roots(system, about=about, params=bike.PARAMS), dtype=complex)
    assert np.count_nonzero(roots == 0) == len(roots) - 4  # exact structural zeros, four lean/steer roots
    return _sorted(roots[roots != 0])


@pytest.mark.slow
def test_characteristic_roots_api(model):
    """The public API (lagrange.characteristic_roots on the constraint manifold, the independent coordinates
    and speeds chosen by the library) against Table 2 at every tabulated speed, and the weave and capsize
    speeds from its roots; the zero roots belong to the ignorable coordinates and the forward-speed mode."""
    system = bike.PROBLEM.system.build()
    for speed, published in PUB["eigenvalues"].items():
        nonzero, want = _api_roots(system, float(speed)), _sorted(published)
        assert nonzero.shape == want.shape, f"v = {speed}: {nonzero}"
        rel = np.max(np.abs(nonzero - want) / np.maximum(np.abs(want), 1.0))
        assert rel < 1e-10, f"v = {speed}: {nonzero} against Table 2 {want}"

    def abscissa(speed):
        return float(np.max(_api_roots(system, speed).real))

    weave = brentq(abscissa, 4.0, 5.0, xtol=1e-13)
    capsize = brentq(abscissa, 5.5, 6.5, xtol=1e-13)
    assert abs(weave - PUB["weave_speed"]) < 1e-10 * PUB["weave_speed"]
    assert abs(capsize - PUB["capsize_speed"]) < 1e-10 * PUB["capsize_speed"]
