"""scipy's ``solve_ivp`` methods, with a generated Jacobian for the implicit ones.

The Jacobian of ``y' = [q̇, M⁻¹f]`` is

.. math:: \\frac{\\partial \\ddot q}{\\partial y_k} = M^{-1}\\Big(\\frac{\\partial f}{\\partial y_k}
          - \\frac{\\partial M}{\\partial y_k}\\,\\ddot q\\Big)

built from symbolic derivatives of M and f (one CSE'd lambdify), never from finite differences.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import sympy as sp

from ..codegen.cse import numeric_arguments, rename_map
from ..codegen.numeric import NumericModel

__all__ = ["SCIPY_METHODS", "IMPLICIT_METHODS", "jacobian_function"]

SCIPY_METHODS = ("DOP853", "RK45", "RK23", "LSODA", "Radau", "BDF")
IMPLICIT_METHODS = ("Radau", "BDF", "LSODA")


def jacobian_function(model: NumericModel) -> Callable:
    """``jac(t, y) -> ndarray (2n, 2n)`` for the model's bound parameters."""
    eqs = model.equations
    n = eqs.n
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    M = eqs.mass_matrix.xreplace(ren)
    f = eqs.forcing.xreplace(ren)
    # d sign(u)/du = 2 δ(u): zero inside every segment the friction driver integrates (σ frozen there)
    def no_delta(expr):
        return expr.replace(sp.DiracDelta, lambda *args: sp.S.Zero)

    dM = [no_delta(M.diff(y)) for y in ys]
    df = no_delta(f.jacobian(ys))
    fn = sp.lambdify((tt, ys, ps), (M, f, df, dM), modules="numpy", cse=True)
    params = list(model.params)

    def jac(t_, y):
        Mv, fv, dfv, dMv = fn(t_, list(y), params)
        Mv = np.array(Mv, dtype=float)
        acc = np.linalg.solve(Mv, np.array(fv, dtype=float).ravel())
        R = np.array(dfv, dtype=float).reshape(n, 2 * n)
        for k in range(2 * n):
            R[:, k] -= np.array(dMv[k], dtype=float) @ acc
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:, :] = np.linalg.solve(Mv, R)
        return J

    return jac
