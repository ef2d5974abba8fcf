r"""Constrained motion numerics: consistent initial conditions, drift control, violation reports.

The index-1 system ``M q̈ = f + Aᵀλ``, ``A q̈ = c`` keeps the constraints only at the acceleration level;
numerically the positions and velocities drift off ``φ = 0`` and ``A q̇ + b = 0``. Two remedies
(``simulate(stabilization=...)``):

``"projection"`` (default)
    After every accepted step the state is projected back: positions by Gauss–Newton on the holonomic
    constraints, ``Δq = −Aₕᵀ(AₕAₕᵀ)⁻¹φ`` (the smallest correction), then velocities onto
    ``A q̇ + b = 0``. Parameter-free; keeps the violation at round-off. Works with RK23, RK45, DOP853
    and Radau (one-step methods); with BDF/LSODA Baumgarte is used instead.

``"baumgarte"``
    ``A q̈ = c − 2α g − β² φ`` (Baumgarte 1972) with ``baumgarte=(α, β)`` in 1/time units (default
    (10, 10)): the violation decays instead of growing, but never reaches round-off and α, β must suit
    the time scale.

``"none"``
    The plain index-1 system: the violation grows (roughly linearly in the velocity constraint and
    quadratically in positions) — shown in the tests.

Initial conditions are projected the same way (``project_initial=True``, default, with the change
recorded on the trajectory), or checked strictly (``project_initial=False``): an inconsistent state then
raises :class:`~lagrange.errors.InitialConditionError` naming the violated constraint and by how much.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ..derive.equations import Equations
from ..errors import InitialConditionError

__all__ = ["baumgarte_rhs", "Projector", "consistent_initial", "STABILIZATIONS"]

STABILIZATIONS = ("projection", "baumgarte", "none")


def baumgarte_rhs(eqs: Equations, alpha: float, beta: float) -> list:
    """``c_k − 2α g_k − β² φ_k`` (φ term only for holonomic constraints), in plain symbols."""
    qd = sp.Matrix(eqs.qd)
    out = []
    for k in range(eqs.m):
        g = (eqs.constraint_matrix[k, :] * qd)[0, 0] + eqs.constraint_bias[k]
        e = eqs.constraint_rhs[k] - 2 * sp.Float(alpha) * g
        if eqs.constraint_positions[k] is not None:
            e -= sp.Float(beta) ** 2 * eqs.constraint_positions[k]
        out.append(e)
    return out


class Projector:
    """Projects states onto the constraint manifold (positions, then velocities)."""

    def __init__(self, constraint_functions, n: int, tol: float = 1e-13, max_iter: int = 8):
        self.cf = constraint_functions
        self.n = n
        self.tol = tol
        self.max_iter = max_iter

    def positions(self, t: float, q: np.ndarray) -> tuple[np.ndarray, float]:
        """Gauss–Newton onto φ(q, t) = 0; returns (q, final max |φ|)."""
        cf = self.cf
        if not cf.holonomic:
            return q, 0.0
        q = np.array(q, dtype=float)
        scale = 1.0 + float(np.max(np.abs(q)))
        r = cf.phi(t, q)
        for _ in range(self.max_iter):
            if np.max(np.abs(r)) <= self.tol * scale:
                break
            Ah = cf.holonomic_matrix(t, q)
            q = q - Ah.T @ np.linalg.lstsq(Ah @ Ah.T, r, rcond=None)[0]
            r = cf.phi(t, q)
        return q, float(np.max(np.abs(r)))

    def velocities(self, t: float, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        A = self.cf.matrix(t, q)
        g = A @ qd + self.cf.bias(t, q)
        return qd - A.T @ np.linalg.lstsq(A @ A.T, g, rcond=None)[0]

    def __call__(self, t: float, z: np.ndarray) -> np.ndarray:
        """Project the state part of ``z`` (a trailing work integral, if any, is left alone)."""
        n = self.n
        z = np.array(z, dtype=float)
        q, _ = self.positions(t, z[:n])
        z[:n] = q
        z[n : 2 * n] = self.velocities(t, q, z[n : 2 * n])
        return z


def consistent_initial(model, t0: float, y0: np.ndarray, project: bool) -> tuple[np.ndarray, dict]:
    """A state on the constraint manifold, and a report ``{constraint: (position, velocity violation)}``
    of the user's state. Raises InitialConditionError when strict and violated, or when projection
    fails to converge."""
    cf = model.constraint_functions
    n = model.n
    names = model.equations.constraint_names
    q, qd = y0[:n], y0[n:]
    pos = np.zeros(model.m)
    if cf.holonomic:
        pos[cf.holonomic] = cf.phi(t0, q)
    vel = cf.matrix(t0, q) @ qd + cf.bias(t0, q)
    report = {names[k]: (float(pos[k]), float(vel[k])) for k in range(model.m)}
    scale = 1.0 + float(np.max(np.abs(y0)))
    bad = [k for k in range(model.m) if abs(pos[k]) > 1e-10 * scale or abs(vel[k]) > 1e-10 * scale]
    if not bad:
        return y0, report
    if not project:
        detail = "; ".join(f"{names[k]}: φ = {pos[k]:.3g}, A q̇ + b = {vel[k]:.3g}" for k in bad)
        raise InitialConditionError(
            f"initial state violates the constraints ({detail}); fix it or pass project_initial=True"
        )
    proj = Projector(cf, n)
    q1, resid = proj.positions(t0, q)
    if resid > 1e-9 * scale:
        raise InitialConditionError(
            f"cannot project the initial positions onto the constraints (remaining |φ| = {resid:.3g}): "
            f"{', '.join(names[k] for k in bad)} may be inconsistent or the guess too far off"
        )
    return np.concatenate([q1, proj.velocities(t0, q1, qd)]), report
