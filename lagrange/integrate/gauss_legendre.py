r"""Gauss–Legendre collocation (implicit Runge–Kutta) of orders 2, 4 and 6, and the implicit midpoint rule.

Symplectic and symmetric for Hamiltonian systems in canonical variables; they conserve quadratic
invariants exactly and keep the energy error bounded over exponentially long times (Hairer, Lubich &
Wanner, *Geometric Numerical Integration*, 2nd ed., ch. II.1, IV.2, VI.4). Stage equations
``K_i = f(t + c_i h, z + h Σ_j a_ij K_j)`` are solved by Newton with the generated Hessian.
"""

from __future__ import annotations

import numpy as np

from .base import Integrator, newton

__all__ = ["GaussLegendre2", "GaussLegendre4", "GaussLegendre6", "ImplicitMidpoint"]

_S3 = np.sqrt(3.0)
_S15 = np.sqrt(15.0)

#: Butcher tableaux (A, b, c) of the Gauss methods (Hairer–Wanner II, Table 7.3 and 7.4).
TABLEAUX = {
    1: (np.array([[0.5]]), np.array([1.0]), np.array([0.5])),
    2: (np.array([[0.25, 0.25 - _S3 / 6], [0.25 + _S3 / 6, 0.25]]), np.array([0.5, 0.5]),
        np.array([0.5 - _S3 / 6, 0.5 + _S3 / 6])),
    3: (np.array([[5 / 36, 2 / 9 - _S15 / 15, 5 / 36 - _S15 / 30],
                  [5 / 36 + _S15 / 24, 2 / 9, 5 / 36 - _S15 / 24],
                  [5 / 36 + _S15 / 30, 2 / 9 + _S15 / 15, 5 / 36]]),
        np.array([5 / 18, 4 / 9, 5 / 18]), np.array([0.5 - _S15 / 10, 0.5, 0.5 + _S15 / 10])),
}


class _Gauss(Integrator):
    stages = 1
    symplectic = True

    def _step_impl(self, t, z, h):
        A, b, c = TABLEAUX[self.stages]
        s, m = self.stages, len(z)
        f, J = self.model.field, self.model.field_jacobian
        K0 = np.tile(f(t, z), s)

        def stage_points(K):
            Kr = K.reshape(s, m)
            return [z + h * (A[i] @ Kr) for i in range(s)]

        def residual(K):
            Y = stage_points(K)
            return K - np.concatenate([f(t + c[i] * h, Y[i]) for i in range(s)])

        def jacobian(K):
            Y = stage_points(K)
            Jac = np.eye(s * m)
            for i in range(s):
                Ji = J(t + c[i] * h, Y[i])
                for j in range(s):
                    Jac[i * m:(i + 1) * m, j * m:(j + 1) * m] -= h * A[i, j] * Ji
            return Jac

        K, its = newton(residual, jacobian, K0, tol=self.tol, max_iter=self.max_iter, where="(stage equations)")
        return z + h * (b @ K.reshape(s, m)), its


class ImplicitMidpoint(_Gauss):
    """``z₁ = z₀ + h f(t + h/2, (z₀ + z₁)/2)`` — Gauss–Legendre with one stage, order 2."""

    name, order, stages = "midpoint", 2, 1


GaussLegendre2 = ImplicitMidpoint


class GaussLegendre4(_Gauss):
    name, order, stages = "gl4", 4, 2


class GaussLegendre6(_Gauss):
    name, order, stages = "gl6", 6, 3
