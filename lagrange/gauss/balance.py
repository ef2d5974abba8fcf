r"""Balance laws of mass-point systems as diagnostics along a run (Sonneveld 2015, §3.3, §4.5; R8).

For point masses with the external forces ``F_k`` (applied forces plus the forces of *external*
constraints — ground, surfaces, dragging points; internal link forces drop out):

.. math::

    \dot p = \sum_k F_k, \qquad \dot W = \sum_k \dot x_k\cdot F_k, \qquad
    \dot b = \sum_k x_k\times F_k,

with :math:`p = \sum m_k\dot x_k`, :math:`W = \sum\tfrac12 m_k|\dot x_k|^2`,
:math:`b = \sum m_k x_k\times\dot x_k` (about the origin). :func:`balance_residuals` integrates the right-hand
sides along a sampled run (cumulative Simpson rule) and reports the largest mismatch of each law, relative
to the size of the quantities involved — zero up to quadrature and integration error for a correct model.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import cumulative_simpson

from ..records import record

__all__ = ["momentum", "angular_momentum", "kinetic_energy", "BalanceReport", "balance_residuals",
           "point_balance"]


def _mv(masses, v):
    m = np.asarray(masses, dtype=float)
    v = np.asarray(v, dtype=float)
    return m, v.reshape(*v.shape[:-2], len(m), 3)


def momentum(masses, v) -> np.ndarray:
    """``p = Σ m_k ẋ_k``; ``v`` shape (..., N, 3) → (..., 3)."""
    m, v = _mv(masses, v)
    return np.einsum("k,...ki->...i", m, v)


def angular_momentum(masses, x, v) -> np.ndarray:
    """``b = Σ m_k x_k × ẋ_k`` about the origin; shapes (..., N, 3) → (..., 3)."""
    m, v = _mv(masses, v)
    return np.einsum("k,...ki->...i", m, np.cross(np.asarray(x, dtype=float).reshape(v.shape), v))


def kinetic_energy(masses, v) -> np.ndarray:
    """``W = Σ ½ m_k |ẋ_k|²``; ``v`` shape (..., N, 3) → (...)."""
    m, v = _mv(masses, v)
    return 0.5 * np.einsum("k,...ki,...ki->...", m, v, v)


@record(frozen=True)
class BalanceReport:
    """Largest relative residual of each balance law along a run.

    ``momentum``: ``max|p(t) − p(0) − ∫ΣF|``; ``energy``: ``max|W(t) − W(0) − ∫Σẋ·F|``;
    ``angular_momentum``: ``max|b(t) − b(0) − ∫Σx×F|`` — each divided by the largest size of the
    quantity or of its integrated source seen during the run.
    """

    momentum: float
    energy: float
    angular_momentum: float

    def ok(self, tol: float = 1e-6) -> bool:
        """True when all three residuals are below ``tol``."""
        return max(self.momentum, self.energy, self.angular_momentum) < tol

    def __str__(self) -> str:
        return (f"balance residuals (relative): momentum {self.momentum:.2e}, energy {self.energy:.2e}, "
                f"angular momentum {self.angular_momentum:.2e}")


def _residual(q, rate, t) -> float:
    src = cumulative_simpson(rate, x=t, axis=0, initial=0.0)
    res = q - q[0] - src
    scale = max(float(np.max(np.abs(q))), float(np.max(np.abs(src))), 1e-300)
    return float(np.max(np.abs(res))) / scale


def balance_residuals(t, masses, x, v, F_ext) -> BalanceReport:
    """Check ``ṗ = ΣF``, ``Ẇ = Σẋ·F``, ``ḃ = Σx×F`` along samples of a run.

    Parameters
    ----------
    t : (k,) sample times (at least 3; dense enough for Simpson's rule)
    masses : (N,)
    x, v, F_ext : (k, N, 3) positions, velocities and external forces at the samples
    """
    t = np.asarray(t, dtype=float)
    x, v, F = (np.asarray(a, dtype=float) for a in (x, v, F_ext))
    p = momentum(masses, v)
    W = kinetic_energy(masses, v)
    b = angular_momentum(masses, x, v)
    return BalanceReport(_residual(p, F.sum(axis=1), t),
                         _residual(W, np.einsum("kni,kni->k", v, F), t),
                         _residual(b, np.cross(x, F).sum(axis=1), t))


def point_balance(system, trajectory) -> BalanceReport:
    """:func:`balance_residuals` of a :class:`~lagrange.gauss.points.PointTrajectory` of ``system``, with
    the external forces (applied + external constraints) from the Gauss solve at every sample."""
    F = np.array([system.accelerations(ti, xi, vi).external_forces(system)
                  for ti, xi, vi in zip(trajectory.t, trajectory.x, trajectory.v)])
    return balance_residuals(trajectory.t, system.masses, trajectory.x, trajectory.v, F)
