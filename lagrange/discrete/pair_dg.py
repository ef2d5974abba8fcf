r"""Energy-conserving discrete-gradient integrator for particles with pair and uniform external forces.

Greenspan's scheme (Greenspan 1996; LaBudde & Greenspan), for particles i with masses m_i, a pair potential
φ(r) between every two particles and weights m_i g_i along −z:

.. math::

    \frac{x_{n+1}-x_n}{\Delta t} = \frac{v_{n+1}+v_n}{2},\qquad
    m_i\frac{v_{i,n+1}-v_{i,n}}{\Delta t} = -\sum_{j\ne i} D(r_{ij,n}, r_{ij,n+1})\,
    \frac{x_{i,n+1}+x_{i,n}-x_{j,n+1}-x_{j,n}}{r_{ij,n+1}+r_{ij,n}} - m_i g_i e_z

with the divided difference ``D(a, b) = (φ(b) − φ(a))/(b − a)``. The energy
``Σ ½m v² + Σ φ(r) + Σ m g z`` telescopes exactly; linear and angular momentum are conserved whenever
the external forces allow it (about the vertical through a fixed point, etc.).

The divided difference cancels catastrophically when b ≈ a; it is therefore **rewritten symbolically**
(``sympy.cancel`` removes the factor b − a for rational φ, e.g.
``(b⁻ᵏ − a⁻ᵏ)/(b − a) = −Σ_{j<k} bʲa^{k−1−j}/(aᵏbᵏ)``), and the generated code never subtracts nearby values.
Non-rational φ fall back to the plain quotient with a midpoint-derivative guard at |b − a| < 1e-9·a
(energy then conserved to that guard's accuracy).

Fixed constraints "coordinate c of particle i held at a value" (the top's tip on the plane z = 0)
remove that unknown; its reaction does no work. The implicit step is solved by Newton's method with the
generated Jacobian; the whole loop is compiled with numba (``pip install "lagrange-dynamics[fast]"``), so millions of
steps run without Python in the loop.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..codegen.source import print_expr
from ..errors import IntegrationError
from ..simplification import is_zero

__all__ = ["divided_difference", "PairSystem", "DGResult"]

_a, _b = sp.symbols("a b", positive=True)


def divided_difference(phi, r: sp.Symbol) -> tuple[sp.Expr, sp.Expr, bool]:
    """``D(a, b) = (φ(b) − φ(a))/(b − a)`` without the subtraction when possible, and ``∂D/∂b``.

    Returns ``(D, dD/db, exact)`` in the symbols ``a, b``; ``exact`` is False when the cancellation could
    not be removed symbolically (non-rational φ)."""
    phi = sp.sympify(phi)
    q = sp.cancel((phi.subs(r, _b) - phi.subs(r, _a)) / (_b - _a))
    num, den = sp.fraction(sp.together(q))
    exact = not sp.Poly(den, _a, _b).as_expr().has(_b - _a) if den.is_polynomial(_a, _b) else False
    exact = exact and not is_zero(den.subs(_b, _a)) and q.is_rational_function(_a, _b)
    if not exact:
        q = (phi.subs(r, _b) - phi.subs(r, _a)) / (_b - _a)
    return q, sp.diff(q, _b), bool(exact)


_TEMPLATE = '''
@numba.njit(cache=True)
def dd(a, b):
    return {D}


@numba.njit(cache=True)
def dd_b(a, b):
    return {Db}


@numba.njit(cache=True)
def dd_mid(a, b):
    # guard for a non-rational potential: the derivative at the midpoint when b is close to a
    if abs(b - a) > 1e-9 * a:
        return dd(a, b)
    return {dphi_mid}


@numba.njit(cache=True)
def ext_U(x, y, z):
    return {U}


@numba.njit(cache=True)
def ext_grad(x, y, z):
    return np.array([{Ux}, {Uy}, {Uz}])


@numba.njit(cache=True)
def ext_hess(x, y, z):
    return np.array([[{Uxx}, {Uxy}, {Uxz}], [{Uxy}, {Uyy}, {Uyz}], [{Uxz}, {Uyz}, {Uzz}]])


@numba.njit(cache=True)
def _residual(X, x, v, m, g, w, dt, F, with_jac, Jfull):
    N = x.shape[0]
    for i in range(N):
        for c in range(3):
            F[i, c] = m[i] * (2.0 * (X[i, c] - x[i, c]) / dt - 2.0 * v[i, c]) / dt
        F[i, 2] += m[i] * g[i]
    if with_jac:
        for p in range(3 * N):
            for q in range(3 * N):
                Jfull[p, q] = 0.0
        for i in range(N):
            for c in range(3):
                Jfull[3 * i + c, 3 * i + c] = 2.0 * m[i] / (dt * dt)
    # external potential w_i U(x_i): Gonzalez' midpoint discrete gradient (exact energy balance)
    for i in range(N):
        if w[i] == 0.0:
            continue
        xm0 = 0.5 * (X[i, 0] + x[i, 0])
        xm1 = 0.5 * (X[i, 1] + x[i, 1])
        xm2 = 0.5 * (X[i, 2] + x[i, 2])
        gr = ext_grad(xm0, xm1, xm2)
        d0 = X[i, 0] - x[i, 0]
        d1 = X[i, 1] - x[i, 1]
        d2 = X[i, 2] - x[i, 2]
        dsq = d0 * d0 + d1 * d1 + d2 * d2
        corr = 0.0
        if dsq > 1e-28 * (1.0 + xm0 * xm0 + xm1 * xm1 + xm2 * xm2):
            dU = ext_U(X[i, 0], X[i, 1], X[i, 2]) - ext_U(x[i, 0], x[i, 1], x[i, 2])
            corr = (dU - (gr[0] * d0 + gr[1] * d1 + gr[2] * d2)) / dsq
        F[i, 0] += w[i] * (gr[0] + corr * d0)
        F[i, 1] += w[i] * (gr[1] + corr * d1)
        F[i, 2] += w[i] * (gr[2] + corr * d2)
        if with_jac:
            H = ext_hess(xm0, xm1, xm2)
            for c in range(3):
                for k in range(3):
                    Jfull[3 * i + c, 3 * i + k] += 0.5 * w[i] * H[c, k]
    for i in range(N):
        for j in range(i + 1, N):
            n0 = X[i, 0] - X[j, 0]
            n1 = X[i, 1] - X[j, 1]
            n2 = X[i, 2] - X[j, 2]
            o0 = x[i, 0] - x[j, 0]
            o1 = x[i, 1] - x[j, 1]
            o2 = x[i, 2] - x[j, 2]
            b = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
            a = math.sqrt(o0 * o0 + o1 * o1 + o2 * o2)
            D = {DCALL}
            rho = a + b
            w0 = n0 + o0
            w1 = n1 + o1
            w2 = n2 + o2
            f = D / rho
            F[i, 0] += f * w0
            F[i, 1] += f * w1
            F[i, 2] += f * w2
            F[j, 0] -= f * w0
            F[j, 1] -= f * w1
            F[j, 2] -= f * w2
            if with_jac:
                Db = dd_b(a, b)
                coef = (Db / rho - D / (rho * rho)) / b
                w = (w0, w1, w2)
                nn = (n0, n1, n2)
                for c in range(3):
                    for k in range(3):
                        val = w[c] * nn[k] * coef
                        if c == k:
                            val += f
                        Jfull[3 * i + c, 3 * i + k] += val
                        Jfull[3 * i + c, 3 * j + k] -= val
                        Jfull[3 * j + c, 3 * i + k] -= val
                        Jfull[3 * j + c, 3 * j + k] += val


@numba.njit(cache=True)
def _lu(A, piv):
    n = A.shape[0]
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(A[i, k]) > abs(A[p, k]):
                p = i
        piv[k] = p
        if p != k:
            for j in range(n):
                A[k, j], A[p, j] = A[p, j], A[k, j]
        for i in range(k + 1, n):
            A[i, k] /= A[k, k]
            f = A[i, k]
            for j in range(k + 1, n):
                A[i, j] -= f * A[k, j]


@numba.njit(cache=True)
def _lu_solve(LU, piv, b):
    n = b.shape[0]
    for k in range(n):
        p = piv[k]
        if p != k:
            b[k], b[p] = b[p], b[k]
    for i in range(n):
        s = b[i]
        for j in range(i):
            s -= LU[i, j] * b[j]
        b[i] = s
    for i in range(n - 1, -1, -1):
        s = b[i]
        for j in range(i + 1, n):
            s -= LU[i, j] * b[j]
        b[i] = s / LU[i, i]


@numba.njit(cache=True)
def run(x0, v0, m, g, w, free, dt, steps, record_every, fall_particles, tol, max_iter, refresh):
    # simplified Newton: the Jacobian (which changes little over dt) is refactored every `refresh` steps
    # and whenever an iteration stalls; each step iterates to the tolerance
    N = x0.shape[0]
    nf = free.shape[0]
    n_rec = steps // record_every + 1
    xs = np.zeros((n_rec, N, 3))
    vs = np.zeros((n_rec, N, 3))
    x = x0.copy()
    v = v0.copy()
    xs[0] = x
    vs[0] = v
    F = np.zeros((N, 3))
    Jfull = np.zeros((3 * N, 3 * N))
    LU = np.zeros((nf, nf))
    piv = np.zeros(nf, dtype=np.int64)
    R = np.zeros(nf)
    X = np.zeros((N, 3))
    rec = 1
    newton_total = 0
    status = 0
    fell_at = -1
    age = refresh
    for n in range(steps):
        for i in range(N):
            for c in range(3):
                X[i, c] = x[i, c] + dt * v[i, c]
        converged = False
        for it in range(max_iter):
            need = age >= refresh or it >= 4
            _residual(X, x, v, m, g, w, dt, F, need, Jfull)
            if need:
                for p in range(nf):
                    for q in range(nf):
                        LU[p, q] = Jfull[free[p], free[q]]
                _lu(LU, piv)
                age = 0
            for p in range(nf):
                R[p] = F[free[p] // 3, free[p] % 3]
            _lu_solve(LU, piv, R)
            big = 0.0
            for p in range(nf):
                X[free[p] // 3, free[p] % 3] -= R[p]
                if abs(R[p]) > big:
                    big = abs(R[p])
            newton_total += 1
            if big <= tol:
                converged = True
                break
        age += 1
        if not converged:
            status = 2
            break
        for i in range(N):
            for c in range(3):
                v[i, c] = 2.0 * (X[i, c] - x[i, c]) / dt - v[i, c]
                x[i, c] = X[i, c]
        for k in range(fall_particles.shape[0]):
            if x[fall_particles[k], 2] <= 0.0:
                status = 1
                fell_at = n + 1
        if (n + 1) % record_every == 0 and rec < n_rec:
            xs[rec] = x
            vs[rec] = v
            rec += 1
        if status == 1:
            if rec < n_rec:
                xs[rec] = x
                vs[rec] = v
                rec += 1
            break
    return xs[:rec], vs[:rec], status, fell_at, newton_total
'''


def _module(source: str):
    from ..codegen.numba_backend import _require_numba, import_module, write_module

    _require_numba("the discrete-gradient particle integrator")
    return import_module(*write_module("pairdg", "import math\nimport numpy as np\nimport numba\n" + source))


@dataclass(frozen=True)
class DGResult:
    """Recorded states (every ``record_every`` steps): ``t`` (k,), ``x``, ``v`` (k, N, 3); ``fell`` and
    ``fall_time`` when a watched particle reached z ≤ 0; Newton iterations in total."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    fell: bool
    fall_time: float | None
    newton_iterations: int
    steps: int


