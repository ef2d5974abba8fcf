r"""Collisions ("transactions", Sonneveld 2015 §2.3, §3): smooth balls and impacts on constructions.

The paper fixes only the balance laws of a collision — momentum is conserved, eq. (10), and kinetic
energy does not increase, eq. (11). The closures used here are the standard ones consistent with them:

* **Smooth balls** (impulse along the contact normal ``n``, the exterior normal of ball 1 at the contact
  point; R9), restitution ``e ∈ [0, 1]`` (``e = 1`` is the paper's ideal collision):

  .. math:: v_n = (v_1 - v_2)\cdot n > 0, \quad
            v_1' = v_1 - \frac{(1+e) m_2}{m_1+m_2} v_n n, \quad
            v_2' = v_2 + \frac{(1+e) m_1}{m_1+m_2} v_n n, \quad
            \Delta W = -\tfrac12\frac{m_1 m_2}{m_1+m_2}(1-e^2)v_n^2 .

* **Impacts on mass-point constructions** (R10, the velocity-level reading of least frustration): the
  post-impact velocities minimise the kinetic distance :math:`\tfrac12\|v'-v\|_M^2` subject to the contact
  rows ``A_c v' = −e A_c v`` (``A_c`` the gradients of the gap functions, closing when ``A_c v < 0``) and
  the construction's own rows ``A_k v' = A_k v`` (links stay rigid). With ``e = 0`` this is the
  perfectly plastic constraint impulse ``v' = v − M⁻¹Aᵀ(AM⁻¹Aᵀ)⁻¹A v``.

Every outcome reports its momentum change (zero when all rows are internal) and its energy change, and
an outcome that would create kinetic energy raises :class:`~lagrange.errors.CollisionError`.
"""

from __future__ import annotations

import numpy as np

from ..errors import CollisionError
from ..records import record
from .balance import kinetic_energy, momentum
from .kkt import solve_least_constraint

__all__ = ["CollisionOutcome", "ball_collision", "contact_row", "impact"]


@record(frozen=True)
class CollisionOutcome:
    """Velocities after the collision ``velocities`` (N, 3), the impulses ``m Δv`` (N, 3), the total
    ``momentum_change`` (3,) and ``energy_change`` (≤ 0)."""

    velocities: np.ndarray
    impulses: np.ndarray
    momentum_change: np.ndarray
    energy_change: float


def _outcome(masses, v, v_new) -> CollisionOutcome:
    m = np.asarray(masses, dtype=float)
    dW = float(kinetic_energy(m, v_new) - kinetic_energy(m, v))
    W = float(kinetic_energy(m, v))
    if dW > 1e-12 * max(W, 1e-300):
        raise CollisionError(f"the collision would create kinetic energy (ΔW = {dW:.3g} > 0): restitution along "
                             "several contact rows at once can do that; use e = 0 or one contact at a time")
    return CollisionOutcome(v_new, m[:, None] * (v_new - v), momentum(m, v_new) - momentum(m, v), dW)


def _check_e(e: float) -> float:
    e = float(e)
    if not 0.0 <= e <= 1.0:
        raise CollisionError(f"restitution coefficient e = {e} must lie in [0, 1] (1: ideal, 0: plastic)")
    return e


def ball_collision(m1: float, m2: float, v1, v2, n, e: float = 1.0) -> CollisionOutcome:
    """Collision of two smooth balls with contact normal ``n`` (from ball 1 towards ball 2) — R9.

    Raises
    ------
    CollisionError
        When the balls are not approaching (``(v1 − v2)·n ≤ 0``) or ``e`` is outside [0, 1].

    Examples
    --------
    Identical balls, central ideal collision (E1): the velocities are exchanged.

    >>> ball_collision(1, 1, (3, 0, 0), (-1, 0, 0), (1, 0, 0)).velocities.tolist()
    [[-1.0, 0.0, 0.0], [3.0, 0.0, 0.0]]
    """
    e = _check_e(e)
    n = np.asarray(n, dtype=float)
    n = n / np.linalg.norm(n)
    v1, v2 = np.asarray(v1, dtype=float), np.asarray(v2, dtype=float)
    vn = float((v1 - v2) @ n)
    if vn <= 0:
        raise CollisionError(f"no collision: the balls are not approaching along n ((v1 − v2)·n = {vn:.3g} ≤ 0)")
    k = (1 + e) * vn / (m1 + m2)
    new = np.array([v1 - k * m2 * n, v2 + k * m1 * n])
    return _outcome([m1, m2], np.array([v1, v2]), new)


def contact_row(n_points: int, i: int, j: int | None, normal) -> np.ndarray:
    """Gradient of the gap between point ``i`` and point ``j`` (or a fixed obstacle when ``j`` is None)
    along ``normal`` (pointing from i towards j): ``−n`` at i, ``+n`` at j; shape (3N,)."""
    n = np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    row = np.zeros(3 * n_points)
    row[3 * i:3 * i + 3] = -n
    if j is not None:
        row[3 * j:3 * j + 3] = n
    return row


def impact(masses, v, contact_rows, *, e: float = 0.0, keep_rows=None, names=None) -> CollisionOutcome:
    """Impulsive impact on a mass-point construction by the mass-metric projection (R10).

    Parameters
    ----------
    masses : (N,)
    v : (N, 3) velocities before
    contact_rows : (k, 3N) gap gradients of the closing contacts (:func:`contact_row`)
    e : restitution along the contact rows, in [0, 1]
    keep_rows : (j, 3N) rows the impulse must respect, e.g. the link rows ``A`` of the construction
    names : labels of all rows (contacts first), for error messages

    Raises
    ------
    CollisionError
        If a contact is not closing, ``e`` is outside [0, 1], or the result would gain energy.
    """
    e = _check_e(e)
    m = np.asarray(masses, dtype=float)
    v = np.asarray(v, dtype=float).reshape(len(m), 3)
    Ac = np.atleast_2d(np.asarray(contact_rows, dtype=float))
    closing = Ac @ v.ravel()
    if np.any(closing >= 0):
        raise CollisionError(f"contact row(s) {np.flatnonzero(closing >= 0).tolist()} are not closing "
                             "(gap rate ≥ 0): no impact there")
    Ak = np.zeros((0, Ac.shape[1])) if keep_rows is None else np.atleast_2d(np.asarray(keep_rows, dtype=float))
    C = np.vstack([Ac, Ak])
    d = np.concatenate([-e * closing, Ak @ v.ravel()])
    Mv = np.repeat(m, 3)
    sol = solve_least_constraint(np.diag(Mv), Mv * v.ravel(), C, d, names=names)
    return _outcome(m, v, sol.z.reshape(len(m), 3))
