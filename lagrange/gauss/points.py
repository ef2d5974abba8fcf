r"""Mass points in redundant Cartesian coordinates, moved by Gauss' principle of least constraint.

A :class:`PointSystem` holds N mass points (positions ``x``, shape (N, 3)), the applied forces
``F_k(t, x, ẋ)`` and constraints of four kinds (Sonneveld 2015, §3.4, §4.1–§4.4; recipes R1–R4):

* :class:`Link` — two points at a fixed distance (an ideal massless bar, internal);
* :class:`Dragging` — a point at a fixed distance from a prescribed path ``x_d(t)`` (a moving support);
* :class:`Surface` — a point on a (possibly moving) surface ``φ(x, y, z, t) = 0``;
* :class:`PointConstraint` — any holonomic ``φ(x_1..x_N, t) = 0`` in the symbols of :func:`point_symbols`.

Every constraint is written ``φ = 0`` and used twice differentiated,

.. math:: \ddot\varphi = \nabla\varphi\cdot\ddot x + \dot x^{\mathsf T}\nabla^2\varphi\,\dot x
          + 2\,\partial_t\nabla\varphi\cdot\dot x + \partial_{tt}\varphi = 0
          \ \Rightarrow\ A\ddot x = b ,

and the accelerations minimise Gauss' constraint :math:`Z = \sum_k \tfrac12 m_k|\ddot x_k - F_k/m_k|^2`
subject to ``A ẍ = b``: one KKT solve (:func:`lagrange.gauss.kkt.solve_least_constraint`) giving
``M ẍ = F + Aᵀλ``. Links use ``φ = ½(|x_j − x_i|² − L²)``, so the bar pulls point i with ``−λ (x_j − x_i)``:
its **tension** is ``−λ L`` (positive when pulling). Redundant but consistent constraints give unique
accelerations and non-unique λ (reported); inconsistent ones raise
:class:`~lagrange.errors.InconsistentConstraintError`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import field

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..conventions import t as T_SYM
from ..errors import DeclarationError
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from .kkt import CONSISTENCY_TOL, LeastConstraintSolution, solve_least_constraint

__all__ = [
    "Link", "Dragging", "Surface", "PointConstraint", "PointSystem", "GaussAccelerations",
    "PointTrajectory", "point_symbols", "simulate_points", "SURFACE_SYMBOLS",
]

#: The symbols (x, y, z) in which a :class:`Surface` is written (time is :data:`lagrange.t`).
SURFACE_SYMBOLS = sp.symbols("x y z", real=True)


def point_symbols(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity symbols of n points, arrays of shape (n, 3): ``x0, y0, z0, …`` and
    ``x0_dot, …`` — the variables of :class:`PointConstraint` and of symbolic forces."""
    X = np.array([[sp.Symbol(f"{c}{k}", real=True) for c in "xyz"] for k in range(n)], dtype=object)
    V = np.array([[sp.Symbol(f"{c}{k}_dot", real=True) for c in "xyz"] for k in range(n)], dtype=object)
    return X, V


@record(frozen=True)
class Link:
    """Points ``i`` and ``j`` kept at distance ``length`` (``φ = ½(|x_j − x_i|² − L²)``; internal)."""

    i: int
    j: int
    length: float
    name: str = ""
    external = False

    def rows(self, t, x, v, n):
        r, rd = x[self.j] - x[self.i], v[self.j] - v[self.i]
        A = np.zeros((1, 3 * n))
        A[0, 3 * self.i:3 * self.i + 3], A[0, 3 * self.j:3 * self.j + 3] = -r, r
        return A, np.array([-rd @ rd]), np.array([0.5 * (r @ r - self.length**2)]), np.zeros(1)


def _path_functions(path):
    if callable(path):
        return path
    vec = sp.Matrix(path)
    if vec.shape != (3, 1) or vec.free_symbols - {T_SYM}:
        raise DeclarationError(f"a dragging path must be 3 expressions in lagrange.t only, got {list(vec)}",
                               subject="Dragging")
    f = _lambdify(T_SYM, [list(vec), list(vec.diff(T_SYM)), list(vec.diff(T_SYM, 2))], modules="numpy")
    return lambda t: tuple(np.array(c, dtype=float).ravel() * np.ones(3) for c in f(t))


@record(frozen=True)
class Dragging:
    """Point ``point`` kept at distance ``length`` from the prescribed path ``x_d(t)`` (R3).

    ``path`` is 3 sympy expressions of :data:`lagrange.t` or a callable ``t -> (x_d, ẋ_d, ẍ_d)``.
    ``φ = ½(|x_d − x|² − L²)``; the cord's tension is ``−λ L`` and the driver does work on the point.
    """

    point: int
    path: object
    length: float
    name: str = ""
    external = True
    _f: Callable = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "_f", _path_functions(self.path))

    def rows(self, t, x, v, n):
        xd, vd, ad = self._f(t)
        r, rd = xd - x[self.point], vd - v[self.point]
        A = np.zeros((1, 3 * n))
        A[0, 3 * self.point:3 * self.point + 3] = -r
        return A, np.array([-(r @ ad + rd @ rd)]), np.array([0.5 * (r @ r - self.length**2)]), np.array([r @ vd])


