"""The kinds of book answers a problem can state, each with its own check against the engine.

Every answer's :meth:`check` derives the quantity from the system with the library's public API and
raises :class:`~lagrange.corpus.compare.Mismatch` when it disagrees with the book. Expressions are
written in the coordinate functions (``x``, ``x.diff(t)``, ``x.diff(t, 2)``) exactly as printed in the
book (after any documented correction).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import field

import mpmath
import numpy as np
import sympy as sp

from ..conventions import t
from ..model.coordinates import coordinate_name, to_symbols
from ..records import record
from ..simplification import SECONDS, run_bounded
from .compare import Mismatch, agree, numeric_points

__all__ = [
    "Answer",
    "EquationsOfMotion",
    "KineticEnergy",
    "PotentialEnergy",
    "PowerFunction",
    "GeneralizedForces",
    "MassMatrix",
    "EnergySplit",
    "ConservedMomenta",
    "JacobiIntegral",
    "Quantity",
    "TrajectoryValues",
    "ConstraintForce",
]


def _residual(eq) -> sp.Expr:
    eq = sp.sympify(eq)
    if isinstance(eq, sp.Equality):
        return eq.lhs - eq.rhs
    return eq


def _state_symbols(eqs) -> list:
    return [*eqs.q, *eqs.qd, t]


class Answer:
    """Base class: a book answer with a citation-free description and a check."""

    description: str = "answer"

    def check(self, system, ranges: Mapping | None = None) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def _agree(self, system, a, b, what, ranges, rtol=1e-10):
        if system is None:  # a problem without dynamics (e.g. moments of inertia): compare as expressions
            syms = sp.sympify(a).free_symbols | sp.sympify(b).free_symbols
            params = [s for s in syms if s.is_positive]
            agree(a, b, list(syms), rtol=rtol, ranges=ranges, parameters=params, what=what)
            return
        eqs = system.derived
        c = system.coordinates
        agree(to_symbols(a, c), to_symbols(b, c), _state_symbols(eqs), rtol=rtol, ranges=ranges,
              parameters=eqs.parameters, what=what)


@record(frozen=True)
class EquationsOfMotion(Answer):
    """The book's equations of motion (one per coordinate, any arrangement or scaling).

    Checked by solving both sets for the accelerations at random states (30-digit arithmetic) and
    requiring agreement to ``rtol`` — independent of how the book arranged or scaled the equations.
    With ``per_equation=True`` each book equation must also equal the derived equation of the same
    coordinate up to a constant factor.
    """

    equations: Sequence
    rtol: float = 1e-10
    per_equation: bool = False
    description: str = "equations of motion"

    def check(self, system, ranges=None):
        eqs = system.derived
        c = system.coordinates
        n = eqs.n
        if eqs.m:
            raise Mismatch("EquationsOfMotion compares unconstrained equations: check eliminate(system, ...) "
                           "or use ConstraintForce for the multiplier form")
        if len(self.equations) != n:
            raise Mismatch(f"book gives {len(self.equations)} equations, system has {n} coordinates")
        R = sp.Matrix([to_symbols(_residual(e), c) for e in self.equations])
        A = R.jacobian(list(eqs.qdd))
        b = -R.subs({a: 0 for a in eqs.qdd})
        if A.free_symbols & set(eqs.qdd) or b.free_symbols & set(eqs.qdd):
            raise Mismatch("book equations are not linear in the accelerations")
        syms = sorted(set(_state_symbols(eqs)) | set(eqs.parameters) | A.free_symbols | b.free_symbols
                      | eqs.mass_matrix.free_symbols | eqs.forcing.free_symbols, key=lambda s: s.name)
        args = syms
        fM = sp.lambdify(args, eqs.mass_matrix, modules="mpmath")
        ff = sp.lambdify(args, eqs.forcing, modules="mpmath")
        fA = sp.lambdify(args, A, modules="mpmath")
        fb = sp.lambdify(args, b, modules="mpmath")
        done, tries = 0, 0
        with mpmath.workdps(30):
            while done < 5:
                tries += 1
                if tries > 100:
                    raise Mismatch("could not find states where both sets of equations can be solved")
                pt = numeric_points(syms, 1, seed=99 + tries, ranges=ranges, parameters=eqs.parameters)[0]
                vals = [mpmath.mpf(str(pt[s])) for s in args]
                try:
                    acc_d = mpmath.lu_solve(mpmath.matrix(fM(*vals)), mpmath.matrix(ff(*vals)))
                    acc_b = mpmath.lu_solve(mpmath.matrix(fA(*vals)), mpmath.matrix(fb(*vals)))
                except (ZeroDivisionError, ValueError, TypeError):
                    continue
                if any(isinstance(v, mpmath.mpc) for v in list(acc_d) + list(acc_b)):
                    continue
                scale = max([abs(v) for v in acc_d] + [abs(v) for v in acc_b] + [mpmath.mpf(1e-20)])
                for i in range(n):
                    if abs(acc_d[i] - acc_b[i]) > self.rtol * scale:
                        shown = ", ".join(f"{s}={float(v):.4g}" for s, v in zip(args, vals))
                        raise Mismatch(
                            f"acceleration of {coordinate_name(c[i])}: derived {float(acc_d[i]):.12g}, "
                            f"book {float(acc_b[i]):.12g} at {shown}"
                        )
                done += 1
        if self.per_equation:
            derived = [to_symbols(e.lhs - e.rhs, c) for e in system.equations()]
            state = set(_state_symbols(eqs)) | set(eqs.qdd)
            for i in range(n):
                ratio = sp.cancel(R[i] / derived[i])
                if ratio.free_symbols & state and not _constant_ratio(R[i], derived[i], state, eqs, ranges):
                    raise Mismatch(
                        f"book equation {i + 1} is not a constant multiple of the derived "
                        f"{coordinate_name(c[i])} equation (ratio {ratio})"
                    )


def _constant_ratio(a, b, state, eqs, ranges) -> bool:
    """Numeric fallback when ``cancel`` cannot simplify a ratio (|x| vs sign(x)·x, trig identities): the
    ratio a/b takes the same value at random states (30 digits) for fixed parameters."""
    syms = sorted((a.free_symbols | b.free_symbols), key=lambda s: s.name)
    pt0 = numeric_points(syms, 1, seed=7, ranges=ranges, parameters=eqs.parameters)[0]
    params = {s: v for s, v in pt0.items() if s not in state}
    values = []
    for k in range(6):
        pt = numeric_points([s for s in syms if s in state], 1, seed=100 + k, ranges=ranges)[0]
        pt.update(params)
        va, vb = a.evalf(30, subs=pt), b.evalf(30, subs=pt)
        if vb == 0 or not (va.is_real and vb.is_real):
            continue
        values.append(va / vb)
    if len(values) < 3:
        return False
    ref = values[0]
    return all(abs(v - ref) <= 1e-12 * max(abs(ref), 1e-30) for v in values)


@record(frozen=True)
class KineticEnergy(Answer):
    """T as printed in the book."""

    T: sp.Expr
    description: str = "kinetic energy T"

    def check(self, system, ranges=None):
        self._agree(system, system.T, self.T, "T", ranges)


@record(frozen=True)
class PotentialEnergy(Answer):
    """V as printed (additive constants ignored: the gradients ∂V/∂q are compared)."""

    V: sp.Expr
    description: str = "potential energy V"

    def check(self, system, ranges=None):
        for q in system.coordinates:
            self._agree(system, sp.diff(system.V, q), sp.diff(sp.sympify(self.V), q),
                        f"dV/d{coordinate_name(q)}", ranges)


@record(frozen=True)
class PowerFunction(Answer):
    """Wells' P as printed (compared through ∂P/∂q̇, the forces it gives)."""

    P: sp.Expr
    description: str = "power function P"

    def check(self, system, ranges=None):
        for q in system.coordinates:
            v = q.diff(t)
            self._agree(system, sp.diff(system.P, v), sp.diff(sp.sympify(self.P), v),
                        f"dP/d{coordinate_name(q)}_dot", ranges)


