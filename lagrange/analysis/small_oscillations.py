r"""Equilibria, linearization and small oscillations (Wells ch. 10).

About an equilibrium ``q₀`` (``q = q₀ + s``) the equations become, to first order,

.. math:: a\,\ddot s + b\,\dot s + c\,s = F(t),

with ``a = (∂²T/∂q̇∂q̇)₀`` (Wells 10.4), ``b = −(∂f/∂q̇)₀`` (damping from P, ``b = −∂²P/∂q̇∂q̇``, plus any
gyroscopic terms) and ``c = −(∂f/∂q)₀`` (``= (∂²V/∂q∂q)₀`` for a conservative system, 10.6).
Undamped frequencies solve ``|a ω² − c| = 0`` (10.10, note the book's order); damped characteristic
roots solve ``|a λ² + b λ + c| = 0`` (10.30). Normal coordinates ``g = Φᵀ a s`` with the modes Φ
normalized so that ``Φᵀ a Φ = 1`` (Wells' c_s, 10.21) give ``T = ½Σġ²``, ``V = ½Σω²g²`` (10.22).
Zero roots (free translation or rotation) and repeated roots are handled by the eigen-solver.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.optimize
import sympy as sp

from ..conventions import t
from ..errors import LagrangeError
from ..model.coordinates import coordinate_name, position_symbol, to_functions, velocity_symbol
from ..simplification import factor, simplify, solve

__all__ = ["equilibrium_equations", "equilibria", "linearize", "LinearModel", "Modes", "normal_modes",
           "characteristic_roots"]


def _state_map(system, point: Mapping) -> dict:
    """{q symbol: value} from a dict keyed by coordinates or names."""
    out = {}
    for q in system.coordinates:
        for key in (q, coordinate_name(q), position_symbol(q)):
            if key in point:
                out[position_symbol(q)] = sp.sympify(point[key])
                break
    return out


def equilibrium_equations(system) -> list:
    """The static equilibrium conditions ``f(q, q̇ = 0) = 0`` (= ∂V/∂q − F_q at rest), one per coordinate,
    in the coordinate functions."""
    eqs = system.derived
    rest = {v: 0 for v in eqs.qd}
    return [to_functions(sp.expand(-e.subs(rest)), system.coordinates) for e in eqs.forcing]


def equilibria(system, params: Mapping | None = None, guess: Mapping | None = None, *, symbolic: bool = True):
    """Static equilibria.

    With ``params is None`` and ``symbolic`` the conditions are solved with sympy (a list of dicts, possibly
    several); otherwise they are solved numerically with ``scipy.optimize.root`` from ``guess`` (a dict of
    coordinate values, default all zero), returning one dict ``{coordinate: value}``.

    Raises :class:`~lagrange.errors.LagrangeError` when the root finder does not converge.
    """
    eqs = system.derived
    conds = [e.subs({v: 0 for v in eqs.qd}) for e in eqs.forcing]
    if params is None and symbolic:
        sols = solve(conds, list(eqs.q), dict=True, what="the equilibrium conditions")
        return [{c: s.get(position_symbol(c), position_symbol(c)) for c in system.coordinates} for s in sols]
    p = {sp.Symbol(k) if isinstance(k, str) else k: v for k, v in (params or {}).items()}
    by_name = {getattr(k, "name", str(k)): v for k, v in p.items()}
    sub = {s: by_name[s.name] for s in eqs.parameters if s.name in by_name}
    t0 = float(by_name.get("t", 0.0))
    f = sp.lambdify([list(eqs.q)], [sp.sympify(c).subs(sub).subs(t, t0) for c in conds], "numpy")
    x0 = np.zeros(eqs.n)
    if guess:
        start = _state_map(system, guess)
        x0 = np.array([float(start.get(s, 0.0)) for s in eqs.q])
    res = scipy.optimize.root(lambda x: np.asarray(f(x), dtype=float), x0, tol=1e-12)
    scale = max(1.0, float(np.max(np.abs(np.asarray(f(x0), dtype=float)))))
    if not (res.success or float(np.max(np.abs(np.asarray(f(res.x), dtype=float)))) <= 1e-10 * scale):
        raise LagrangeError(f"no equilibrium found from {dict(zip(map(str, eqs.q), x0))}: {res.message}")
    return {c: float(v) for c, v in zip(system.coordinates, res.x)}


@dataclass(frozen=True)
class LinearModel:
    """``a s̈ + b ṡ + c s = F(t)`` about a reference state (Wells' a, b, c of ch. 10–11), sympy matrices."""

    coordinates: tuple
    a: sp.Matrix
    b: sp.Matrix
    c: sp.Matrix
    forcing: sp.Matrix
    about: dict

    def numeric(self, params: Mapping) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(a, b, c) as float arrays with parameter values substituted (keys: symbols or names)."""
        by_name = {getattr(k, "name", str(k)): v for k, v in params.items()}

        def ev(Mx):
            sub = {s: by_name[s.name] for s in Mx.free_symbols if s.name in by_name}
            out = Mx.subs(sub)
            if out.free_symbols:
                raise LagrangeError(f"missing parameter values for {sorted(map(str, out.free_symbols))}")
            return np.array(out.evalf(), dtype=float)

        return ev(self.a), ev(self.b), ev(self.c)

    def characteristic_polynomial(self, lam: sp.Symbol | None = None) -> sp.Expr:
        """``|a λ² + b λ + c|`` (Wells 10.30); with b = 0 set λ = iω for ``|c − a ω²|``."""
        lam = lam or sp.Symbol("lambda")
        return factor((self.a * lam**2 + self.b * lam + self.c).det())

    def frequency_equation(self, omega: sp.Symbol | None = None) -> sp.Expr:
        """Wells' fundamental determinant ``|a ω² − c|`` (10.10)."""
        omega = omega or sp.Symbol("omega", positive=True)
        return (self.a * omega**2 - self.c).det()

    def squared_frequencies(self) -> list:
        """Symbolic roots ω² of ``|a ω² − c| = 0`` (small systems)."""
        w2 = sp.Symbol("w2")
        return solve((self.a * w2 - self.c).det(), w2, what="the frequency equation")

    def _repr_latex_(self) -> str:
        from ..display import linear_model_latex

        return linear_model_latex(self)


def linearize(system, about: Mapping | None = None, velocities: Mapping | None = None) -> LinearModel:
    """Linearize about ``q₀`` (default 0) with reference velocities (default 0; non-zero for a steady motion
    of non-ignorable coordinates is not meaningful — use :mod:`lagrange.analysis.steady_motion`).

    ``a = M(q₀)``, ``b = −∂f/∂q̇``, ``c = −∂f/∂q``, ``F = f`` at the reference (a non-equilibrium reference
    gives a constant or time-dependent ``F``).
    """
    eqs = system.derived
    ref = {s: 0 for s in eqs.q}
    ref.update(_state_map(system, about or {}))
    vref = {v: 0 for v in eqs.qd}
    for q in system.coordinates:
        if velocities and q.diff(t) in velocities:
            vref[velocity_symbol(q)] = sp.sympify(velocities[q.diff(t)])
    at = {**ref, **vref}
    f = sp.Matrix(eqs.forcing)
    a = sp.Matrix(eqs.mass_matrix).subs(at)
    b = -f.jacobian(list(eqs.qd)).subs(at)
    c = -f.jacobian(list(eqs.q)).subs(at)
    F = f.subs(at)
    simp = lambda M: M.applyfunc(lambda e: simplify(e, limit=199))  # noqa: E731
    return LinearModel(system.coordinates, simp(a), simp(b), simp(c), simp(F),
                       {q: ref[position_symbol(q)] for q in system.coordinates})


@dataclass(frozen=True)
class Modes:
    """Numeric normal modes of ``a s̈ + c s = 0``.

    Attributes
    ----------
    omega : ndarray (n,) — angular frequencies, ascending (0 for rigid-body modes)
    shapes : ndarray (n, n) — column s is mode s, normalized so that ``shapesᵀ a shapes = I`` (Wells 10.21)
    a, c : the matrices used
    """

    omega: np.ndarray
    shapes: np.ndarray
    a: np.ndarray
    c: np.ndarray

    @property
    def periods(self) -> np.ndarray:
        """2π/ω (infinite for zero modes)."""
        with np.errstate(divide="ignore"):
            return np.where(self.omega > 0, 2 * np.pi / np.where(self.omega > 0, self.omega, 1), np.inf)

    def ratios(self, reference: int = 0) -> np.ndarray:
        """Mode shapes scaled so that component ``reference`` is 1 (Wells' cofactor ratios d_rs/d_1s)."""
        return self.shapes / self.shapes[reference, :]

    def normal_coordinates(self, s) -> np.ndarray:
        """``g = Φᵀ a s`` (Wells 10.25) for displacement(s) ``s`` of shape (n,) or (m, n)."""
        return np.asarray(s) @ (self.shapes.T @ self.a).T

    def fit(self, s0, v0):
        """Amplitude and phase of each mode for initial displacements ``s0`` and velocities ``v0``:
        ``s(t) = Σ Φ_s A_s cos(ω_s t + φ_s)`` (Wells 10.27–10.28); a zero mode gets ``g = g0 + ġ0 t``
        (returned as A = g0, phase = ġ0 for those)."""
        g0, gd0 = self.normal_coordinates(s0), self.normal_coordinates(v0)
        A, ph = np.empty_like(g0), np.empty_like(g0)
        for k, w in enumerate(self.omega):
            if w > 1e-12:
                A[k] = np.hypot(g0[k], gd0[k] / w)
                ph[k] = np.arctan2(-gd0[k] / w, g0[k])
            else:
                A[k], ph[k] = g0[k], gd0[k]
        return A, ph

    def motion(self, s0, v0, times) -> np.ndarray:
        """The linear solution at ``times``, shape (m, n)."""
        A, ph = self.fit(s0, v0)
        times = np.asarray(times, dtype=float)
        g = np.empty((len(times), len(self.omega)))
        for k, w in enumerate(self.omega):
            g[:, k] = A[k] * np.cos(w * times + ph[k]) if w > 1e-12 else A[k] + ph[k] * times
        return g @ self.shapes.T

    def _repr_html_(self) -> str:
        from ..display import modes_html

        return modes_html(self)


def normal_modes(linear: LinearModel, params: Mapping) -> Modes:
    """Generalized symmetric eigenproblem ``c Φ = a Φ ω²`` (scipy.linalg.eigh). Raises when ``a`` is not
    positive definite or ``c`` has negative eigenvalues (an unstable equilibrium: no oscillation)."""
    a, _, c = linear.numeric(params)
    c = (c + c.T) / 2
    try:
        w2, Phi = scipy.linalg.eigh(c, a)
    except np.linalg.LinAlgError as exc:
        raise LagrangeError(f"the mass matrix at the equilibrium is not positive definite: {exc}") from None
    scale = max(1.0, float(np.max(np.abs(w2))))
    if np.any(w2 < -1e-10 * scale):
        raise LagrangeError(f"unstable equilibrium: negative ω² {w2[w2 < 0]} (c is not positive semi-definite)")
    w2 = np.where(np.abs(w2) < 1e-12 * scale, 0.0, w2)
    return Modes(np.sqrt(np.maximum(w2, 0.0)), Phi, a, c)


def characteristic_roots(linear: LinearModel, params: Mapping) -> np.ndarray:
    """Roots λ of ``|a λ² + b λ + c| = 0`` (damped or gyroscopic), from the first-order companion form;
    stable when every real part ≤ 0 (Wells 10.17)."""
    a, b, c = linear.numeric(params)
    n = a.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(a, c), -np.linalg.solve(a, b)]])
    return np.sort_complex(np.linalg.eigvals(A))