class _Symbolic:
    """Numeric φ, ∇φ, ∇²φ, ∂_t∇φ, ∂_tφ, ∂_ttφ of a holonomic φ(u, t) over variables u."""

    def __init__(self, phi, variables, label):
        phi = _sympify(phi)
        stray = phi.free_symbols - set(variables) - {T_SYM}
        if stray:
            raise DeclarationError(f"{label}: φ = {phi} contains {', '.join(sorted(map(str, stray)))}, which are "
                                   "not its variables or lagrange.t (substitute parameter values first)",
                                   subject="point constraint")
        u = list(variables)
        grad = sp.Matrix([phi]).jacobian(u)
        parts = [phi, list(grad), sp.hessian(phi, u).tolist(), list(grad.diff(T_SYM)), phi.diff(T_SYM),
                 phi.diff(T_SYM, 2)]
        self._f = _lambdify((T_SYM, u), parts, modules="numpy", cse=True)
        self.k = len(u)

    def __call__(self, t, u, ud):
        phi, g, Hs, gt, pt, ptt = self._f(t, list(u))
        g, Hs, gt = (np.array(a, dtype=float) * np.ones(s) for a, s in ((g, self.k), (Hs, (self.k, self.k)),
                                                                         (gt, self.k)))
        return float(phi), g, float(-(ud @ Hs @ ud + 2 * gt @ ud + float(ptt))), float(pt)


@record(frozen=True)
class Surface:
    """Point ``point`` on the surface ``φ(x, y, z, t) = 0`` written in :data:`SURFACE_SYMBOLS` (external;
    the force is ``λ ∇φ``)."""

    point: int
    phi: sp.Expr
    name: str = ""
    external = True
    _f: _Symbolic = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "_f", _Symbolic(self.phi, SURFACE_SYMBOLS, self.name or "surface"))

    def rows(self, t, x, v, n):
        phi, g, b, pt = self._f(t, x[self.point], v[self.point])
        A = np.zeros((1, 3 * n))
        A[0, 3 * self.point:3 * self.point + 3] = g
        return A, np.array([b]), np.array([phi]), np.array([pt])


@record(frozen=True)
class PointConstraint:
    """A holonomic ``φ(x_0..x_{N−1}, t) = 0`` in the position symbols of :func:`point_symbols` (external
    unless ``external=False``)."""

    phi: sp.Expr
    n_points: int
    name: str = ""
    external: bool = True
    _f: _Symbolic = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        X, _ = point_symbols(self.n_points)
        object.__setattr__(self, "_f", _Symbolic(self.phi, list(X.ravel()), self.name or "point constraint"))

    def rows(self, t, x, v, n):
        phi, g, b, pt = self._f(t, x.ravel(), v.ravel())
        return g[None, :], np.array([b]), np.array([phi]), np.array([pt])


Constraint = Link | Dragging | Surface | PointConstraint


def _symbolic_forces(forces: Mapping, n: int) -> Callable:
    X, V = point_symbols(n)
    keys = sorted(forces)
    exprs = [list(sp.Matrix(forces[k])) + [0] * (3 - len(sp.Matrix(forces[k]))) for k in keys]
    f = _lambdify((T_SYM, list(X.ravel()), list(V.ravel())), exprs, modules="numpy", cse=True)

    def F(t, x, v):
        out = np.zeros((n, 3))
        for k, row in zip(keys, f(t, list(x.ravel()), list(v.ravel()))):
            out[k] = np.array(row, dtype=float).ravel()
        return out

    return F


@record(frozen=True)
class GaussAccelerations:
    """The result of one least-constraint solve.

    Attributes
    ----------
    a : ndarray (N, 3) — accelerations (unique)
    multipliers : ndarray (m,) — minimum-norm λ, one per constraint, ``M ẍ = F + Aᵀλ``
    rank, redundant : rank of the constraint rows and the number of dependent ones (λ non-unique if > 0)
    applied : ndarray (N, 3) — the applied forces F
    constraint_forces : ndarray (m, N, 3) — the force each constraint exerts on each point
    names : constraint names
    """

    a: np.ndarray
    multipliers: np.ndarray
    rank: int
    redundant: int
    applied: np.ndarray
    constraint_forces: np.ndarray
    names: tuple
    lengths: tuple

    def tension(self, name: str) -> float:
        """Tension of the link or dragging cord ``name``: ``−λ L`` (> 0 pulling; unique only without
        redundant constraints)."""
        k = self.names.index(name)
        return float(-self.multipliers[k] * self.lengths[k])

    def external_forces(self, system: PointSystem) -> np.ndarray:
        """Applied forces plus the forces of external constraints (what the balance laws see), (N, 3)."""
        ext = [k for k, c in enumerate(system.constraints) if c.external]
        return self.applied + self.constraint_forces[ext].sum(axis=0)


