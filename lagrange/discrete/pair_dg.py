r"""Energy-conserving discrete-gradient integrator for particles with pair and uniform external forces.

Greenspan's scheme (Greenspan 1996; LaBudde & Greenspan), for particles i with masses m_i, a pair potential
φ(r) between every two particles and weights m_i g_i along −z:

.. math::

    \frac{x_{n+1}-x_n}{\Delta t} = \frac{v_{n+1}+v_n}{2},\qquad
    m_i\frac{v_{i,n+1}-v_{i,n}}{\Delta t} = F_i := -\sum_{j\ne i} D(r_{ij,n}, r_{ij,n+1})\,
    \frac{x_{i,n+1}+x_{i,n}-x_{j,n+1}-x_{j,n}}{r_{ij,n+1}+r_{ij,n}} - m_i g_i e_z

with the divided difference ``D(a, b) = (φ(b) − φ(a))/(b − a)``. The energy
``Σ ½m v² + Σ φ(r) + Σ m g z`` telescopes exactly; linear and angular momentum are conserved whenever
the external forces allow it (about the vertical through a fixed point, etc.).

The divided difference cancels catastrophically when b ≈ a; it is therefore **rewritten symbolically**
(``sympy.cancel`` removes the factor b − a for rational φ, e.g.
``(b⁻ᵏ − a⁻ᵏ)/(b − a) = −Σ_{j<k} bʲa^{k−1−j}/(aᵏbᵏ)``), and the generated code never subtracts nearby values.
Non-rational φ fall back to the plain quotient with a midpoint-derivative guard at |b − a| < 1e-9·a
(energy then conserved to that guard's accuracy).

**Rounding.** The loop works in positions relative to the initial centre of mass ``c`` (the origin of the
output is added back only when states are recorded) and takes the increments ``Δ = x_{n+1} − x_n`` as the
unknowns: with ``h = Δt``

.. math::

    Δ_i = h v_{i,n} + \frac{h^2}{2 m_i} F_i(x_n, x_n + Δ),\qquad v_{i,n+1} = v_{i,n} + \frac{h}{m_i} F_i,

so velocities never come from differences of positions (``2(x_{n+1} − x_n)/h − v_n`` loses
``eps·|x|/h`` per step) and no rounding grows with the distance of the body from the origin: a translated
body follows the same relative trajectory and conserves energy to the same few ulps of ``|E|``. A momentum
component that the forces conserve exactly (horizontal, for the top) is reset to its initial value after
each step, so that its rounding, eps·|v| per step, does not accumulate and move the centre of mass.

**Solver.** The increment equation is a contraction of constant ``h² max|∂F/∂x|/(2m)`` (3e-4 for
Greenspan's top at h = 1e-5), so it is solved by **fixed-point iteration** from the predictor
``h v + h² F̃/(2m)`` (F̃: the force extrapolated quadratically from the last three steps) until the next
change, estimated from the contraction of the last two, is at the rounding level (a few ulps of
``max|Δ|``; 2 force evaluations per step on Greenspan's top). A step on which the iteration contracts by
less than a factor 10 per sweep (a step too large for the stiffness) is solved by **Newton's method** with
the generated Jacobian instead, and so are the next 64 steps before the fixed point is tried again; the
result reports how many steps needed it (``solver="newton"`` forces Newton on every step,
``"fixed-point"`` refuses the fallback).

Fixed constraints "coordinate c of particle i held at a value" (the top's tip on the plane z = 0)
remove that unknown (its increment is 0, so it stays exactly at its initial value); its reaction does no
work. The whole loop is compiled with numba (``pip install "lagrange-dynamics[fast]"``), so millions of
steps run without Python in the loop.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import sympy as sp

from ..codegen.source import print_expr
from ..errors import DeclarationError, InitialConditionError, IntegrationError
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero

__all__ = ["divided_difference", "PairSystem", "DGResult", "SOLVERS"]

#: Solvers of the implicit step: fixed point with Newton fallback, fixed point only, Newton only.
SOLVERS = {"auto": 0, "fixed-point": 1, "newton": 2}

_a, _b = sp.symbols("a b", positive=True)


def divided_difference(phi, r: sp.Symbol) -> tuple[sp.Expr, sp.Expr, bool]:
    """``D(a, b) = (φ(b) − φ(a))/(b − a)`` without the subtraction when possible, and ``∂D/∂b``.

    Returns ``(D, dD/db, exact)`` in the symbols ``a, b``; ``exact`` is False when the cancellation could
    not be removed symbolically (non-rational φ)."""
    phi = _sympify(phi)
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
def _pairs(x, po, pa):
    # old separations x_i - x_j and distances of every pair (fixed during a step)
    N = x.shape[0]
    k = 0
    for i in range(N):
        for j in range(i + 1, N):
            s = 0.0
            for c in range(3):
                po[k, c] = x[i, c] - x[j, c]
                s += po[k, c] * po[k, c]
            pa[k] = math.sqrt(s)
            k += 1


@numba.njit(cache=True)
def _force(x, d, origin, po, pa, m, g, w, F, with_jac, K):
    # F: the discrete-gradient force of the step x -> x + d (m (v_new - v)/dt = F); K = dF/dd if with_jac
    N = x.shape[0]
    for i in range(N):
        F[i, 0] = 0.0
        F[i, 1] = 0.0
        F[i, 2] = -m[i] * g[i]
    if with_jac:
        for p in range(3 * N):
            for q in range(3 * N):
                K[p, q] = 0.0
    # external potential w_i U(x_i): Gonzalez' midpoint discrete gradient (exact energy balance)
    for i in range(N):
        if w[i] == 0.0:
            continue
        a0 = origin[0] + x[i, 0]
        a1 = origin[1] + x[i, 1]
        a2 = origin[2] + x[i, 2]
        d0 = d[i, 0]
        d1 = d[i, 1]
        d2 = d[i, 2]
        gr = ext_grad(a0 + 0.5 * d0, a1 + 0.5 * d1, a2 + 0.5 * d2)
        dsq = d0 * d0 + d1 * d1 + d2 * d2
        corr = 0.0
        if dsq > 1e-28 * (1.0 + a0 * a0 + a1 * a1 + a2 * a2):
            dU = ext_U(a0 + d0, a1 + d1, a2 + d2) - ext_U(a0, a1, a2)
            corr = (dU - (gr[0] * d0 + gr[1] * d1 + gr[2] * d2)) / dsq
        F[i, 0] -= w[i] * (gr[0] + corr * d0)
        F[i, 1] -= w[i] * (gr[1] + corr * d1)
        F[i, 2] -= w[i] * (gr[2] + corr * d2)
        if with_jac:
            H = ext_hess(a0 + 0.5 * d0, a1 + 0.5 * d1, a2 + 0.5 * d2)
            for c in range(3):
                for k in range(3):
                    K[3 * i + c, 3 * i + k] -= 0.5 * w[i] * H[c, k]
    k = 0
    for i in range(N):
        for j in range(i + 1, N):
            o0 = po[k, 0]
            o1 = po[k, 1]
            o2 = po[k, 2]
            n0 = o0 + (d[i, 0] - d[j, 0])
            n1 = o1 + (d[i, 1] - d[j, 1])
            n2 = o2 + (d[i, 2] - d[j, 2])
            a = pa[k]
            k += 1
            b = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
            D = {DCALL}
            rho = a + b
            w0 = n0 + o0
            w1 = n1 + o1
            w2 = n2 + o2
            f = D / rho
            F[i, 0] -= f * w0
            F[i, 1] -= f * w1
            F[i, 2] -= f * w2
            F[j, 0] += f * w0
            F[j, 1] += f * w1
            F[j, 2] += f * w2
            if with_jac:
                coef = (dd_b(a, b) / rho - D / (rho * rho)) / b
                wv = (w0, w1, w2)
                nn = (n0, n1, n2)
                for c in range(3):
                    for e in range(3):
                        val = wv[c] * nn[e] * coef
                        if c == e:
                            val += f
                        K[3 * i + c, 3 * i + e] -= val
                        K[3 * i + c, 3 * j + e] += val
                        K[3 * j + c, 3 * i + e] += val
                        K[3 * j + c, 3 * j + e] -= val


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
def _fixed_point(x, v, d, origin, po, pa, m, g, w, free, h, h2m, F, K, tol, max_iter):
    # d <- h v + h^2/(2m) F(x, x + d) until the next change, estimated from the contraction of the last
    # two, is below tol * max|d| (the rounding level); returns the iterations (negative when the iteration
    # does not contract); F is left at the force from which the accepted d was computed
    nf = free.shape[0]
    prev = np.inf
    for it in range(max_iter):
        _force(x, d, origin, po, pa, m, g, w, F, False, K)
        delta = 0.0
        scale = 0.0
        for p in range(nf):
            i = free[p] // 3
            c = free[p] % 3
            new = h * v[i, c] + h2m[i] * F[i, c]
            ch = abs(new - d[i, c])
            if ch > delta:
                delta = ch
            if abs(new) > scale:
                scale = abs(new)
            d[i, c] = new
        if delta <= tol * scale:
            return it + 1
        if it >= 1:
            if delta < prev and delta * (delta / prev) <= tol * scale:  # the next change: rounding level
                return it + 1
            if delta <= 64.0 * tol * scale:
                if delta >= prev:  # the rounding floor: the change no longer decreases
                    return it + 1
            elif delta > 0.1 * prev:  # contracts too slowly (or not at all): Newton is cheaper
                return -(it + 1)
        prev = delta
    return -max_iter


@numba.njit(cache=True)
def _newton(x, v, d, origin, po, pa, m, g, w, free, h, h2m, F, K, LU, piv, R, tol, max_iter):
    # solve G(d) = d - h v - h^2/(2m) F(x, x + d) = 0 with the full Jacobian I - h^2/(2m) dF/dd;
    # returns the iterations (negative when it does not converge); F is left at the force of the accepted d
    nf = free.shape[0]
    for it in range(max_iter):
        _force(x, d, origin, po, pa, m, g, w, F, True, K)
        for p in range(nf):
            i = free[p] // 3
            R[p] = d[i, free[p] % 3] - h * v[i, free[p] % 3] - h2m[i] * F[i, free[p] % 3]
            for q in range(nf):
                LU[p, q] = -h2m[i] * K[free[p], free[q]]
            LU[p, p] += 1.0
        _lu(LU, piv)
        _lu_solve(LU, piv, R)
        delta = 0.0
        scale = 0.0
        for p in range(nf):
            i = free[p] // 3
            c = free[p] % 3
            d[i, c] -= R[p]
            if abs(R[p]) > delta:
                delta = abs(R[p])
            if abs(d[i, c]) > scale:
                scale = abs(d[i, c])
        if not (delta <= scale):  # NaN or a step larger than the increment itself: not converging
            if it > 8:
                return -(it + 1)
        if delta <= 64.0 * tol * scale:
            # one fixed-point sweep makes d consistent with the force used for the velocity update
            _force(x, d, origin, po, pa, m, g, w, F, False, K)
            for p in range(nf):
                i = free[p] // 3
                c = free[p] % 3
                d[i, c] = h * v[i, c] + h2m[i] * F[i, c]
            return it + 1
    return -max_iter


@numba.njit(cache=True)
def run(x0, v0, origin, m, g, w, free, dt, steps, record_every, fall_particles, tol, max_fp, max_newton, mode,
        conserved):
    # positions x are relative to `origin`; mode 0: fixed point, Newton when it does not contract;
    # 1: fixed point only; 2: Newton only. status 0 ok, 1 fell, 2 no convergence
    N = x0.shape[0]
    nf = free.shape[0]
    n_rec = steps // record_every + 2
    xs = np.zeros((n_rec, N, 3))
    vs = np.zeros((n_rec, N, 3))
    x = x0.copy()
    v = v0.copy()
    xs[0] = x
    vs[0] = v
    F = np.zeros((N, 3))
    K = np.zeros((3 * N, 3 * N))
    LU = np.zeros((nf, nf))
    piv = np.zeros(nf, dtype=np.int64)
    R = np.zeros(nf)
    d = np.zeros((N, 3))
    npair = N * (N - 1) // 2
    po = np.zeros((npair, 3))
    pa = np.zeros(npair)
    h2m = np.empty(N)
    for i in range(N):
        h2m[i] = dt * dt / (2.0 * m[i])
    rec = 1
    fp_total = 0
    newton_steps = 0
    newton_total = 0
    status = 0
    fall_time = -1.0
    failed_at = -1
    taken = 0
    skip = 0
    mtot = 0.0
    P0 = np.zeros(3)
    for i in range(N):
        mtot += m[i]
        for c in range(3):
            P0[c] += m[i] * v[i, c]
    _pairs(x, po, pa)
    _force(x, d, origin, po, pa, m, g, w, F, False, K)  # the force at x_0 for the first predictor
    F1 = F.copy()  # the forces of the last three steps, extrapolated for the predictor
    F2 = F.copy()
    F3 = F.copy()
    for n in range(steps):
        _pairs(x, po, pa)
        for p in range(nf):  # predictor: the force extrapolated (quadratically) from the last steps
            i = free[p] // 3
            c = free[p] % 3
            if n >= 2:
                fp = 3.0 * (F1[i, c] - F2[i, c]) + F3[i, c]
            elif n == 1:
                fp = 2.0 * F1[i, c] - F2[i, c]
            else:
                fp = F1[i, c]
            d[i, c] = dt * v[i, c] + h2m[i] * fp
        its = -1
        if mode == 1 or (mode == 0 and skip == 0):
            its = _fixed_point(x, v, d, origin, po, pa, m, g, w, free, dt, h2m, F, K, tol, max_fp)
            fp_total += abs(its)
            if its < 0:
                skip = 64  # Newton for the next steps too before trying the fixed point again
        elif skip > 0:
            skip -= 1
        if its < 0:
            if mode == 1:
                status = 2
                failed_at = n
                break
            for p in range(nf):
                i = free[p] // 3
                c = free[p] % 3
                d[i, c] = dt * v[i, c] + h2m[i] * F1[i, c]
            nits = _newton(x, v, d, origin, po, pa, m, g, w, free, dt, h2m, F, K, LU, piv, R, tol, max_newton)
            newton_steps += 1
            newton_total += abs(nits)
            if nits < 0:
                status = 2
                failed_at = n
                break
        low = np.inf
        for k in range(fall_particles.shape[0]):
            p = fall_particles[k]
            zo = origin[2] + x[p, 2]
            zn = origin[2] + (x[p, 2] + d[p, 2])
            if zn <= 0.0 < zo:
                s = n + zo / (zo - zn)
                if s < low:
                    low = s
        for p in range(nf):
            i = free[p] // 3
            c = free[p] % 3
            v[i, c] += (dt / m[i]) * F[i, c]
            x[i, c] += d[i, c]
            F3[i, c] = F2[i, c]
            F2[i, c] = F1[i, c]
            F1[i, c] = F[i, c]
        for c in range(3):  # a conserved momentum component: its rounding is not let accumulate
            if conserved[c]:
                s = 0.0
                for i in range(N):
                    s += m[i] * v[i, c]
                corr = (s - P0[c]) / mtot
                for i in range(N):
                    v[i, c] -= corr
        taken = n + 1
        if low < np.inf:
            status = 1
            fall_time = low * dt
        if (n + 1) % record_every == 0 or status == 1:
            xs[rec] = x
            vs[rec] = v
            rec += 1
        if status == 1:
            break
    return xs[:rec], vs[:rec], status, fall_time, failed_at, taken, fp_total, newton_steps, newton_total
'''


def _module(source: str):
    from ..codegen.numba_backend import _require_numba, import_module, write_module

    _require_numba("the discrete-gradient particle integrator")
    return import_module(*write_module("pairdg", "import math\nimport numpy as np\nimport numba\n" + source))


@record(frozen=True)
class DGResult:
    """A discrete-gradient run.

    Attributes
    ----------
    t : ndarray, shape (k,)
        Recorded times (every ``record_every`` steps, and the fall).
    x, v : ndarray, shape (k, N, 3)
        Positions and velocities at ``t``; fixed coordinates are exactly their initial values.
    fell, fall_time
        Whether a watched particle reached the plane z = 0, and when: the time at which its height,
        linear in t within the step (the scheme's positions are), crosses 0; ``None`` if it did not.
    energy : ndarray, shape (k,)
        Total energy of the recorded states, evaluated in extended precision (``numpy.longdouble``) and
        rounded, so that it measures the states and not the rounding of the sum.
    energy_drift : float
        ``max_k |E_k − E_0|`` (absolute), from the extended-precision values.
    fixed_point_iterations, newton_steps, newton_iterations : int
        Force evaluations of the fixed-point iteration in total; steps solved by Newton's method (the
        fallback, or every step with ``solver="newton"``) and its iterations in total.
    steps : int
        Steps taken (fewer than asked when the top fell).
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    fell: bool
    fall_time: float | None
    energy: np.ndarray
    energy_drift: float
    fixed_point_iterations: int
    newton_steps: int
    newton_iterations: int
    steps: int

    @property
    def energy_drift_ulps(self) -> float:
        """:attr:`energy_drift` in units of ``ulp(|E_0|)`` (``numpy.spacing``)."""
        return float(self.energy_drift / np.spacing(abs(float(self.energy[0]))))

    @property
    def solver(self) -> str:
        """Which solver took the steps: ``"fixed point"``, ``"Newton"`` or ``"fixed point (Newton on k steps)"``."""
        if self.newton_steps == 0:
            return "fixed point"
        if self.fixed_point_iterations == 0:
            return "Newton"
        return f"fixed point (Newton on {self.newton_steps} steps)"

    def solver_report(self) -> str:
        """One line: the solver and its iteration counts per step."""
        n = max(self.steps, 1)
        text = f"solver: {self.solver}; {self.fixed_point_iterations / n:.2f} fixed-point iterations per step"
        if self.newton_steps:
            text += f", {self.newton_iterations / self.newton_steps:.2f} Newton iterations per Newton step"
        return text


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
        if self.masses.ndim != 1 or N < 2 or not np.all(np.isfinite(self.masses) & (self.masses > 0)):
            raise DeclarationError(f"particle masses must be at least two finite positive numbers; got {masses!r}")
        self.g = np.zeros(N) if weights is None else np.asarray(weights, dtype=float)
        if self.g.shape != (N,) or not np.all(np.isfinite(self.g)):
            raise DeclarationError(f"weights: one finite value per particle ({N}); got {weights!r}")
        bad_fixed = [f for f in fixed if len(f) != 2 or not 0 <= int(f[0]) < N or int(f[1]) not in (0, 1, 2)]
        if bad_fixed:
            raise DeclarationError(f"fixed: (particle 0…{N - 1}, axis 0/1/2) pairs; got {bad_fixed}")
        self.fixed = tuple((int(i), int(c)) for i, c in fixed)
        self.potential = _sympify(potential)
        self.r = r
        D, Db, exact = divided_difference(self.potential, r)
        self.exact = exact
        dphi_mid = sp.diff(self.potential, r).subs(r, (_a + _b) / 2)
        X, Y, Z = sp.symbols("x y z", real=True)
        U = _sympify(external if external is not None else 0)
        bad = U.free_symbols - {X, Y, Z}
        if bad:
            raise DeclarationError(f"the external potential may use only x, y, z (Symbol('x', real=True), …); "
                                   f"got {bad}")
        self.external = U
        self.w = np.zeros(N) if external_weights is None else np.asarray(external_weights, dtype=float)
        grads = [sp.diff(U, s) for s in (X, Y, Z)]
        hes = {f"U{a}{b}": sp.diff(U, sa, sb) for a, sa in zip("xyz", (X, Y, Z)) for b, sb in zip("xyz", (X, Y, Z))}
        src = _TEMPLATE.format(D=print_expr(D), Db=print_expr(Db), dphi_mid=print_expr(dphi_mid),
                               DCALL="dd(a, b)" if exact else "dd_mid(a, b)", U=print_expr(U) + " + 0.0 * x",
                               Ux=print_expr(grads[0]) + " + 0.0 * x", Uy=print_expr(grads[1]) + " + 0.0 * y",
                               Uz=print_expr(grads[2]) + " + 0.0 * z",
                               **{k: print_expr(v) + " + 0.0 * x" for k, v in hes.items()})
        self._U = _lambdify((X, Y, Z), U, "numpy")
        self._mod = _module(src)
        self._phi = _lambdify(r, self.potential, "numpy")
        free = [3 * i + c for i in range(N) for c in range(3) if (i, c) not in self.fixed]
        self._free = np.array(free, dtype=np.int64)
        # momentum components the scheme conserves exactly (pair forces cancel; nothing external acts along c)
        self._conserved = np.array([not np.any(self.w) and all(ax != c for _, ax in self.fixed)
                                    and (c != 2 or not np.any(self.g)) for c in range(3)], dtype=np.bool_)

    def energy(self, x: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Total energy ``Σ ½ m v² + Σ_{i<j} φ(r_ij) + Σ m g z + Σ w U`` of states ``x``, ``v`` (shape (N, 3)
        or (k, N, 3)), evaluated in extended precision (``numpy.longdouble``); returns shape (k,), float."""
        return self._energy(np.asarray(x, dtype=float), np.asarray(v, dtype=float)).astype(float)

    def _energy(self, x, v, origin=None) -> np.ndarray:
        ld = np.longdouble
        if x.ndim == 2:
            x, v = x[None], v[None]
        x, v = x.astype(ld), v.astype(ld)
        ke = ld(0.5) * np.einsum("i,kic->k", self.masses.astype(ld), v * v)
        N = len(self.masses)
        pe = np.zeros(len(x), dtype=ld)
        for i in range(N):
            for j in range(i + 1, N):
                sep = x[:, i] - x[:, j]
                pe += self._phi(np.sqrt(np.einsum("kc,kc->k", sep, sep)))
        xa = x if origin is None else x + np.asarray(origin, dtype=float).astype(ld)
        pe += np.einsum("i,ki->k", (self.masses * self.g).astype(ld), xa[:, :, 2])
        for i in range(N):
            if self.w[i]:
                pe += ld(self.w[i]) * np.broadcast_to(self._U(xa[:, i, 0], xa[:, i, 1], xa[:, i, 2]), pe.shape)
        return ke + pe

    def _check_start(self, x0, v0, fall_particles) -> None:
        N = len(self.masses)
        problems = []
        for name, arr in (("x0", x0), ("v0", v0)):
            if arr.shape != (N, 3):
                problems.append(f"{name} must have shape ({N}, 3), one row per particle; got {arr.shape}")
            elif not np.all(np.isfinite(arr)):
                problems.append(f"{name} has non-finite entries")
        if not problems:
            for i, c in self.fixed:
                if v0[i, c] != 0.0:
                    problems.append(f"particle {i} coordinate {'xyz'[c]} is fixed but starts with velocity "
                                    f"{v0[i, c]:g} (a fixed coordinate starts at rest)")
            for p in fall_particles:
                if x0[p, 2] <= 0.0:
                    problems.append(f"watched particle {p} starts at z = {x0[p, 2]:g}, not above the plane z = 0")
        if problems:
            raise InitialConditionError("; ".join(problems))

    def integrate(self, x0, v0, *, dt: float, steps: int, record_every: int = 1,
                  fall_particles: Sequence[int] = (), solver: str = "auto", tol: float = 4 * np.finfo(float).eps,
                  max_iter: int = 12, max_newton: int = 30) -> DGResult:
        """Run ``steps`` steps of size ``dt`` (compiled loop); stop early when a ``fall_particles`` z ≤ 0.

        Parameters
        ----------
        x0, v0 : array_like, shape (N, 3)
            Initial positions and velocities (fixed coordinates must start at rest).
        solver : {"auto", "fixed-point", "newton"}
            ``"auto"``: fixed-point iteration, Newton's method on a step where it does not contract;
            ``"fixed-point"``: raise :class:`~lagrange.errors.IntegrationError` instead; ``"newton"``:
            Newton on every step.
        tol : float
            Relative convergence tolerance on the increments (a few eps: the rounding floor).
        max_iter, max_newton : int
            Iteration caps per step of the fixed point (then the fallback) and of Newton.

        Raises
        ------
        InitialConditionError
            Bad shapes, non-finite values, a moving fixed coordinate or a watched particle not above z = 0.
        IntegrationError
            A step that neither solver solves (names the step and time; reduce ``dt``).
        """
        if solver not in SOLVERS:
            raise InitialConditionError(f"solver={solver!r}: choose one of {', '.join(SOLVERS)}")
        if not (math.isfinite(dt) and dt > 0) or int(steps) < 1 or int(record_every) < 1:
            raise InitialConditionError(f"dt must be positive and finite and steps, record_every ≥ 1; got dt={dt!r}, "
                                        f"steps={steps!r}, record_every={record_every!r}")
        x0 = np.ascontiguousarray(x0, dtype=float)
        v0 = np.ascontiguousarray(v0, dtype=float)
        fall = np.asarray(fall_particles, dtype=np.int64)
        self._check_start(x0, v0, fall)
        origin = np.einsum("i,ic->c", self.masses, x0) / self.masses.sum()
        xs, vs, status, fall_time, failed_at, taken, fp, nsteps, nits = self._mod.run(
            x0 - origin, v0, origin, self.masses, self.g, self.w, self._free, float(dt), int(steps),
            int(record_every), fall, float(tol), int(max_iter), int(max_newton), SOLVERS[solver], self._conserved)
        if status == 2:
            how = ("the fixed-point iteration does not converge (its contraction dt² max|∂F/∂x|/(2m) is not "
                   "small; solver='auto' falls back to Newton)" if solver == "fixed-point"
                   else "Newton's method did not converge")
            raise IntegrationError(f"discrete-gradient step {failed_at + 1} (t = {failed_at * dt:g} → "
                                   f"{(failed_at + 1) * dt:g}): {how}; reduce dt")
        E = self._energy(xs, vs, origin)
        x = xs + origin
        for i, c in self.fixed:
            x[:, i, c] = x0[i, c]  # held exactly: its increment is zero
        k = xs.shape[0]
        t = np.arange(k, dtype=float) * dt * record_every
        if status == 1:
            t[-1] = fall_time
        return DGResult(t=t, x=x, v=vs, fell=status == 1, fall_time=float(fall_time) if status == 1 else None,
                        energy=E.astype(float), energy_drift=float(np.max(np.abs(E - E[0]))),
                        fixed_point_iterations=int(fp), newton_steps=int(nsteps), newton_iterations=int(nits),
                        steps=int(taken))
