r"""Why the generated solve failed at a state: the cause computed from the numbers at that state.

The generated right-hand side solves ``M q̈ = f`` — with constraints the augmented
``(M + AᵀA) q̈ = f + Aᵀc + Bλ`` (:mod:`lagrange.codegen.cse`) — by an unrolled LDLᵀ whose pivot test
(:mod:`lagrange.codegen.source`) raises on a pivot that is not positive. That test fails for three different
reasons, told apart by :func:`diagnose` at the state of the failure:

``"dependent"``
    The constraint Jacobian ``A`` (m × n, rows scaled to unit length: a constraint times a constant is the same
    constraint) has rank below m: the constraints with a component in its left null space are redundant here.
``"mass"``
    The mass matrix is singular (or not positive definite) on the motions the constraints allow: ``NᵀMN``, with
    ``N`` an orthonormal basis of the null space of ``A`` (``N = I`` without constraints), has an eigenvalue
    ≤ :data:`RANK_RTOL` times the largest eigenvalue of ``M``. The coordinates involved are those of its
    eigenvector ``N v``. (``M`` itself may be singular while ``NᵀMN`` is not — coordinates that carry no
    inertia of their own but are fixed by a constraint: then the configuration is regular.)
``"ill-conditioned"``
    Neither: the configuration is regular and the solve failed for scale — ``AᵀA`` far larger than ``M``, as
    at a trial state far off the constraint manifold. An adaptive run rejects such a trial step and shrinks it
    (:func:`lagrange.integrate.scipy_ivp.state_function`); it is never reported as a singular mass matrix.

Ranks are numerical: a singular value of the row-scaled ``A`` below :data:`RANK_RTOL` times the largest counts
as zero.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["diagnose", "RANK_RTOL"]

#: relative threshold below which a singular value (of the row-scaled A) or an eigenvalue (of NᵀMN, relative to
#: the largest of M) counts as zero: ten times the generated pivot test's 1e-13
RANK_RTOL = 1e-12

#: a coordinate (or constraint) is named as involved when its component in the unit null vector exceeds this
INVOLVED = 1e-6


def diagnose(M: np.ndarray, A: np.ndarray | None, coordinates: Sequence[str],
             constraints: Sequence[str] = (), where: str = "") -> tuple[str, str]:
    """``(kind, text)``: the cause (module docstring) of a failed solve with mass matrix ``M`` (n × n) and
    constraint Jacobian ``A`` (m × n, or None / m = 0), ``text`` naming the coordinates or constraints involved
    and the ranks (``where``, e.g. ``"at t=1 (x=0)"``, placed after its subject); ``kind`` is ``"dependent"``,
    ``"mass"`` or ``"ill-conditioned"``."""
    at = f" {where}" if where else ""
    M = np.asarray(M, dtype=float)
    n = M.shape[0]
    A = np.zeros((0, n)) if A is None else np.asarray(A, dtype=float).reshape(-1, n)
    m = A.shape[0]
    N = np.eye(n)
    rank_a = 0
    if m:
        norms = np.linalg.norm(A, axis=1)
        scaled = A / np.where(norms > 0, norms, 1.0)[:, None]
        U, s, Vt = np.linalg.svd(scaled)
        rank_a = int(np.sum(s > RANK_RTOL * max(s.max(initial=0.0), 1e-300))) if s.size else 0
        if rank_a < m:
            left = U[:, rank_a:]  # left null space: combinations of rows that vanish
            named = [constraints[i] for i in range(m) if np.max(np.abs(left[i])) > INVOLVED]
            return "dependent", (f"the constraints {', '.join(named)} are dependent{at}: the constraint Jacobian has "
                                 f"rank {rank_a} < {m}. Remove redundant constraints")
        N = Vt[rank_a:].T
    w_m = np.linalg.eigvalsh((M + M.T) / 2)
    scale = max(float(np.max(np.abs(w_m))), 1e-300)
    rank_m = int(np.sum(w_m > RANK_RTOL * scale))
    free = n - rank_a
    ranks = f"mass matrix rank {rank_m} of {n}"
    if m:
        ranks += f", constraint Jacobian rank {rank_a} of {m}"
    if free:
        w, v = np.linalg.eigh(N.T @ ((M + M.T) / 2) @ N)
        if w[0] <= RANK_RTOL * scale:
            direction = N @ v[:, 0]
            involved = [c for c, comp in zip(coordinates, direction) if abs(comp) > INVOLVED]
            allowed = f"on the {free} motions the constraints allow, " if m else ""
            sign = ("negative: the kinetic energy is negative for this motion" if w[0] < -RANK_RTOL * scale
                    else "zero to round-off")
            return "mass", (f"the mass matrix is singular{at} ({allowed}smallest eigenvalue {w[0]:.3g}, {sign}; "
                            f"{ranks}), coordinates involved: {', '.join(involved)}. A massless point or a coordinate "
                            "that does not appear in T gives no inertia: eliminate it (statics) or give it mass")
    try:
        cond = float(np.linalg.cond(M + A.T @ A))
    except np.linalg.LinAlgError:
        cond = float("inf")
    definite = ", positive definite on the allowed motions" if m else ""
    matrix = "M + AᵀA" if m else "M"
    return "ill-conditioned", (f"the configuration{at} is regular ({ranks}{definite}) but the solve is "
                               f"ill-conditioned (condition number of {matrix} {cond:.3g}): the state is far off the "
                               "constraint manifold, or the scales of the masses and of the constraints differ by "
                               "many orders of magnitude (rescale the constraints or the units)")