@record(frozen=True)
class PointSystem:
    """N mass points with applied forces and constraints (frozen, validated).

    Parameters
    ----------
    masses : sequence of N positive numbers
    constraints : Link, Dragging, Surface, PointConstraint objects
    forces : callable ``F(t, x, v) -> (N, 3)``, or ``{k: 3 expressions}`` in :func:`point_symbols` and t
    gravity : optional field g (3 numbers): adds ``m_k g`` to every point

    Examples
    --------
    A bob on a fixed pivot (E9): speed 3 on a radius 0.5 gives the centripetal acceleration 18.

    >>> s = PointSystem([2.0], [Dragging(0, (0, 0, 0), 0.5, "cord")])
    >>> r = s.accelerations(0.0, [[0.5, 0, 0]], [[0, 3.0, 0]])
    >>> r.a.round(9).tolist(), round(r.tension("cord"), 9)
    ([[-18.0, 0.0, 0.0]], 36.0)
    """

    masses: tuple
    constraints: tuple = ()
    forces: object = None
    gravity: tuple | None = None
    _F: Callable | None = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        problems = []
        masses = tuple(float(m) for m in self.masses)
        n = len(masses)
        problems += [f"mass of point {k} is {m}: masses must be positive" for k, m in enumerate(masses) if not m > 0]
        names = []
        for k, c in enumerate(self.constraints):
            pts = [c.i, c.j] if isinstance(c, Link) else [getattr(c, "point", 0)]
            if any(not 0 <= p < n for p in pts):
                problems.append(f"constraint {c.name or k + 1} refers to point(s) {pts} of {n}")
            if isinstance(c, PointConstraint) and c.n_points != n:
                problems.append(f"constraint {c.name or k + 1} is written for {c.n_points} points, not {n}")
            names.append(c.name or f"{type(c).__name__.lower()} {k + 1}")
        if len(set(names)) != len(names):
            problems.append(f"constraint names must be unique: {names}")
        if problems:
            raise DeclarationError(problems, subject="point system")
        object.__setattr__(self, "masses", masses)
        object.__setattr__(self, "constraints", tuple(self.constraints))
        object.__setattr__(self, "_names", tuple(names))
        F = self.forces
        if isinstance(F, Mapping):
            F = _symbolic_forces(F, n)
        object.__setattr__(self, "_F", F)

    @property
    def n(self) -> int:
        return len(self.masses)

    @property
    def names(self) -> tuple:
        """Constraint names (given or ``link 1`` …)."""
        return self._names

    @property
    def mass_vector(self) -> np.ndarray:
        """Masses repeated per component, shape (3N,)."""
        return np.repeat(np.array(self.masses), 3)

    def applied_forces(self, t: float, x: np.ndarray, v: np.ndarray) -> np.ndarray:
        """``F(t, x, v)``, shape (N, 3), gravity included."""
        F = np.zeros((self.n, 3))
        if self._F is not None:
            F += np.asarray(self._F(t, x, v), dtype=float).reshape(self.n, 3)
        if self.gravity is not None:
            F += np.outer(self.masses, np.asarray(self.gravity, dtype=float))
        return F

    def constraint_rows(self, t: float, x, v) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(A, b, φ, ∂φ/∂t)``: A (m, 3N), b (m,) with ``A ẍ = b``; φ and its explicit time rate (m,)."""
        x, v = np.asarray(x, dtype=float).reshape(self.n, 3), np.asarray(v, dtype=float).reshape(self.n, 3)
        parts = [c.rows(t, x, v, self.n) for c in self.constraints]
        if not parts:
            z = np.zeros(0)
            return np.zeros((0, 3 * self.n)), z, z, z
        return tuple(np.concatenate([p[i] for p in parts]) for i in range(4))

    def solve(self, t: float, x, v, *, consistency_tol: float = CONSISTENCY_TOL
              ) -> tuple[LeastConstraintSolution, np.ndarray, np.ndarray]:
        """The raw KKT solution, the constraint matrix A and the applied forces at a state."""
        x = np.asarray(x, dtype=float).reshape(self.n, 3)
        v = np.asarray(v, dtype=float).reshape(self.n, 3)
        F = self.applied_forces(t, x, v)
        A, b, _, _ = self.constraint_rows(t, x, v)
        sol = solve_least_constraint(np.diag(self.mass_vector), F.ravel(), A, b, names=self.names,
                                     consistency_tol=consistency_tol)
        return sol, A, F

    def accelerations(self, t: float, x, v, *, consistency_tol: float = CONSISTENCY_TOL) -> GaussAccelerations:
        """Accelerations minimising Gauss' Z at ``(t, x, v)`` (x, v shape (N, 3)), with constraint forces.

        ``consistency_tol`` is the relative residual above which redundant rows count as inconsistent; a
        state slightly off the constraints (inside an integration step) makes redundant rows disagree at
        the size of the drift, so :func:`simulate_points` relaxes it there and checks strictly at its
        projected output states.

        Raises
        ------
        InconsistentConstraintError
            The constraints cannot all hold (jamming); the message names them.
        """
        sol, A, F = self.solve(t, x, v, consistency_tol=consistency_tol)
        cf = (A * sol.multipliers[:, None]).reshape(len(self.constraints), self.n, 3)
        lengths = tuple(float(getattr(c, "length", 1.0)) for c in self.constraints)
        return GaussAccelerations(sol.z.reshape(self.n, 3), sol.multipliers, sol.rank, sol.redundant, F, cf,
                                  self.names, lengths)

    def project(self, t: float, x, v, *, tol: float = 1e-13, max_iter: int = 20) -> tuple[np.ndarray, np.ndarray]:
        """Mass-weighted projection onto ``φ = 0`` (Gauss–Newton) and then onto ``φ̇ = 0`` (R10):
        the nearest consistent state in the kinetic metric. Returns ``(x, v)``, shape (N, 3)."""
        w = 1.0 / self.mass_vector
        x = np.array(x, dtype=float).ravel()
        v = np.array(v, dtype=float).ravel()
        for _ in range(max_iter):
            A, _, phi, _ = self.constraint_rows(t, x, v)
            if not phi.size or np.max(np.abs(phi)) < tol * max(1.0, float(np.max(np.abs(x)))):
                break
            x -= w * (A.T @ np.linalg.lstsq((A * w) @ A.T, phi, rcond=1e-12)[0])
        A, _, _, pt = self.constraint_rows(t, x, v)
        if A.shape[0]:
            v -= w * (A.T @ np.linalg.lstsq((A * w) @ A.T, A @ v + pt, rcond=1e-12)[0])
        return x.reshape(self.n, 3), v.reshape(self.n, 3)


@record(frozen=True)
class PointTrajectory:
    """Positions and velocities of a point system over time: ``t`` (k,), ``x`` and ``v`` (k, N, 3);
    ``violation`` (k,) is ``max |φ|`` before each projection."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    violation: np.ndarray

    def accelerations(self, system: PointSystem) -> np.ndarray:
        """Gauss accelerations at every output point, shape (k, N, 3)."""
        return np.array([system.accelerations(ti, xi, vi).a for ti, xi, vi in zip(self.t, self.x, self.v)])