@record(frozen=True)
class GeneralizedForces(Answer):
    """Generalized forces per coordinate (only the coordinates listed are checked).

    ``which="all"`` (default) compares ``F_q + ∂P/∂q̇ − ∂D/∂q̇``; ``"applied"`` compares ``F_q`` only;
    ``"total"`` also adds ``−∂V/∂q`` (Wells' chapters 3–4, where every force is in F_q).
    """

    forces: Mapping
    which: str = "all"
    description: str = "generalized forces"

    def check(self, system, ranges=None):
        if self.which not in ("all", "applied", "total"):
            raise Mismatch(f"unknown which={self.which!r}")
        allf = system.generalized_forces()
        for q, expected in self.forces.items():
            if q not in system.coordinates:
                raise Mismatch(f"{q} is not a coordinate of the system")
            got = system.forces[q] if self.which == "applied" else allf[q]
            if self.which == "total":
                got = got - sp.diff(system.V, q)
            self._agree(system, got, expected, f"F_{coordinate_name(q)}", ranges)


@record(frozen=True)
class MassMatrix(Answer):
    """The mass matrix M = ∂²T/∂q̇∂q̇."""

    M: sp.Matrix
    description: str = "mass matrix"

    def check(self, system, ranges=None):
        M = system.mass_matrix
        B = sp.Matrix(self.M)
        if B.shape != M.shape:
            raise Mismatch(f"shape {B.shape} != {M.shape}")
        for i in range(M.rows):
            for j in range(M.cols):
                self._agree(system, M[i, j], B[i, j], f"M[{i},{j}]", ranges)