class PairSystem:
    """Particles with one pair potential φ(r) (every pair), weights ``m_i g_i`` along −z, an optional
    external potential ``w_i U(x, y, z)`` per particle (``external=U`` in the symbols x, y, z,
    ``external_weights=w``; Gonzalez' midpoint discrete gradient keeps the energy balance exact), and
    fixed coordinates (``fixed=[(particle, axis)]``, axis 0/1/2 for x/y/z, held at their initial values).

    >>> import sympy as sp
    >>> r = sp.Symbol("r", positive=True)
    >>> D, Db, exact = divided_difference(1 / r**3, r)
    >>> exact, sp.simplify(D - (-(_a**2 + _a*_b + _b**2) / (_a**3 * _b**3)))
    (True, 0)
    """

    def __init__(self, masses: Sequence[float], potential, r: sp.Symbol, *, weights: Sequence[float] | None = None,
                 fixed: Sequence[tuple[int, int]] = (), external=None, external_weights: Sequence[float] | None = None):
        self.masses = np.asarray(masses, dtype=float)
        N = len(self.masses)
        if not np.all(self.masses > 0):
            raise ValueError("particle masses must be positive")
        self.g = np.zeros(N) if weights is None else np.asarray(weights, dtype=float)
        self.fixed = tuple(fixed)
        self.potential = sp.sympify(potential)
        self.r = r
        D, Db, exact = divided_difference(self.potential, r)
        self.exact = exact
        dphi_mid = sp.diff(self.potential, r).subs(r, (_a + _b) / 2)
        X, Y, Z = sp.symbols("x y z", real=True)
        U = sp.sympify(external if external is not None else 0)
        bad = U.free_symbols - {X, Y, Z}
        if bad:
            raise ValueError(f"the external potential may use only x, y, z (Symbol('x', real=True), …); got {bad}")
        self.external = U
        self.w = np.zeros(N) if external_weights is None else np.asarray(external_weights, dtype=float)
        grads = [sp.diff(U, s) for s in (X, Y, Z)]
        hes = {f"U{a}{b}": sp.diff(U, sa, sb) for a, sa in zip("xyz", (X, Y, Z)) for b, sb in zip("xyz", (X, Y, Z))}
        src = _TEMPLATE.format(D=print_expr(D), Db=print_expr(Db), dphi_mid=print_expr(dphi_mid),
                               DCALL="dd(a, b)" if exact else "dd_mid(a, b)", U=print_expr(U) + " + 0.0 * x",
                               Ux=print_expr(grads[0]) + " + 0.0 * x", Uy=print_expr(grads[1]) + " + 0.0 * y",
                               Uz=print_expr(grads[2]) + " + 0.0 * z",
                               **{k: print_expr(v) + " + 0.0 * x" for k, v in hes.items()})
        self._U = sp.lambdify((X, Y, Z), U, "numpy")
        self._mod = _module(src)
        self._phi = sp.lambdify(r, self.potential, "numpy")
        free = [3 * i + c for i in range(N) for c in range(3) if (i, c) not in self.fixed]
        self._free = np.array(free, dtype=np.int64)

    def energy(self, x: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Total energy of recorded states, shape (k,)."""
        x, v = np.atleast_3d(x), np.atleast_3d(v)
        if x.ndim == 2:
            x, v = x[None], v[None]
        ke = 0.5 * np.einsum("i,kic->k", self.masses, v * v)
        N = len(self.masses)
        pe = np.zeros(len(x))
        for i in range(N):
            for j in range(i + 1, N):
                pe += self._phi(np.linalg.norm(x[:, i] - x[:, j], axis=1))
        pe += np.einsum("i,ki->k", self.masses * self.g, x[:, :, 2])
        for i in range(N):
            if self.w[i]:
                pe += self.w[i] * np.broadcast_to(self._U(x[:, i, 0], x[:, i, 1], x[:, i, 2]), pe.shape)
        return ke + pe

    def integrate(self, x0, v0, *, dt: float, steps: int, record_every: int = 1,
                  fall_particles: Sequence[int] = (), tol: float = 1e-13, max_iter: int = 30,
                  refresh: int = 20) -> DGResult:
        """Run ``steps`` steps of size ``dt`` (compiled loop); stop early when a ``fall_particles`` z ≤ 0.

        Each step is iterated to ``tol`` (absolute, on the position update) by a simplified Newton method
        whose Jacobian is refreshed every ``refresh`` steps (and when an iteration stalls)."""
        x0 = np.ascontiguousarray(x0, dtype=float)
        v0 = np.ascontiguousarray(v0, dtype=float)
        xs, vs, status, fell_at, its = self._mod.run(
            x0, v0, self.masses, self.g, self.w, self._free, float(dt), int(steps), int(record_every),
            np.asarray(fall_particles, dtype=np.int64), float(tol), int(max_iter), int(refresh))
        if status == 2:
            raise IntegrationError("discrete-gradient step: Newton did not converge; reduce dt")
        k = xs.shape[0]
        t = np.arange(k, dtype=float) * dt * record_every
        if status == 1:
            t[-1] = fell_at * dt
        return DGResult(t, xs, vs, status == 1, fell_at * dt if status == 1 else None, int(its), int(steps))