#: Consistency tolerance inside integration steps, where the state drifts off the constraints by about
#: the local error (redundant rows then disagree at that size).
STEP_CONSISTENCY_TOL = 1e-4


def simulate_points(system: PointSystem, t_eval: Sequence[float], x0, v0, *, rtol: float = 1e-10,
                    atol: float = 1e-12, project: bool = True) -> PointTrajectory:
    """Integrate ``ẍ = Gauss accelerations`` with DOP853 between the output times ``t_eval``, projecting
    the state onto the position and velocity constraints at every output time (drift control).

    The initial state is projected first (so it need only be approximately consistent).
    """
    t_eval = np.asarray(t_eval, dtype=float)
    n = system.n
    x, v = (system.project(t_eval[0], x0, v0) if project else
            (np.asarray(x0, float).reshape(n, 3), np.asarray(v0, float).reshape(n, 3)))

    def rhs(t, y):
        a = system.accelerations(t, y[:3 * n], y[3 * n:], consistency_tol=STEP_CONSISTENCY_TOL).a
        return np.concatenate([y[3 * n:], a.ravel()])

    xs, vs, viol = [x], [v], [0.0]
    for t0, t1 in zip(t_eval[:-1], t_eval[1:]):
        sol = solve_ivp(rhs, (t0, t1), np.concatenate([x.ravel(), v.ravel()]), method="DOP853", rtol=rtol, atol=atol)
        y = sol.y[:, -1]
        x, v = y[:3 * n].reshape(n, 3), y[3 * n:].reshape(n, 3)
        phi = system.constraint_rows(t1, x, v)[2]
        viol.append(float(np.max(np.abs(phi))) if phi.size else 0.0)
        if project:
            x, v = system.project(t1, x, v)
            system.accelerations(t1, x, v)  # strict consistency check at the projected state (jamming)
        xs.append(x)
        vs.append(v)
    return PointTrajectory(t_eval, np.array(xs), np.array(vs), np.array(viol))