@record(frozen=True)
class EnergySplit(Answer):
    """Wells' ``T = Σ A q̇q̇ + Σ B q̇ + C`` (2.55); give any of A (matrix), B (list), C."""

    A: sp.Matrix | None = None
    B: Sequence | None = None
    C: sp.Expr | None = None
    description: str = "T split into A, B, C (Wells 2.55)"

    def check(self, system, ranges=None):
        A, B, C = system.energy_split()
        if self.A is not None:
            Ab = sp.Matrix(self.A)
            for i in range(A.rows):
                for j in range(A.cols):
                    self._agree(system, A[i, j], Ab[i, j], f"A[{i},{j}]", ranges)
        if self.B is not None:
            for i, bexp in enumerate(self.B):
                self._agree(system, B[i], bexp, f"B[{i}]", ranges)
        if self.C is not None:
            self._agree(system, C, self.C, "C", ranges)


@record(frozen=True)
class ConservedMomenta(Answer):
    """Ignorable coordinates and their constant momenta ``{q: p_q}``."""

    momenta: Mapping
    description: str = "ignorable coordinates and conserved momenta"

    def check(self, system, ranges=None):
        found = system.ignorable_coordinates()
        for q, p in self.momenta.items():
            if q not in found:
                raise Mismatch(f"{coordinate_name(q)} is not detected as ignorable")
            self._agree(system, found[q], p, f"p_{coordinate_name(q)}", ranges)


@record(frozen=True)
class JacobiIntegral(Answer):
    """The Jacobi integral h (or the energy T+V when nothing moves)."""

    h: sp.Expr
    description: str = "Jacobi integral"

    def check(self, system, ranges=None):
        self._agree(system, system.jacobi_integral(), self.h, "h", ranges)


@record(frozen=True)
class Quantity(Answer):
    """Any quantity computed from the system by ``compute(system)`` and compared with the book.

    Use for results such as small-oscillation periods, equilibrium positions or acceleration
    components. ``compute`` must use the library (the system's derived matrices, etc.), never restate
    the answer. For a problem without a system (``system=None``, e.g. moments of inertia), ``compute``
    receives None and the two sides are compared over their free symbols.
    """

    name: str
    compute: Callable
    expected: sp.Expr
    rtol: float = 1e-10
    description: str = "quantity"

    def check(self, system, ranges=None):
        # bounded: seeded sympy, a time limit well above the slowest answer, retried with new seeds
        got = run_bounded(self.compute, system, what=f"the answer {self.name!r}", seconds=3 * SECONDS)
        exp = self.expected
        if isinstance(got, (sp.MatrixBase, list, tuple)):
            got_l, exp_l = list(got), list(exp)
            if len(got_l) != len(exp_l):
                raise Mismatch(f"{self.name}: {len(got_l)} values derived, {len(exp_l)} in the book")
            for i, (a, b) in enumerate(zip(got_l, exp_l)):
                self._agree(system, a, b, f"{self.name}[{i}]", ranges, self.rtol)
        else:
            self._agree(system, got, exp, self.name, ranges, self.rtol)


