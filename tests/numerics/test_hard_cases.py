"""Hard cases of numerical integration: stiffness, dry friction, chaos.

Already covered elsewhere (not repeated here): ``method='auto'`` picking LSODA on strong damping and saying
why (tests/test_integrate.py::test_auto_detects_stiff_dissipation); the closed-form stick positions of a
block on a rough floor (tests/test_integrate.py::TestCoulombFriction); gimbal lock of Euler angles raised
at θ = 0 and warned near it, with the quaternion remedy (tests/test_rigid_body.py); 10,000 periods with
bounded energy under Störmer–Verlet and GL4 (slow, tests/numerics/test_geometric.py).
"""

import numpy as np
import pytest
import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.bench.horizon import validity_horizon
from lagrange.bench.problems import belt_state, belt_stick_interval, belt_system, damped_double_pendulum, get_problem
from lagrange.examples import n_link_pendulum

STIFF_IC = {"q1": 0.3, "q2": -0.2, "q1_dot": 0.0, "q2_dot": 0.0}
BELT = {"m": 1.0, "k": 1.0, "mu": 0.5, "g": 1.0}


def test_explicit_method_on_stiff_damping_needs_far_more_evaluations():
    """Elbow damping c = 10³ (decay rate ≈ 3.9e3/s, the pendulum swings on): auto sees the stiffness and says
    why; DOP853 reaches the same answer only with > 50,000 evaluations (stability-limited steps: ~74,000
    whatever the tolerance). Moderately stiff and analytic: auto picks the Taylor method when a tape
    interpreter is here (steps ~p/(2·rate), 5-20× faster than LSODA here), else an implicit method."""
    s = damped_double_pendulum()
    p = {"g": 9.81, "c": 1e3}
    auto = s.simulate(10, STIFF_IC, p, method="auto", rtol=1e-6, atol=1e-8, t_eval=[10.0])
    assert "auto: stiff" in auto.method and "decay rate" in auto.method
    assert auto.method.split(" ")[0] in ("taylor", "LSODA", "Radau")
    explicit = s.simulate(10, STIFF_IC, p, method="DOP853", rtol=1e-6, atol=1e-8, t_eval=[10.0])
    assert explicit.nfev > 50_000
    ref = s.simulate(10, STIFF_IC, p, method="Radau", rtol=1e-11, atol=1e-13, t_eval=[10.0]).y[-1]
    assert np.max(np.abs(auto.y[-1] - ref)) < 1e-5 and np.max(np.abs(explicit.y[-1] - ref)) < 1e-5


@pytest.mark.parametrize("v0", [0.5, 0.0])
def test_belt_stick_slip_matches_closed_form(v0):
    """A mass on a spring on a moving belt: slip, one stick phase of the closed-form duration, then the
    limit cycle that only touches the belt speed — over 20 periods, without chatter."""
    T = 2 * np.pi * 20
    ts = np.linspace(0, T, 20001)
    sol = belt_system().simulate(T, {"x": 0.0, "x_dot": v0}, BELT, t_eval=ts, rtol=1e-10, atol=1e-12)
    assert np.max(np.abs(sol.y - belt_state(ts, v0=v0))) < 1e-7
    stuck = np.abs(sol.switches[1][:, 0]) < 1 - 1e-9  # Filippov sticking: |σ*| < 1
    t1, t2 = belt_stick_interval(v0=v0)
    assert ts[stuck].min() == pytest.approx(t1, abs=ts[1]) and ts[stuck].max() == pytest.approx(t2, abs=ts[1])
    assert np.count_nonzero(np.diff(stuck.astype(int)) == 1) == 1  # one stick phase, no chatter
    assert sol.nfev < 30_000


def _belt_transitions_from_closed_form(t_end: float, v0: float = 0.5, belt: float = 0.2):
    """The stick/slip mode changes of :func:`belt_state`: the initial slip, the stick at t1, the slip behind the
    belt at t2; and the times t2 + 2πk where the limit cycle touches the belt speed (a tangency, which a run may
    record as a stick of zero length: at most two more mode changes each)."""
    t1, t2 = belt_stick_interval(v0=v0, belt=belt)
    expected = [(0.0, "slip+" if v0 > belt else "slip-"), (t1, "stick"), (t2, "slip-")]
    return expected, t2 + 2 * np.pi * np.arange(1, int((t_end - t2) / (2 * np.pi)) + 1)


@pytest.mark.parametrize("method, rtol", [("DOP853", 1e-8), ("DOP853", 1e-10), ("DOP853", 1e-12), ("RK45", 1e-12),
                                          ("Radau", 1e-12), ("LSODA", 1e-12)])
