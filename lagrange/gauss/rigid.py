r"""A rigid body as a point cloud with every pair linked, and its reduction to Euler's equations.

Sonneveld (2015, §5): a rigid body of N mass points carries all ``N(N−1)/2`` distance constraints —
most of them redundant — and Gauss' principle still gives unique accelerations
(:class:`~lagrange.gauss.points.PointSystem` with :class:`~lagrange.gauss.points.Link` rows, solved by SVD).
Resolving the constraints through the centre of mass ``x_c`` and the angular velocity ω gives
Newton–Euler in the space frame,

.. math::

    M\ddot x_c = \sum_k F_k, \qquad J\dot\omega + \omega\times J\omega = \sum_k r_k\times F_k,
    \qquad J = \sum_k m_k(|r_k|^2 I - r_k r_k^{\mathsf T}),

with ``r_k = x_k − x_c`` and ``ẍ_k = ẍ_c + ω̇ × r_k + ω × (ω × r_k)`` (eqs. (68)–(74)). Both routes are
implemented here so that they can be compared (test E19); :func:`integrate_rigid_body` integrates the
space-frame form with ``Q̇ = Ω Q`` (E20, no Euler angles).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

import numpy as np
from scipy.integrate import solve_ivp

from ..records import record
from .points import Link, PointSystem

__all__ = ["cloud_inertia", "rigid_cloud", "rigid_velocities", "angular_velocity", "newton_euler_accelerations",
           "RigidMotion", "integrate_rigid_body", "skew"]


def skew(w) -> np.ndarray:
    """The matrix ``[w]×`` with ``[w]× b = w × b`` (Sonneveld eq. (2))."""
    w1, w2, w3 = np.asarray(w, dtype=float)
    return np.array([[0.0, -w3, w2], [w3, 0.0, -w1], [-w2, w1, 0.0]])


def _com(masses, x) -> tuple[np.ndarray, np.ndarray, float]:
    m = np.asarray(masses, dtype=float)
    x = np.asarray(x, dtype=float).reshape(len(m), 3)
    M = float(m.sum())
    xc = m @ x / M
    return m, x - xc, M


def cloud_inertia(masses: Sequence[float], x) -> np.ndarray:
    """Inertia tensor of point masses about their centre of mass, ``Σ m (|r|² I − r rᵀ)`` (3, 3).

    >>> cloud_inertia([1, 1, 1, 1], [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]]).diagonal().tolist()
    [2.0, 2.0, 4.0]
    """
    m, r, _ = _com(masses, x)
    return np.einsum("k,kij->ij", m, np.einsum("ki,ki->k", r, r)[:, None, None] * np.eye(3)
                     - np.einsum("ki,kj->kij", r, r))


def rigid_cloud(masses: Sequence[float], x, *, forces=None, gravity=None) -> PointSystem:
    """A :class:`PointSystem` with a :class:`Link` between every pair of points (at their current
    distances): the brute-force rigid body, redundant for N > 4."""
    x = np.asarray(x, dtype=float).reshape(len(masses), 3)
    links = [Link(i, j, float(np.linalg.norm(x[j] - x[i])), f"link {i}-{j}")
             for i, j in itertools.combinations(range(len(masses)), 2)]
    return PointSystem(tuple(masses), tuple(links), forces=forces, gravity=tuple(gravity) if gravity else None)


def rigid_velocities(masses, x, v_c, omega) -> np.ndarray:
    """Point velocities ``v_c + ω × r_k`` of a rigid motion (eq. (68)), shape (N, 3)."""
    _, r, _ = _com(masses, x)
    return np.asarray(v_c, dtype=float) + np.cross(np.asarray(omega, dtype=float), r)


def angular_velocity(masses, x, v) -> np.ndarray:
    """ω of a rigid motion from its point velocities: ``J ω = Σ m r × v`` (the angular momentum about
    the centre of mass, eq. (72))."""
    m, r, _ = _com(masses, x)
    v = np.asarray(v, dtype=float).reshape(len(m), 3)
    H = np.einsum("k,ki->i", m, np.cross(r, v - m @ v / m.sum()))
    return np.linalg.lstsq(cloud_inertia(masses, x), H, rcond=1e-12)[0]


def newton_euler_accelerations(masses, x, v, F) -> np.ndarray:
    """Point accelerations of the rigid body from Newton–Euler: ``M ẍ_c = ΣF``,
    ``J ω̇ + ω × Jω = Σ r × F``, ``ẍ_k = ẍ_c + ω̇ × r_k + ω × (ω × r_k)``; shape (N, 3)."""
    m, r, M = _com(masses, x)
    F = np.asarray(F, dtype=float).reshape(len(m), 3)
    J = cloud_inertia(masses, x)
    w = angular_velocity(masses, x, v)
    L = np.cross(r, F).sum(axis=0)
    wd = np.linalg.lstsq(J, L - np.cross(w, J @ w), rcond=1e-12)[0]
    return F.sum(axis=0) / M + np.cross(wd, r) + np.cross(w, np.cross(w, r))


@record(frozen=True)
class RigidMotion:
    """A rigid-body motion: ``t`` (k,), orientation ``Q`` (k, 3, 3) (body → space), space-frame ``omega``
    (k, 3), angular momentum about the centre of mass ``H = J ω`` (k, 3), centre ``x_c`` and ``v_c`` (k, 3)."""

    t: np.ndarray
    Q: np.ndarray
    omega: np.ndarray
    H: np.ndarray
    x_c: np.ndarray
    v_c: np.ndarray

    def body_omega(self) -> np.ndarray:
        """ω along the body axes, ``Qᵀ ω`` (k, 3)."""
        return np.einsum("kji,kj->ki", self.Q, self.omega)


def integrate_rigid_body(mass: float, J0, t_eval, *, Q0=None, omega0=(0, 0, 0), x_c0=(0, 0, 0), v_c0=(0, 0, 0),
                         force: Callable | None = None, torque: Callable | None = None,
                         rtol: float = 1e-11, atol: float = 1e-12) -> RigidMotion:
    r"""Integrate Newton–Euler in the space frame (Sonneveld §5.2):
    ``M ẍ_c = F``, ``J(t) ω̇ + ω × J ω = L``, ``J(t) = Q J₀ Qᵀ``, ``Q̇ = [ω]× Q``.

    Parameters
    ----------
    mass : M
    J0 : inertia about the centre of mass along the body axes (3, 3)
    t_eval : output times (the first is the initial time)
    Q0 : initial orientation (default identity); omega0 : initial ω in the space frame
    force, torque : callables ``(t, x_c, v_c, Q, ω) -> 3-vector`` (default zero)
    """
    J0 = np.asarray(J0, dtype=float)
    Q0 = np.eye(3) if Q0 is None else np.asarray(Q0, dtype=float)
    zero = np.zeros(3)

    def rhs(t, y):
        xc, vc, Q, w = y[:3], y[3:6], y[6:15].reshape(3, 3), y[15:18]
        F = zero if force is None else np.asarray(force(t, xc, vc, Q, w), dtype=float)
        L = zero if torque is None else np.asarray(torque(t, xc, vc, Q, w), dtype=float)
        J = Q @ J0 @ Q.T
        wd = np.linalg.solve(J, L - np.cross(w, J @ w))
        return np.concatenate([vc, F / mass, (skew(w) @ Q).ravel(), wd])

    t_eval = np.asarray(t_eval, dtype=float)
    y0 = np.concatenate([x_c0, v_c0, Q0.ravel(), omega0]).astype(float)
    sol = solve_ivp(rhs, (t_eval[0], t_eval[-1]), y0, method="DOP853", t_eval=t_eval, rtol=rtol, atol=atol)
    Y = sol.y.T
    Q = Y[:, 6:15].reshape(-1, 3, 3)
    w = Y[:, 15:18]
    H = np.einsum("kij,kj->ki", Q @ J0 @ np.transpose(Q, (0, 2, 1)), w)
    return RigidMotion(sol.t, Q, w, H, Y[:, :3], Y[:, 3:6])
