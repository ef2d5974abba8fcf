r"""Störmer–Verlet (leapfrog) for separable Hamiltonians ``H = ½ pᵀM⁻¹p + V(q)`` with constant M.

``p_{½} = p₀ − (h/2)∇V(q₀)``, ``q₁ = q₀ + h M⁻¹p_{½}``, ``p₁ = p_{½} − (h/2)∇V(q₁)``: explicit, symplectic,
symmetric, order 2 (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, ch. I.3).
"""

from __future__ import annotations

import numpy as np

from .base import Integrator

__all__ = ["StormerVerlet"]


class StormerVerlet(Integrator):
    name, order, symplectic, requires = "verlet", 2, True, "separable"

    def _step_impl(self, t, z, h):
        n = self.model.n
        g = self.model.grad
        q, p = z[:n].copy(), z[n:].copy()
        p -= 0.5 * h * g(t, np.concatenate([q, p]))[:n]
        q += h * g(t, np.concatenate([q, p]))[n:]  # ∂H/∂p = M⁻¹p (independent of q when separable)
        p -= 0.5 * h * g(t + h, np.concatenate([q, p]))[:n]
        return np.concatenate([q, p]), 0