def test_belt_stick_slip_at_tight_tolerances(method, rtol):
    """The benchmark's stick-slip problem (issue #7) at tight tolerances. DOP853 at rtol 1e-12 used to chatter
    at the end of the stick (100,000 switches at t = 2.1075: the end-of-stick event fired where static friction
    could still hold by 1e-12, Filippov's test re-entered sticking and the new stick's event fired again at
    the same instant; Radau did the same at 1e-10). Now: the closed form to O(rtol), and only the physical
    mode changes, at their closed-form times."""
    prob = get_problem("stick_slip")
    ts = np.asarray(prob.sample_times)
    sol = prob.build().simulate((0.0, prob.t_end), prob.initial, prob.params, method=method, rtol=rtol,
                                atol=rtol * prob.atol_scale, t_eval=ts, **prob.options)
    assert np.max(np.abs(sol.y - belt_state(ts))) < 100 * rtol
    expected, tangencies = _belt_transitions_from_closed_form(prob.t_end)
    transitions = sol.switches[2]
    assert [tr.after for tr in transitions[:3]] == [mode for _, mode in expected]
    assert np.allclose([tr.t for tr in transitions[:3]], [t_ for t_, _ in expected], rtol=0, atol=100 * rtol)
    extra = transitions[3:]  # zero-length sticks where the limit cycle grazes the belt speed, nothing else
    assert len(extra) <= 2 * len(tangencies)
    assert all(np.min(np.abs(tangencies - tr.t)) < 0.01 for tr in extra)


def test_friction_loaded_exactly_to_its_limit_stays_stuck():
    """A block at rest on an incline at exactly the friction angle (driving force = μmg): static friction holds
    it (up to the hysteresis η = rtol of lagrange.integrate.switching). Without the hysteresis the end-of-stick
    test compares 1 − |σ*| = 0 with 0 at every step and the run chatters at t = 0."""
    x = coordinates("x")
    m, mu, g = parameters("m mu g")
    s = System([x], T=m * x.diff(t) ** 2 / 2, forces={x: mu * m * g - mu * m * g * sp.sign(x.diff(t))})
    for rtol in (1e-6, 1e-12):
        sol = s.simulate(50, {"x": 0.0, "x_dot": 0.0}, {"m": 1, "mu": 0.3, "g": 9.81}, rtol=rtol, atol=rtol,
                         t_eval=np.linspace(0, 50, 11))
        assert np.all(sol.y == 0.0)
        assert [tr.after for tr in sol.switches[2]] == ["stick"]
        assert np.allclose(sol.switches[1], 1.0)  # the static friction needed: all of μmg


def test_two_contacts_stuck_together_are_solved_jointly():
    """Two friction contacts whose slip velocities u1 = ȧ − vb, u2 = ȧ + ḃ − vb share a coordinate (the
    matrix ∂u M⁻¹ ∂uᵀ is [[2, 1], [1, 1]]/m, not diagonal). Starting with both at the belt speed, both stay stuck
    (a = vb t, b = 0) while the friction each needs — σ1 = −k a/(μmg), σ2 = 0 — is available, so contact 1
    slips first at t = μmg/(k vb) = 2.5. Solving the σ* one contact at a time with the other's σ frozen at ±1
    started the block moving at t = 0."""
    a, b = coordinates("a b")
    m, k, mu, g = parameters("m k mu g")
    vb = sp.Rational(1, 5)
    ad, bd = a.diff(t), b.diff(t)
    s = System([a, b], T=m * ad**2 / 2 + m * bd**2 / 2, V=k * a**2 / 2 + k * b**2 / 2,
               P=-mu * m * g * (sp.Abs(ad - vb) + sp.Abs(ad + bd - vb)))
    ts = np.linspace(0, 2.4, 25)
    sol = s.simulate(3, {"a": 0.0, "b": 0.0, "a_dot": 0.2, "b_dot": 0.0}, {"m": 1, "k": 1, "mu": 0.5, "g": 1},
                     t_eval=ts, method="DOP853", rtol=1e-10, atol=1e-12)
    assert np.allclose(sol.y, np.column_stack([0.2 * ts, 0 * ts, 0.2 + 0 * ts, 0 * ts]), rtol=0, atol=1e-9)
    assert np.allclose(sol.switches[1], np.column_stack([-0.4 * ts, 0 * ts]), rtol=0, atol=1e-9)
    assert [(tr.switch, tr.after) for tr in sol.switches[2]] == [(0, "stick"), (1, "stick"), (0, "slip-")]
    assert sol.switches[2][-1].t == pytest.approx(2.5, abs=1e-8)


def test_regularized_friction_converges_to_the_stick_slip_cycle():
    """friction='regularize' (sign(u) → u/√(u² + ε²), documented in lagrange.integrate.switching) is an
    approximation whose error against the closed form shrinks with ε."""
    ts = np.linspace(0, 30, 301)
    errs = []
    for eps in (1e-3, 1e-5):
        sol = belt_system().simulate(30, {"x": 0.0, "x_dot": 0.5}, BELT, t_eval=ts, friction="regularize",
                                     friction_epsilon=eps, method="LSODA", rtol=1e-10, atol=1e-12)
        errs.append(np.max(np.abs(sol.y - belt_state(ts))))
    assert errs[1] < 2e-3 and errs[1] < errs[0] / 10


