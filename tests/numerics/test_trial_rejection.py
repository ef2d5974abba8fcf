"""A failed solve of the model in a trial stage rejects the step and shrinks it; a run ends with
SingularMassMatrixError only where the configuration itself is singular, with the cause computed there
(lagrange/codegen/singular.py, lagrange/integrate/scipy_ivp.py).

The stiff problem is the car axis of Mazzia & Magherini's *Test Set for IVP Solvers* (index-3 form: two
wheels of mass ε²M/2 on springs, one end of the axle on a support moving as y_b = r sin ωt,
x_b = √(L² − y_b²)), declared with its two holonomic constraints and springs 10⁴ times the test set's: the
first explicit trial steps leave the constraint manifold so far that ``M + AᵀA`` loses a pivot. Its reference
is a hand-written index-1 formulation (KKT solve with numpy) integrated by scipy's DOP853 at rtol
1e-13 (both in :mod:`lagrange.bench.hard`, whose hard-case suite runs the same problem).
"""

import numpy as np
import pytest

import lagrange as lg
from lagrange import Holonomic, IntegrationError, SingularMassMatrixError, System, t
from lagrange.bench.hard import CAR, CAR_IC, car_axis
from lagrange.bench.hard import car_axis_reference as hard_car_axis_reference
from lagrange.codegen.singular import diagnose


def car_axis_reference(t_eval: np.ndarray) -> np.ndarray:
    """Positions (4, len(t_eval)) of the hand-written index-1 car axis (:func:`lagrange.bench.hard.car_axis_reference`,
    DOP853 at rtol 1e-13)."""
    return hard_car_axis_reference(np.asarray(t_eval)).T


def test_stiff_car_axis_completes_and_agrees_with_a_tight_reference():
    """DOP853 at rtol 1e-6 on the stiff car axis: trial stages far off the manifold are rejected (the label
    counts them) and the run agrees with the independent index-1 formulation at rtol 1e-13."""
    s = car_axis()
    sol = s.simulate((0.0, 0.05), CAR_IC, CAR, method="DOP853", rtol=1e-6, atol=1e-8, n_points=11)
    assert sol.success and "trial stage(s) at an ill-conditioned or singular solve" in sol.method
    ref = car_axis_reference(sol.t)
    Q = np.array([sol[n] for n in ("x_l", "y_l", "x_r", "y_r")])
    assert np.max(np.abs(Q - ref)) < 1e-6, np.max(np.abs(Q - ref))
    assert sol.max_constraint_violation() < 1e-9


def test_singular_configuration_mid_run_is_named_with_ranks():
    """x pinned at 0 by a constraint, y with inertia 1 − t: the configuration becomes singular at t = 1 on the
    one motion the constraint allows. The run stops there with SingularMassMatrixError naming y and the
    ranks, and the partial trajectory is the exact motion up to there (no force acts on y: it stays at 0.5)."""
    x, y = lg.coordinates("x y")
    s = System([x, y], T=x.diff(t) ** 2 / 2 + (1 - t) * y.diff(t) ** 2 / 2, V=x**2 / 2,
               constraints=[Holonomic(x, "pin")])
    with pytest.raises(SingularMassMatrixError) as info:
        s.simulate(2.0, {x: 0.0, y: 0.5, x.diff(t): 0.0, y.diff(t): 0.0}, {}, max_step=0.02)
    exc = info.value
    text = str(exc)
    assert "on the 1 motions the constraints allow" in text and "coordinates involved: y." in text
    assert "mass matrix rank 1 of 2, constraint Jacobian rank 1 of 1" in text and "massless" in text
    assert exc.t == pytest.approx(1.0, abs=1e-6)
    assert exc.partial is not None and exc.partial.t[-1] == pytest.approx(1.0, abs=1e-6)
    assert np.allclose(exc.partial[y], 0.5) and np.allclose(exc.partial[x], 0.0, atol=1e-12)


def test_a_coordinate_without_inertia_fixed_by_a_constraint_runs():
    """T = ẋ²/2 gives y no inertia (M singular), but the constraint y = x fixes it: the constrained system is
    regular (x = cos t), so nothing is refused and no trial step fails."""
    x, y = lg.coordinates("x y")
    s = System([x, y], T=x.diff(t) ** 2 / 2, V=x**2 / 2, constraints=[Holonomic(y - x, "tie")])
    sol = s.simulate(3.0, {x: 1.0, y: 1.0, x.diff(t): 0.0, y.diff(t): 0.0}, {}, n_points=31)
    assert sol.success and "trial stage" not in sol.method
    assert np.allclose(sol[x], np.cos(sol.t), atol=1e-7) and np.allclose(sol[y], sol[x], atol=1e-10)
    kind, _ = diagnose(np.diag([1.0, 0.0]), np.array([[-1.0, 1.0]]), ["x", "y"], ["tie"])
    assert kind == "ill-conditioned"  # not singular: M restricted to the allowed motion (1, 1)/√2 is 1/2


