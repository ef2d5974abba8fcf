r"""Symmetric compositions of Störmer–Verlet: explicit symplectic methods of order 6 and 8 for separable
Hamiltonians ``H = ½ pᵀM⁻¹p + V(q)`` with constant M.

One step of size h is ``Φ_{γ_s h} ∘ … ∘ Φ_{γ_1 h}`` with Φ the Störmer–Verlet step
(:mod:`~lagrange.integrate.stormer_verlet`) and palindromic coefficients ``γ_i = γ_{s+1−i}``, ``Σ γ_i = 1``
that cancel the error terms up to the order claimed (Hairer, Lubich & Wanner, *Geometric Numerical
Integration*, 2nd ed., Sect. V.3.2, Table 3.1 and eq. (3.11)):

* ``verlet6`` — Kahan & Li's ``s9odr6a``: 9 stages, order 6 (W. Kahan and R.-C. Li, *Math. Comp.* 66 (1997)
  1089–1099);
* ``verlet8`` — ``s15odr8``: 15 stages, order 8 (R. I. McLachlan, *SIAM J. Sci. Comput.* 16 (1995) 151–168;
  found independently by Suzuki & Umeno, 1993).

Like Verlet they are explicit (no Newton iteration), symplectic and time-symmetric, so the energy error stays
bounded over long times; a step costs one evaluation of ∇V per stage (adjacent half kicks share their force)
and one of ``M⁻¹p`` per stage. They suit long runs of separable problems at moderate accuracy; for accuracy at
machine precision over long runs the adaptive Taylor methods are cheaper (see ``benchmarks/results/longrun.md``).
"""

from __future__ import annotations

import numpy as np

from .stormer_verlet import StormerVerlet

__all__ = ["COEFFICIENTS", "KahanLi6", "McLachlan8"]


def _palindrome(half: list[float]) -> np.ndarray:
    """The full coefficient sequence ``γ_1 … γ_s`` from its first ``(s + 1)/2`` entries."""
    return np.array(half + half[-2::-1])


#: name → γ_1 … γ_s (HLW, Sect. V.3.2; 20 digits as published)
COEFFICIENTS = {
    "verlet6": _palindrome([0.39216144400731413928, 0.33259913678935943860, -0.70624617255763935981,
                            0.08221359629355080023, 0.79854399093482996340]),
    "verlet8": _palindrome([0.74167036435061295345, -0.40910082580003159400, 0.19075471029623837995,
                            -0.57386247111608226666, 0.29906418130365592384, 0.33462491824529818378,
                            0.31529309239676659663, -0.79688793935291635402]),
}


class _Composition(StormerVerlet):
    """Composition of Störmer–Verlet steps of sizes ``γ_i h``: a separable H is required (as for Verlet)."""

    symplectic = True

    @property
    def gammas(self) -> np.ndarray:
        return COEFFICIENTS[self.name]

    def _step_impl(self, t, z, h):
        tau = t
        for gamma in self.gammas:
            z, _ = super()._step_impl(tau, z, gamma * h)
            tau += gamma * h
        return z, 0


class KahanLi6(_Composition):
    """Kahan–Li ``s9odr6a``: 9 Verlet stages, order 6."""

    name, order = "verlet6", 6


class McLachlan8(_Composition):
    """``s15odr8`` (McLachlan; Suzuki–Umeno): 15 Verlet stages, order 8."""

    name, order = "verlet8", 8
