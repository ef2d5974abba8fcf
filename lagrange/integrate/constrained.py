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

Initial conditions (:func:`consistent_initial`)
    The user gives the coordinates and the *independent* speeds; the speeds left out are computed from the
    velocity constraints ``A(q, t) q̇ + b = 0`` (:func:`complete_speeds`): the dependent set is chosen among the
    speeds not given by the rule of :func:`pivot_columns` (the same rule chooses the dependent speeds of a
    linearization, :mod:`lagrange.analysis.manifold`), and a speed left out that the constraints do not
    determine is refused as missing. A state that still violates the constraints (a given coordinate off
    ``φ = 0``, given speeds that contradict a constraint) is projected as above (``project_initial=True``,
    default): every given value that moves is named, old → new, in an
    :class:`~lagrange.errors.InitialStateChangedWarning` and recorded on the trajectory
    (``initial_adjustments``, with ``initial_constraint_violation``); never silently. With
    ``project_initial=False`` it raises :class:`~lagrange.errors.InitialConditionError` naming the violated
    constraint and by how much.
"""

from __future__ import annotations

import importlib
import warnings

import numpy as np

from ..conventions import VELOCITY_SUFFIX
from ..errors import InitialConditionError, InitialStateChangedWarning
from ..model.coordinates import coordinate_name
from .options import STABILIZATIONS

__all__ = ["Projector", "consistent_initial", "complete_speeds", "pivot_columns", "STABILIZATIONS"]

#: a constraint residual above this fraction of (1 + the largest |value| of the state) is a violation
INITIAL_TOL = 1e-10
#: a given value moved by more than this fraction of (1 + the largest |value| of the state) counts as changed
CHANGE_TOL = 1e-12
#: a column of a constraint Jacobian whose remaining norm is within this fraction of the largest entry is zero
RANK_TOL = 1e-10


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


def pivot_columns(J: np.ndarray) -> list[int]:
    """The columns of ``J`` (k × n) that make a well-conditioned square block, as many as its rank (sorted).

    The rule: a pivoted Gram–Schmidt that takes, at each step, the LAST declared column whose remaining norm is
    at least 0.1 of the largest remaining norm — well conditioned, and the variables declared first stay
    independent. It stops when no column has a remaining norm above ``RANK_TOL`` × the largest entry of ``J``
    (so fewer than k columns come back when J is rank deficient; none when J is not finite)."""
    k = J.shape[0]
    R = np.array(J, dtype=float)
    if not np.all(np.isfinite(R)):
        return []
    scale = max(1.0, float(np.max(np.abs(R)))) if R.size else 1.0
    chosen: list[int] = []
    for _ in range(k):
        norms = np.linalg.norm(R, axis=0)
        norms[chosen] = 0.0
        best = float(np.max(norms)) if norms.size else 0.0
        if best <= RANK_TOL * scale:
            break
        j = max(i for i in range(J.shape[1]) if norms[i] >= 0.1 * best)
        v = R[:, j] / norms[j]
        R = R - np.outer(v, v @ R)
        chosen.append(j)
    return sorted(chosen)


def complete_speeds(A: np.ndarray, b: np.ndarray, qd: np.ndarray, given) -> tuple[np.ndarray, list[int], list[int]]:
    r"""The speeds ``qd`` with those not ``given`` computed from the velocity constraints ``A q̇ + b = 0``.

    .. math:: A_{:,D}\,\dot q_D = -\big(b + A_{:,\bar D}\,\dot q_{\bar D}\big)

    The dependent set ``D`` is chosen among the speeds not given by :func:`pivot_columns` on their columns of
    ``A``; it has the rank of those columns (at most m). Speeds not given and not in ``D`` keep their value in
    ``qd`` (the caller's default). When the given speeds contradict a constraint that ``D`` cannot satisfy,
    ``D`` satisfies the rest in the least-squares sense and the residual ``A q̇ + b`` is left for the caller
    to report or project.

    Parameters
    ----------
    A : ndarray, shape (m, n); b : ndarray, shape (m,) — the velocity constraints at the state's positions
    qd : ndarray, shape (n,) — the speeds (values at the entries not given are defaults)
    given : sequence of n bools — which speeds the user gave (never changed here)

    Returns
    -------
    (speeds, computed, undetermined) : the completed speeds, shape (n,); the indices computed (D, sorted); the
    indices neither given nor determined by the constraints (left at their default)
    """
    qd = np.array(qd, dtype=float)
    A = np.asarray(A, dtype=float).reshape(-1, qd.size)
    free = [i for i in range(qd.size) if not given[i]]
    if not free or not A.shape[0]:
        return qd, [], free
    dep = [free[j] for j in pivot_columns(A[:, free])]
    rest = [i for i in range(qd.size) if i not in dep]
    if dep:
        rhs = -(np.asarray(b, dtype=float).ravel() + A[:, rest] @ qd[rest])
        qd[dep] = np.linalg.lstsq(A[:, dep], rhs, rcond=None)[0]
    return qd, dep, [i for i in free if i not in dep]


def consistent_initial(model, t0: float, y0: np.ndarray, project: bool, given=None) -> tuple[np.ndarray, dict, dict]:
    """A state on the constraint manifold from the user's ``y0``: the speeds not ``given`` computed
    (:func:`complete_speeds`), then the positions and speeds projected when the state still violates the
    constraints (``project``) or InitialConditionError (strict).

    Parameters
    ----------
    y0 : ndarray, shape (2n,) — the user's state (entries not given hold placeholders)
    given : sequence of 2n bools, optional — which entries the user gave (default: all); a coordinate must be
        given, a speed may be left out when the velocity constraints determine it

    Returns
    -------
    (y, violation, adjustments) : the consistent state, shape (2n,); ``{constraint: (φ, A q̇ + b)}``: φ of the
    given positions, A q̇ + b of the speeds (those left out computed) at the positions used;
    ``{name: (given value or None, value used)}`` for each value computed (None) or changed by the projection.
    Each changed given value is also named in an :class:`~lagrange.errors.InitialStateChangedWarning`.

    Raises
    ------
    InitialConditionError
        A speed left out that the constraints do not determine, a violated constraint when strict, or a
        projection that does not converge.
    """
    cf, n, cnames = model.constraint_functions, model.n, model.equations.constraint_names
    names = _state_names(model)
    given = [True] * (2 * n) if given is None else [bool(g) for g in given]
    y0 = np.array(y0, dtype=float)
    pos = np.zeros(model.m)
    if cf.holonomic:
        pos[cf.holonomic] = cf.phi(t0, y0[:n])
    scale = 1.0 + float(np.max(np.abs(y0)))  # (entries not given hold 0)
    tol = INITIAL_TOL * scale
    proj = Projector(cf, n)
    q1 = _projected_positions(proj, t0, y0[:n], pos, tol, cnames) if project and np.any(np.abs(pos) > tol) \
        else y0[:n]
    qd, computed = _completed_speeds(cf, t0, q1, y0[n:], given[n:], names[n:], cnames)
    vel = cf.matrix(t0, q1) @ qd + cf.bias(t0, q1)
    report = {cnames[k]: (float(pos[k]), float(vel[k])) for k in range(model.m)}
    adjustments = {names[n + i]: (None, float(qd[i])) for i in computed}
    bad = [k for k in range(model.m) if abs(pos[k]) > tol or abs(vel[k]) > tol]
    if not bad:
        return np.concatenate([y0[:n], qd]), report, adjustments
    detail = "; ".join(_violation(cnames[k], pos[k], vel[k], tol) for k in bad)
    if not project:
        raise InitialConditionError(
            f"initial state violates the constraints ({detail}); fix it (give only the independent speeds: the "
            "others are computed from the velocity constraints) or pass Stabilization(project_initial=True)")
    y1 = np.concatenate([q1, proj.velocities(t0, q1, qd)])
    changed = [i for i in range(2 * n) if given[i] and abs(y1[i] - y0[i]) > CHANGE_TOL * scale]
    adjustments.update({names[i]: (float(y0[i]), float(y1[i])) for i in changed})
    adjustments.update({names[n + i]: (None, float(y1[n + i])) for i in computed})
    if changed:
        moves = ", ".join(f"{names[i]} {y0[i]:.10g} → {y1[i]:.10g}" for i in changed)
        warnings.warn(f"the initial state violates the constraints ({detail}) and was projected onto them, "
                      f"changing given values: {moves}. Give a consistent state, or only the independent speeds "
                      "(the others are computed from the velocity constraints); "
                      "Stabilization(project_initial=False) refuses instead", InitialStateChangedWarning,
                      stacklevel=5)
    return y1, report, adjustments


def _projected_positions(proj: Projector, t0: float, q: np.ndarray, pos: np.ndarray, tol: float,
                         cnames) -> np.ndarray:
    """The positions projected onto φ = 0; InitialConditionError when the projection does not converge."""
    q1, resid = proj.positions(t0, q)
    if resid > 10 * tol:
        bad = [cnames[k] for k in range(len(pos)) if abs(pos[k]) > tol]
        raise InitialConditionError(
            f"cannot project the initial positions onto the constraints (remaining |φ| = {resid:.3g}): "
            f"{', '.join(bad)} may be inconsistent or the guess too far off")
    return q1


def _completed_speeds(cf, t0: float, q: np.ndarray, qd: np.ndarray, given, names, cnames) -> tuple[np.ndarray, list]:
    """The speeds with those left out computed at the positions ``q`` (:func:`complete_speeds`), and their
    indices; InitialConditionError naming a speed left out that cannot be computed."""
    left_out = [names[i] for i in range(len(qd)) if not given[i]]
    if not left_out:
        return np.array(qd, dtype=float), []
    with np.errstate(all="ignore"):  # (a singular configuration: refused here)
        A, b = cf.matrix(t0, q), cf.bias(t0, q)
    if not (np.all(np.isfinite(A)) and np.all(np.isfinite(b))):
        raise InitialConditionError(
            f"missing initial value(s) for {', '.join(left_out)}: the velocity constraints ({', '.join(cnames)}) "
            "are not finite at the initial positions (a singular configuration), so they cannot be computed; "
            "give them, or start from another configuration")
    qd, computed, missing = complete_speeds(A, b, qd, given)
    if missing:
        raise InitialConditionError(
            f"missing initial value(s) for {', '.join(names[i] for i in missing)}: the velocity constraints "
            f"({', '.join(cnames)}) determine only {', '.join(names[i] for i in computed) or 'none of them'}; "
            "give the others")
    return qd, computed


def _violation(name: str, pos: float, vel: float, tol: float) -> str:
    parts = ([f"φ = {pos:.3g}"] if abs(pos) > tol else []) + ([f"A q̇ + b = {vel:.3g}"] if abs(vel) > tol else [])
    return f"{name}: {', '.join(parts)}"


def _state_names(model) -> list[str]:
    qs = [coordinate_name(c) for c in model.equations.coordinates]
    return qs + [nm + VELOCITY_SUFFIX for nm in qs]