def test_stuck_block_never_chatters():
    """Block on a spring on a rough floor (sticks for good at t = 5π): 300 time units later the events
    treatment has used no more evaluations than the sliding part needed — the stuck phase costs one segment."""
    x = coordinates("x")
    m, k, mu, g = parameters("m k mu g")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * g * sp.Abs(x.diff(t)))
    p = {"m": 1, "k": 1, "mu": 0.1, "g": 1}
    short = s.simulate(5 * np.pi + 1, {x: 1.05, x.diff(t): 0}, p)
    long = s.simulate(300, {x: 1.05, x.diff(t): 0}, p, t_eval=np.linspace(0, 300, 3001))
    stuck = long.t > 5 * np.pi + 1e-6
    assert np.allclose(long["x"][stuck], -0.05, atol=1e-7) and np.all(np.abs(long["x_dot"][stuck]) < 1e-9)
    assert long.nfev < short.nfev + 500


def test_friction_with_sparse_output_times():
    x = coordinates("x")
    m, k, mu, g = parameters("m k mu g")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-mu * m * g * sp.Abs(x.diff(t)))
    sol = s.simulate(30, {x: 1.05, x.diff(t): 0}, {"m": 1, "k": 1, "mu": 0.1, "g": 1}, t_eval=[20.0, 30.0])
    assert np.allclose(sol["x"], -0.05, atol=1e-7)


def test_validity_horizon_of_a_chaotic_double_pendulum():
    """High-energy double pendulum (q = 2, 2.3): the rtol = 1e-6 trajectory is valid only up to a finite time,
    tightening rtol by 10³ extends it (logarithmically), and the finite-time Lyapunov exponent is positive."""
    s = n_link_pendulum(2)
    ic = {"q1": 2.0, "q2": 2.3, "q1_dot": 0.0, "q2_dot": 0.0}
    loose = validity_horizon(s, 30, ic, {"g": 9.81}, rtol=1e-6, n_points=1501)
    tight = validity_horizon(s, 30, ic, {"g": 9.81}, rtol=1e-9, n_points=1501)
    assert loose.diverged and tight.diverged
    assert 1.0 < loose.horizon < tight.horizon < 30
    assert loose.lyapunov > 0.5  # chaos: ln-separation grows at ≥ 0.5 per unit time
    assert loose.separation[0] == 0 and loose.separation.max() > loose.threshold
    assert "valid (to 0.01) until t = " in str(loose)


def test_validity_horizon_covers_a_regular_run():
    """Small oscillations: the two tolerances agree to the threshold over the whole run; separation of
    nearby initial states grows only slowly (λ_T ≈ 0)."""
    s = n_link_pendulum(2)
    ic = {"q1": 0.05, "q2": -0.05, "q1_dot": 0.0, "q2_dot": 0.0}
    h = validity_horizon(s, 30, ic, {"g": 9.81}, rtol=1e-6, n_points=601)
    assert not h.diverged and h.horizon == 30.0
    assert h.lyapunov < 0.1 and h.separation.max() < 1e-4


def test_friction_switch_with_a_parameter_matches_the_literal():
    """A dry-friction switching function that contains a parameter (the belt speed) is evaluated with the
    parameter's value: the run equals the one with the number written in."""
    x = coordinates("x")
    m, k, mu, g, vb = parameters("m k mu g vb")
    xd = x.diff(t)
    base = {"m": 1, "k": 1, "mu": 0.3, "g": 9.81}
    runs = []
    for belt, extra in ((vb, {"vb": 0.2}), (sp.Rational(1, 5), {})):
        s = System([x], T=m * xd**2 / 2, V=k * x**2 / 2, forces={x: -mu * m * g * sp.sign(xd - belt)})
        runs.append(s.simulate(10, {"x": 0.0, "x_dot": 0.0}, {**base, **extra}, t_eval=[2.0, 10.0]))
    assert np.allclose(runs[0].y, runs[1].y, rtol=0, atol=1e-9)
    assert runs[0].y[-1, 1] == pytest.approx(0.2)  # stuck to the belt at the end


def test_implicit_method_on_dry_friction():
    """Radau gets a generated Jacobian even when the forces contain sign(): the derivative of the sign
    (a Dirac delta) vanishes inside every frozen-sign segment, and the run matches DOP853."""
    s = belt_system()
    runs = [s.simulate(15.0, {"x": 0.0, "x_dot": 0.5}, BELT, method=m, rtol=1e-10, atol=1e-12, t_eval=[5.0, 15.0])
            for m in ("Radau", "DOP853")]
    assert np.allclose(runs[0].y, runs[1].y, atol=1e-6)
