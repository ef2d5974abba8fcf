r"""The least-constraint quadratic program and its KKT system, solved in a rank-revealing way.

Gauss' principle (Sonneveld 2015, eqs. (27)–(32), (64)) asks for the minimiser of a convex quadratic
under linear equality constraints,

.. math::

    \min_z\ \tfrac12 z^{\mathsf T} H z - g^{\mathsf T} z \quad\text{s.t.}\quad C z = d,
    \qquad
    \begin{bmatrix} H & -C^{\mathsf T} \\ -C & 0 \end{bmatrix}
    \begin{bmatrix} z \\ \lambda \end{bmatrix} = \begin{bmatrix} g \\ -d \end{bmatrix},

so that ``H z = g + Cᵀλ`` (the library's sign convention ``M q̈ = f + Aᵀλ``). With ``H = M`` (masses),
``g = F`` (applied forces) and ``C z = d`` the twice-differentiated constraints this is Gauss'
:math:`Z = \sum_k \tfrac12 m_k |\ddot x_k - F_k/m_k|^2` up to a constant.

The KKT system is solved through the singular value decomposition of the (row-equilibrated) constraint
matrix — the null-space method — because that is what reveals the two situations Sonneveld's Lemma 7
distinguishes:

* **redundant but consistent** rows (a rigid point cloud with all its links): ``z`` is unique, λ is not
  (the minimum-norm λ is returned and :attr:`LeastConstraintSolution.redundant` counts the dependent rows);
* **inconsistent** rows (a jammed mechanism, ``d ∉ range(C)``): no ``z`` exists and
  :class:`~lagrange.errors.InconsistentConstraintError` names the constraints involved.

``H`` may be only semi-definite (Gibbs–Appell form with generalized coordinates): ``z`` is unique when
``H`` is definite on the null space of ``C``; otherwise :class:`~lagrange.errors.SingularMassMatrixError`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import InconsistentConstraintError, SingularMassMatrixError
from ..records import record

__all__ = ["LeastConstraintSolution", "solve_least_constraint", "RANK_TOL", "CONSISTENCY_TOL"]

#: Singular values of the row-normalised constraint matrix below ``RANK_TOL·σ_max`` count as zero.
RANK_TOL = 1e-10
#: Constraint residual, relative to the size of the problem, above which the rows are inconsistent.
CONSISTENCY_TOL = 1e-8


@record(frozen=True, slots=True)
class LeastConstraintSolution:
    """Minimiser of the least-constraint program.

    Attributes
    ----------
    z : ndarray, shape (n,) — the unique minimiser (accelerations)
    multipliers : ndarray, shape (m,) — the minimum-norm λ with ``H z = g + Cᵀλ``
    rank : int — rank of the constraint matrix
    redundant : int — number of dependent constraint rows (``m − rank``); λ is non-unique when > 0
    residual : float — ``|C z − d|`` relative to the problem's scale (round-off size when consistent)
    """

    z: np.ndarray
    multipliers: np.ndarray
    rank: int
    redundant: int
    residual: float

    @property
    def multipliers_unique(self) -> bool:
        """True when no constraint row is redundant (then λ is unique)."""
        return self.redundant == 0


def _involved(w: np.ndarray, names: Sequence[str]) -> list[str]:
    big = np.abs(w) > 1e-6 * max(float(np.max(np.abs(w))), 1e-300)
    return [names[i] for i in np.flatnonzero(big)]


def solve_least_constraint(H, g, C, d, *, names: Sequence[str] | None = None,
                           consistency_tol: float = CONSISTENCY_TOL,
                           require_minimum: bool = True) -> LeastConstraintSolution:
    r"""Solve ``min ½ zᵀHz − gᵀz`` subject to ``C z = d`` (the KKT system above).

    Parameters
    ----------
    H : array, shape (n, n) — symmetric, positive semi-definite (definite on the null space of C)
    g : array, shape (n,)
    C : array, shape (m, n) — may be rank deficient (redundant constraints); m may be 0
    d : array, shape (m,)
    names : one label per constraint row, used in error messages (default ``row 1``, …)
    consistency_tol : relative residual above which the constraints are declared inconsistent
    require_minimum : demand ``H`` definite on the null space of C (a true minimum). ``False`` accepts any
        non-singular reduced ``H`` and returns the stationary point (non-physical, e.g. indefinite, inertia
        data still have well-defined Lagrange equations to compare with)

    Returns
    -------
    LeastConstraintSolution

    Raises
    ------
    InconsistentConstraintError
        ``d`` is not in the range of ``C`` (kinematically inconsistent, e.g. jammed); the message and
        ``.constraints`` name the rows involved.
    SingularMassMatrixError
        ``H`` is singular (or, with ``require_minimum``, not positive definite) on the null space of ``C``.

    Examples
    --------
    A unit mass pulled by F = (0, −1) on the line y = 0 (C = [0, 1], d = 0):

    >>> s = solve_least_constraint(np.eye(2), [0.0, -1.0], [[0.0, 1.0]], [0.0])
    >>> s.z.round(12).tolist(), s.multipliers.round(12).tolist()
    ([0.0, 0.0], [1.0])
    """
    H = np.atleast_2d(np.asarray(H, dtype=float))
    g = np.asarray(g, dtype=float).ravel()
    n = H.shape[0]
    C = np.asarray(C, dtype=float).reshape(-1, n)
    d = np.asarray(d, dtype=float).ravel()
    m = C.shape[0]
    names = list(names) if names is not None else [f"row {i + 1}" for i in range(m)]
    hscale = max(float(np.max(np.abs(np.diag(H)))) if n else 0.0, 1e-300)
    if m == 0:
        return _unconstrained(H, g, n)
    s = np.linalg.norm(C, axis=1)
    zero = s == 0
    s[zero] = 1.0
    Cs, ds = C / s[:, None], d / s
    U, S, Vt = np.linalg.svd(Cs)
    r = int(np.sum(S > RANK_TOL * max(S[0] if S.size else 0.0, 1e-300)))
    Ur, Sr, Vr = U[:, :r], S[:r], Vt[:r]
    z_p = Vr.T @ ((Ur.T @ ds) / Sr) if r else np.zeros(n)
    scale = max(float(np.linalg.norm(ds)), float(np.linalg.norm(g)) / hscale, float(np.linalg.norm(z_p)), 1e-300)
    w = U[:, r:] @ (U[:, r:].T @ ds)  # part of d outside the range of C
    residual = float(np.linalg.norm(w)) / scale
    if residual > consistency_tol:
        involved = _involved(w, names)
        raise InconsistentConstraintError(
            f"the constraints {', '.join(involved)} are kinematically inconsistent (jammed): no acceleration "
            f"satisfies them all (relative residual {residual:.2e}); remove or correct one of them",
            constraints=involved,
        )
    N = Vt[r:].T
    if N.shape[1]:
        Hr = N.T @ H @ N
        ev = np.linalg.eigvalsh(Hr)
        low = ev[0] if require_minimum else float(np.min(np.abs(ev)))
        if low <= 1e-12 * max(float(np.max(np.abs(ev))), hscale):
            raise SingularMassMatrixError(
                "the accelerations are not determined: the mass matrix is singular on the motions the "
                f"constraints allow (smallest reduced eigenvalue {ev[0]:.3g}); give every moving point mass "
                "or add the missing constraint"
            )
        z = z_p + N @ np.linalg.solve(Hr, N.T @ (g - H @ z_p))
    else:
        z = z_p
    lam_s = Ur @ ((Vr @ (H @ z - g)) / Sr) if r else np.zeros(m)
    return LeastConstraintSolution(z, lam_s / s, r, m - r, residual)


def _unconstrained(H, g, n) -> LeastConstraintSolution:
    try:
        ev = np.linalg.eigvalsh(H) if n else np.ones(1)
        if ev[0] <= 1e-12 * max(float(ev[-1]), 1e-300):
            raise np.linalg.LinAlgError
        z = np.linalg.solve(H, g) if n else np.zeros(0)
    except np.linalg.LinAlgError:
        raise SingularMassMatrixError(
            "the accelerations are not determined: the mass matrix is singular (a massless point or a "
            "coordinate that moves no mass)"
        ) from None
    return LeastConstraintSolution(z, np.zeros(0), 0, 0, 0.0)
