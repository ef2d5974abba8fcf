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
    ``A q̈ = c − 2α g − β² φ`` (Baumgarte 1972) with ``Stabilization("baumgarte", alpha=α, beta=β)``
    in 1/time units (default (10, 10)): the violation decays instead of growing, but never reaches round-off
    and α, β must suit the time scale.

``"none"``
    The plain index-1 system: the violation grows (roughly linearly in the velocity constraint and
    quadratically in positions) — shown in the tests.

Initial conditions are projected the same way (``project_initial=True``, default, with the change
recorded on the trajectory), or checked strictly (``project_initial=False``): an inconsistent state then
raises :class:`~lagrange.errors.InitialConditionError` naming the violated constraint and by how much.
"""

from __future__ import annotations

import importlib
import warnings

import numpy as np

from ..errors import InitialConditionError
from .options import STABILIZATIONS

__all__ = ["Projector", "consistent_initial", "STABILIZATIONS"]


def __getattr__(name: str):
    if name == "baumgarte_rhs":  # symbolic: code generation's (lagrange/integrate/__init__.py)
        warnings.warn("lagrange.integrate.constrained.baumgarte_rhs moved to lagrange.codegen.run_functions",
                      DeprecationWarning, stacklevel=2)
        return importlib.import_module("lagrange.codegen.run_functions").baumgarte_rhs
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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