def test_diagnose_tells_the_three_causes_apart():
    M = 5e-4 * np.eye(4)
    # dependent rows (one a multiple of the other, at another scale): named, rank 1 < 2
    kind, text = diagnose(M, np.array([[1.0, -1.0, 0, 0], [3e5, -3e5, 0, 0]]), list("abcd"), ["c1", "c2"])
    assert kind == "dependent" and "c1, c2 are dependent" in text and "rank 1 < 2" in text
    # the car axis far off its manifold: M regular, A full rank, M + AᵀA ill-conditioned
    q = np.array([0.0, 5e6, 1e7, 5e6])
    A = np.array([[1.0, 0.0, 0, 0], [2 * (q[0] - q[2]), 2 * (q[1] - q[3]), -2 * (q[0] - q[2]), -2 * (q[1] - q[3])]])
    kind, text = diagnose(M, A, ["x_l", "y_l", "x_r", "y_r"], ["support", "axle"], where="at t=0")
    assert kind == "ill-conditioned"
    assert "at t=0 is regular (mass matrix rank 4 of 4, constraint Jacobian rank 2 of 2" in text
    assert "massless" not in text
    # a massless coordinate that no constraint fixes: named
    kind, text = diagnose(np.diag([1.0, 1.0, 0.0, 1.0]), np.array([[1.0, -1.0, 0, 0]]), list("abcd"), ["c"])
    assert kind == "mass" and "coordinates involved: c." in text and "mass matrix rank 3 of 4" in text
    # without constraints: a negative inertia is not positive definite
    kind, text = diagnose(np.diag([1.0, -0.5]), None, ["x", "y"])
    assert kind == "mass" and "negative" in text and "coordinates involved: y." in text


def test_collapse_at_a_regular_configuration_is_not_a_singular_mass_matrix():
    """Where the step size collapsed with the last failed trial stage at a regular configuration, the error is
    an IntegrationError naming the ill-conditioned solve, never SingularMassMatrixError."""
    from lagrange.integrate.scipy_ivp import _trial_fault_error
    from lagrange.integrate.stepper import StepLog

    model = car_axis().compile(CAR)
    log = StepLog(np.linspace(0.0, 1.0, 3))
    log.start(0.0, np.zeros(8), 1.0)
    assert _trial_fault_error(model, log) is None  # no failed trial stage: another cause
    far = np.array([0.0, 5e6, 1e7, 5e6, 0, 0, 0, 0])
    with pytest.raises(SingularMassMatrixError):
        model.fun(0.0, far)  # the generated solve does fail there
    log.fault(0.0, far)
    err = _trial_fault_error(model, log)
    assert type(err) is IntegrationError and "is regular" in str(err) and "ill-conditioned" in str(err)


@pytest.mark.slow
def test_compiled_loop_rejects_a_failed_solve_and_names_it_where_the_step_collapses():
    """The compiled DOP853 loop (numba) treats a trial stage whose solve fails as a rejected step: with inertia
    1 − t it runs up to t = 1 (to round-off, where it stopped at the first trial step past 1 before) and ends
    with the failed solve as the cause, its partial trajectory exact."""
    pytest.importorskip("numba")
    x, y = lg.coordinates("x y")
    s = System([x, y], T=x.diff(t) ** 2 / 2 + (1 - t) * y.diff(t) ** 2 / 2, V=x**2 / 2)
    with pytest.raises(IntegrationError, match="division by zero while evaluating the model") as info:
        s.simulate(2.0, {x: 1.0, y: 0.5, x.diff(t): 0.0, y.diff(t): 0.0}, {}, max_step=0.02, loop="compiled",
                   backend="numba")
    exc = info.value
    assert exc.t == pytest.approx(1.0, abs=1e-9)
    p = exc.partial  # the output times (every 0.002) reached
    assert p.t[-1] == pytest.approx(0.998, abs=1e-12)
    assert np.allclose(p[x], np.cos(p.t), atol=1e-8) and np.allclose(p[y], 0.5)