@record(frozen=True)
class TrajectoryValues(Answer):
    """Numbers from a simulation: ``values = {coordinate: [v(t_k) ...]}`` at ``times``.

    Simulated with DOP853 at rtol 1e-11 and compared with ``tolerance`` (absolute, in the problem's
    units) — for book or derived closed-form values.
    """

    params: Mapping
    initial: Mapping
    times: Sequence
    values: Mapping
    tolerance: float = 1e-6
    description: str = "trajectory values"
    options: Mapping = field(default_factory=dict)

    def check(self, system, ranges=None):
        times = np.asarray(self.times, dtype=float)
        t_eval = np.concatenate([[0.0], times])
        sol = system.simulate((0.0, float(times[-1])), self.initial, self.params, rtol=1e-11, atol=1e-12,
                              t_eval=t_eval, **dict(self.options))
        for q, vals in self.values.items():
            got = sol[q][1:]
            err = np.max(np.abs(got - np.asarray(vals, dtype=float)))
            if not err <= self.tolerance:
                raise Mismatch(f"{q}: simulated {got} vs expected {list(vals)} (max error {err:.3g})")


@record(frozen=True)
class ConstraintForce(Answer):
    """A force of constraint, checked along a simulated trajectory of the multiplier formulation.

    ``expected`` is the book's expression in the coordinates, velocities, accelerations (``q.diff(t, 2)``,
    evaluated from the simulated motion), parameters and t. It is compared with the multiplier λ of
    ``constraint`` (by name), or, with ``coordinate=q``, with the generalized force of constraint on q,
    ``(Aᵀλ)_q`` — Wells' 𝓕_q of the freed superfluous coordinate (eq. 12.3). Agreement to ``rtol``
    relative to the largest value along the run.
    """

    constraint: str
    expected: sp.Expr
    params: Mapping
    initial: Mapping
    t_end: float
    coordinate: object = None
    rtol: float = 1e-6
    description: str = "force of constraint"

    def check(self, system, ranges=None):
        eqs = system.derived
        if self.constraint not in eqs.constraint_names:
            raise Mismatch(f"no constraint named {self.constraint!r} (have {', '.join(eqs.constraint_names)})")
        k = eqs.constraint_names.index(self.constraint)
        own = {p.name for p in eqs.parameters}  # extra values may serve the book's expression only
        sim_params = {k: v for k, v in self.params.items() if getattr(k, "name", str(k)) in own}
        sol = system.simulate(self.t_end, self.initial, sim_params, rtol=1e-11, atol=1e-12, n_points=41)
        lam = sol.multipliers
        if self.coordinate is not None:
            j = system.coordinates.index(self.coordinate)
            A = np.array([sol.model.constraint_functions.matrix(ti, yi[: eqs.n])[k, j]
                          for ti, yi in zip(sol.t, sol.y)])
            got = A * lam[:, k]
        else:
            got = lam[:, k]
        c = system.coordinates
        expr = to_symbols(sp.sympify(self.expected), c)
        syms = [*eqs.q, *eqs.qd, *eqs.qdd, t]
        values = {getattr(k, "name", str(k)): v for k, v in (self.params or {}).items()}
        free = [p for p in expr.free_symbols if p not in syms]
        missing = sorted(p.name for p in free if p.name not in values)
        if missing:
            raise Mismatch(f"parameter values missing for {', '.join(missing)}")
        par = {p: float(values[p.name]) for p in free}
        fn = sp.lambdify(syms, expr.subs(par), modules="numpy")
        cols = [sol.y[:, i] for i in range(2 * eqs.n)] + [sol.accelerations[:, i] for i in range(eqs.n)] + [sol.t]
        want = np.broadcast_to(np.asarray(fn(*cols), dtype=float), got.shape)
        scale = max(float(np.max(np.abs(want))), float(np.max(np.abs(got))), 1e-30)
        err = float(np.max(np.abs(got - want)))
        if not err <= self.rtol * scale:
            i = int(np.argmax(np.abs(got - want)))
            raise Mismatch(f"{self.constraint}: derived {got[i]:.10g} vs book {want[i]:.10g} at t={sol.t[i]:.4g} "
                           f"(max error {err:.3g}, scale {scale:.3g})")
