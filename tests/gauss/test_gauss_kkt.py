"""The least-constraint KKT solve (Sonneveld Lemma 7, E21): KKT = Schur complement = SLSQP minimiser;
redundant rows leave the minimiser unchanged; inconsistent rows raise naming the rows."""

import numpy as np
import pytest
from scipy.optimize import minimize

from lagrange.errors import InconsistentConstraintError, LagrangeError, SingularMassMatrixError
from lagrange.gauss.kkt import solve_least_constraint


def _problem(seed, n=6, k=3):
    rng = np.random.default_rng(seed)
    B = rng.normal(size=(n, n))
    return B @ B.T + n * np.eye(n), rng.normal(size=n), rng.normal(size=(k, n)), rng.normal(size=k)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_kkt_equals_schur_and_slsqp(seed):
    H, g, C, d = _problem(seed)
    sol = solve_least_constraint(H, g, C, d)
    Hi = np.linalg.inv(H)
    lam = np.linalg.solve(C @ Hi @ C.T, d - C @ Hi @ g)  # Schur complement, eq. (31)
    z = Hi @ (g + C.T @ lam)  # eq. (30)
    assert np.allclose(sol.z, z, rtol=1e-12, atol=1e-12)
    assert np.allclose(sol.multipliers, lam, rtol=1e-10, atol=1e-12)
    assert sol.rank == 3 and sol.redundant == 0 and sol.multipliers_unique
    res = minimize(lambda x: 0.5 * x @ H @ x - g @ x, np.zeros(len(g)), jac=lambda x: H @ x - g, method="SLSQP",
                   constraints=[{"type": "eq", "fun": lambda x: C @ x - d, "jac": lambda x: C}],
                   options={"ftol": 1e-14, "maxiter": 500})
    assert np.allclose(res.x, sol.z, atol=1e-6)


def test_duplicated_row_same_minimiser_multipliers_not_unique():
    H, g, C, d = _problem(3)
    base = solve_least_constraint(H, g, C, d)
    C2, d2 = np.vstack([C, 2 * C[1]]), np.concatenate([d, [2 * d[1]]])
    dup = solve_least_constraint(H, g, C2, d2)
    assert np.allclose(dup.z, base.z, rtol=1e-12, atol=1e-12)
    assert dup.redundant == 1 and not dup.multipliers_unique
    # the constraint force C^T lambda is the same; the individual multipliers are not (only the sum matters)
    assert np.allclose(C2.T @ dup.multipliers, C.T @ base.multipliers, atol=1e-10)
    alt = dup.multipliers + 0.7 * np.array([0, 2, 0, -1.0])  # a null vector of C2^T
    assert np.allclose(C2.T @ alt, C2.T @ dup.multipliers, atol=1e-10)


def test_inconsistent_rows_raise_and_name_them():
    H, g, C, d = _problem(4)
    C2, d2 = np.vstack([C, C[0] + C[2]]), np.concatenate([d, [d[0] + d[2] + 0.5]])
    with pytest.raises(InconsistentConstraintError) as exc:
        solve_least_constraint(H, g, C2, d2, names=["a", "b", "c", "a+c"])
    assert set(exc.value.constraints) == {"a", "c", "a+c"}
    assert isinstance(exc.value, LagrangeError) and isinstance(exc.value, ValueError)
    assert "a, c, a+c" in str(exc.value) and "jammed" in str(exc.value)


def test_semidefinite_hessian_definite_on_null_space():
    # z = (x, y); H = diag(1, 0): y alone has no "mass", but the constraint y = 2x fixes it
    sol = solve_least_constraint(np.diag([1.0, 0.0]), [3.0, 0.0], [[2.0, -1.0]], [0.0])
    # minimise x^2/2 - 3x with y = 2x -> x = 3, y = 6
    assert np.allclose(sol.z, [3.0, 6.0])
    with pytest.raises(SingularMassMatrixError):
        solve_least_constraint(np.diag([1.0, 0.0]), [3.0, 0.0], [[1.0, 0.0]], [1.0])
    with pytest.raises(SingularMassMatrixError):
        solve_least_constraint(np.diag([1.0, 0.0]), [3.0, 1.0], np.zeros((0, 2)), [])
