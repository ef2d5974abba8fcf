r"""Gonzalez' midpoint discrete gradient: energy-conserving to the solver tolerance.

``z₁ = z₀ + h 𝕁 ∇̄H(z₀, z₁)`` with

.. math:: \bar\nabla H(z_0, z_1) = \nabla H(\bar z) + \frac{H(z_1) - H(z_0) - \nabla H(\bar z)\cdot\Delta z}
          {|\Delta z|^2}\,\Delta z, \qquad \bar z = \tfrac12(z_0 + z_1),

so ``H(z₁) − H(z₀) = ∇̄H · Δz = 0`` exactly (O. Gonzalez, J. Nonlinear Sci. 6 (1996) 449–467;
McLachlan, Quispel & Robidoux, Phil. Trans. R. Soc. A 357 (1999)). Second order, symmetric, not
symplectic. For autonomous H only. The equations are solved by Newton with the midpoint Hessian as the
Jacobian (exact up to the O(|Δz|²) correction term), iterated to the round-off floor.
"""

from __future__ import annotations

import numpy as np

from ..errors import LagrangeError
from .base import Integrator, newton

__all__ = ["DiscreteGradient"]


class DiscreteGradient(Integrator):
    name, order, symplectic, energy_conserving = "dg", 2, False, True

    def check(self) -> None:
        if not self.model.autonomous:
            raise LagrangeError("the discrete gradient conserves energy of autonomous systems: H depends on t")

    def _dgrad(self, t, z0, z1):
        zm = 0.5 * (z0 + z1)
        g = self.model.grad(t, zm)
        d = z1 - z0
        dd = float(d @ d)
        if dd < 1e-300:
            return g
        return g + (self.model.H(t, z1) - self.model.H(t, z0) - float(g @ d)) / dd * d

    def _step_impl(self, t, z, h):
        n = self.model.n
        m = 2 * n

        def field(g):
            return np.concatenate([g[n:], -g[:n]])

        def residual(z1):
            return z1 - z - h * field(self._dgrad(t, z, z1))

        def jacobian(z1):
            return np.eye(m) - 0.5 * h * self.model.field_jacobian(t, 0.5 * (z + z1))

        z1 = z + h * self.model.field(t, z)
        z1, its = newton(residual, jacobian, z1, tol=self.tol, max_iter=self.max_iter, where="(discrete gradient)")
        return z1, its
