r"""The compiled fixed-step geometric integrators: generic over the model, compiled once per machine.

A model enters through the three generated functions of :mod:`lagrange.codegen.hamiltonian_source`,
passed as numba first-class functions (:data:`MASS`, :data:`LAGRANGIAN`, :data:`SECOND`); from them this
module evaluates ``q̇ = M⁻¹(p − b)`` (Cholesky), H, ∇H and the exact Hessian, and runs

``run(scheme, mass, lagrangian, second, A, b, c, t0, h, steps, stride, p, tol, max_iter, k_stop, z, T, Y,
counts, info)``

— ``steps`` fixed steps of size ``h`` from ``z = (q, p)``, recording ``[q, q̇]`` every ``stride``-th step
and after the last. ``scheme`` is :data:`GAUSS` (Gauss–Legendre collocation with the tableau ``A, b, c``:
implicit midpoint, GL4, GL6), :data:`VERLET` (Störmer–Verlet), :data:`DG` (Gonzalez' midpoint discrete
gradient) or :data:`COMPOSE` (a symmetric composition of Störmer–Verlet steps of sizes ``b_i h``, the
coefficients in ``b``: :mod:`lagrange.integrate.composition`). It returns a status of :data:`STATUS` (or
:data:`PAUSED` at step ``k_stop``) and keeps everything
else in the arrays passed in, updated in place: the state ``z`` (before the failed step, or the final
state), the recorded times and states ``T[:n_out]``, ``Y[:n_out]`` (on failure the state before the failed
step is the last row), ``counts = [step reached (the failed one when the status is not 0), n_out, total
Newton iterations, iterations of the last step]`` and ``info = [last Newton residual]``. A run is called in
chunks of bounded work (:func:`lagrange.integrate.compiled.run_in_chunks`) so that Ctrl-C, which numba code
cannot see, is acted on between chunks; the chunks give the same result bit for bit as one call.

This is a transcription of the Python schemes (:mod:`lagrange.integrate.gauss_legendre`,
:mod:`~lagrange.integrate.stormer_verlet`, :mod:`~lagrange.integrate.discrete_gradient` and
:func:`lagrange.integrate.base.newton`): the same equations, first guesses, Newton iteration (full Newton
with the exact Jacobian, converged when the residual is below ``tol`` relative to ``1 + max|x|`` or the
update at the round-off floor ``4e-16``) and failure cases; the tests compare the two step by step. Linear
systems are solved by Gaussian elimination with partial pivoting, M by Cholesky. No Python runs per step.

This file must stay self-contained (absolute imports of numpy and numba only): it is imported as a copy in
the cache directory (:func:`lagrange.integrate.compiled.kernel`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.core.types import FunctionType

_VEC = types.float64[::1]
_MAT = types.float64[:, ::1]
#: signatures of the generated functions (lagrange.codegen.hamiltonian_source)
MASS = types.boolean(types.float64, _VEC, _VEC, _MAT, _VEC)
LAGRANGIAN = types.float64(types.float64, _VEC, _VEC, _VEC, _VEC)
SECOND = types.boolean(types.float64, _VEC, _VEC, _VEC, _MAT, _MAT)

GAUSS, VERLET, DG, COMPOSE = 0, 1, 2, 3
#: status codes: 0 success, then the ways a step fails
STATUS = ("success", "Newton did not converge", "Newton diverged (non-finite residual)", "singular Jacobian",
          "mass matrix not positive definite", "non-finite state")
OK, NEWTON_MAX_ITER, NEWTON_DIVERGED, SINGULAR_JACOBIAN, SINGULAR_MASS, NON_FINITE = range(6)

#: the signature of :func:`run`: the state lives in the arrays passed in, the result is the status alone (no
#: array is boxed on return: boxing calls Python, which fails inside numba when a SIGINT is pending)
RUN = types.int64(types.int64, FunctionType(MASS), FunctionType(LAGRANGIAN), FunctionType(SECOND), _MAT, _VEC,
                  _VEC, types.float64, types.float64, types.int64, types.int64, _VEC, types.float64, types.int64,
                  types.int64, _VEC, _VEC, _MAT, types.int64[::1], _VEC)
MOMENTA = types.boolean(FunctionType(MASS), types.float64, _VEC, _VEC, _VEC, _VEC)
#: the status of a run paused at the step ``k_stop`` (call again with the same arrays to go on)
PAUSED = -1

_OPTIONS = dict(cache=True, error_model="numpy")


@njit(**_OPTIONS)
def _cholesky(A, n):
    """Lower Cholesky factor of the symmetric A in place (lower triangle); False when A is not positive
    definite (a pivot not above 1e-13 of its diagonal entry, as the generated LDLᵀ of the right-hand side)."""
    for j in range(n):
        s = A[j, j]
        for k in range(j):
            s -= A[j, k] * A[j, k]
        if not s > 1e-13 * abs(A[j, j]):
            return False
        d = math.sqrt(s)
        A[j, j] = d
        for i in range(j + 1, n):
            s = A[i, j]
            for k in range(j):
                s -= A[i, k] * A[j, k]
            A[i, j] = s / d
    return True


@njit(**_OPTIONS)
def _cholesky_solve(F, n, x):
    """Solve (F Fᵀ) y = x in place, F the lower factor of :func:`_cholesky`."""
    for i in range(n):
        s = x[i]
        for k in range(i):
            s -= F[i, k] * x[k]
        x[i] = s / F[i, i]
    for i in range(n - 1, -1, -1):
        s = x[i]
        for k in range(i + 1, n):
            s -= F[k, i] * x[k]
        x[i] = s / F[i, i]


@njit(**_OPTIONS)
def _lu_solve(J, r, m):
    """Solve J x = r in place (r becomes x; J is destroyed) by Gaussian elimination with partial pivoting;
    False when J is singular (an exactly zero pivot, as LAPACK reports)."""
    for k in range(m):
        p = k
        best = abs(J[k, k])
        for i in range(k + 1, m):
            if abs(J[i, k]) > best:
                best, p = abs(J[i, k]), i
        if best == 0.0:
            return False
        if p != k:
            for j in range(m):
                J[k, j], J[p, j] = J[p, j], J[k, j]
            r[k], r[p] = r[p], r[k]
        for i in range(k + 1, m):
            f = J[i, k] / J[k, k]
            if f != 0.0:
                for j in range(k + 1, m):
                    J[i, j] -= f * J[k, j]
                r[i] -= f * r[k]
    for i in range(m - 1, -1, -1):
        s = r[i]
        for j in range(i + 1, m):
            s -= J[i, j] * r[j]
        r[i] = s / J[i, i]
    return True


@njit(**_OPTIONS)
def _grad(mass, lagrangian, t, z, p, n, q, v, M, b, Lq, g):
    """∇H at (t, z) into g (``g[:n] = ∂H/∂q = −L_q``, ``g[n:] = q̇``); returns ``(ok, H)``. Leaves q, q̇ in
    ``q``, ``v`` and the Cholesky factor of M in ``M``; not ok when M is not positive definite."""
    for i in range(n):
        q[i] = z[i]
    mass(t, q, p, M, b)
    if not _cholesky(M, n):
        return False, 0.0
    for i in range(n):
        v[i] = z[n + i] - b[i]
    _cholesky_solve(M, n, v)
    L = lagrangian(t, q, v, p, Lq)
    H = -L
    for i in range(n):
        H += z[n + i] * v[i]
        g[i] = -Lq[i]
        g[n + i] = v[i]
    return True, H


@njit(**_OPTIONS)
def _field_jacobian(mass, lagrangian, second, t, z, p, n, q, v, M, b, Lq, g, Lqq, Lqv, W, x, Jf):
    """Jacobian of the field 𝕁∇H at (t, z) into ``Jf`` (2n × 2n): rows (q̇, ṗ) = (∂H/∂p, −∂H/∂q), from
    ``M⁻¹``, ``W = M⁻¹ L_{qq̇}ᵀ`` and ``L_qq`` (formula in lagrange.codegen.hamiltonian_source)."""
    ok, _ = _grad(mass, lagrangian, t, z, p, n, q, v, M, b, Lq, g)
    if not ok:
        return False
    second(t, q, v, p, Lqq, Lqv)
    for k in range(n):  # column k of M⁻¹ and of W
        for i in range(n):
            x[i] = 1.0 if i == k else 0.0
        _cholesky_solve(M, n, x)
        for i in range(n):
            Jf[i, n + k] = x[i]
            x[i] = Lqv[k, i]
        _cholesky_solve(M, n, x)
        for i in range(n):
            W[i, k] = x[i]
    for i in range(n):
        for k in range(n):
            Jf[i, k] = -W[i, k]
            Jf[n + i, n + k] = W[k, i]
            s = Lqq[i, k]
            for j in range(n):
                s -= Lqv[i, j] * W[j, k]
            Jf[n + i, k] = s
    return True


@njit(**_OPTIONS)
def _norms(r, x, m):
    """``(max|r|, 1 + max|x|)`` as Newton measures them; inf when an entry is not finite."""
    rn, xn = 0.0, 0.0
    for j in range(m):
        a, e = abs(r[j]), abs(x[j])
        rn = a if a > rn or not a <= math.inf else rn
        xn = e if e > xn or not e <= math.inf else xn
    if not (rn <= math.inf and xn <= math.inf):  # a nan
        return math.inf, math.inf
    return rn, 1.0 + xn


@njit(**_OPTIONS)
def _gauss_step(mass, lagrangian, second, A, bb, c, t, z, h, p, n, tol, max_iter, w, K, Y, R, Jac, Jf, znew):
    """One Gauss–Legendre step ``K_i = f(t + c_i h, z + h Σ_j a_ij K_j)``; returns (status, iterations,
    residual). ``w`` = (q, v, M, b, Lq, g, Lqq, Lqv, W, x)."""
    q, v, M, b, Lq, g, Lqq, Lqv, W, x = w
    s = c.size
    m = 2 * n
    ok, _ = _grad(mass, lagrangian, t, z, p, n, q, v, M, b, Lq, g)
    if not ok:
        return SINGULAR_MASS, 0, 0.0
    for i in range(s):
        for j in range(n):
            K[i * m + j] = g[n + j]
            K[i * m + n + j] = -g[j]
    rnorm = math.inf
    for it in range(1, max_iter + 1):
        for i in range(s):
            for j in range(m):
                acc = 0.0
                for k in range(s):
                    acc += A[i, k] * K[k * m + j]
                Y[i, j] = z[j] + h * acc
            ok, _ = _grad(mass, lagrangian, t + c[i] * h, Y[i], p, n, q, v, M, b, Lq, g)
            if not ok:
                return SINGULAR_MASS, it, rnorm
            for j in range(n):
                R[i * m + j] = K[i * m + j] - g[n + j]
                R[i * m + n + j] = K[i * m + n + j] + g[j]
        rnorm, scale = _norms(R, K, s * m)
        if not (math.isfinite(rnorm) and math.isfinite(scale)):
            return NEWTON_DIVERGED, it, math.inf
        if rnorm <= tol * scale:
            _combine(z, h, bb, K, s, m, znew)
            return OK, it - 1, rnorm
        for i in range(s * m):
            for j in range(s * m):
                Jac[i, j] = 1.0 if i == j else 0.0
        for i in range(s):
            if not _field_jacobian(mass, lagrangian, second, t + c[i] * h, Y[i], p, n, q, v, M, b, Lq, g, Lqq,
                                   Lqv, W, x, Jf):
                return SINGULAR_JACOBIAN, it, rnorm
            for k in range(s):
                f = h * A[i, k]
                for a in range(m):
                    for e in range(m):
                        Jac[i * m + a, k * m + e] -= f * Jf[a, e]
        if not _lu_solve(Jac, R, s * m):
            return SINGULAR_JACOBIAN, it, rnorm
        dx = 0.0
        for j in range(s * m):
            K[j] -= R[j]
            dx = max(dx, abs(R[j]))
        if dx <= 4e-16 * scale:
            _combine(z, h, bb, K, s, m, znew)
            return OK, it, rnorm
    return NEWTON_MAX_ITER, max_iter, rnorm


@njit(**_OPTIONS)
def _combine(z, h, bb, K, s, m, znew):
    for j in range(m):
        acc = 0.0
        for i in range(s):
            acc += bb[i] * K[i * m + j]
        znew[j] = z[j] + h * acc


@njit(**_OPTIONS)
def _compose_step(mass, lagrangian, t, z, h, gam, p, n, w, znew):
    """Störmer–Verlet steps of sizes ``γ_i h`` in turn (M constant; plain Störmer–Verlet is ``γ = (1,)``: half
    kick, drift with q̇ = M⁻¹p, half kick): the force after one stage's drift is the force of the next stage's
    first half kick, so a stage costs one ∇V and one ``M⁻¹p``."""
    q, v, M, b, Lq, g, Lqq, Lqv, W, x = w
    for j in range(2 * n):
        znew[j] = z[j]
    ok, _ = _grad(mass, lagrangian, t, znew, p, n, q, v, M, b, Lq, g)
    if not ok:
        return SINGULAR_MASS, 0, 0.0
    tau = t
    for i in range(gam.size):
        a = gam[i] * h
        for j in range(n):
            znew[n + j] -= 0.5 * a * g[j]
        ok, _ = _grad(mass, lagrangian, tau, znew, p, n, q, v, M, b, Lq, g)
        if not ok:
            return SINGULAR_MASS, 0, 0.0
        for j in range(n):
            znew[j] += a * g[n + j]
        tau += a
        ok, _ = _grad(mass, lagrangian, tau, znew, p, n, q, v, M, b, Lq, g)
        if not ok:
            return SINGULAR_MASS, 0, 0.0
        for j in range(n):
            znew[n + j] -= 0.5 * a * g[j]
    return OK, 0, 0.0


@njit(**_OPTIONS)
def _dg_step(mass, lagrangian, second, t, z, h, p, n, tol, max_iter, w, zm, d, R, Jac, Jf, znew):
    """Gonzalez' discrete gradient ``z₁ = z₀ + h 𝕁 ∇̄H(z₀, z₁)`` by Newton with the midpoint Jacobian."""
    q, v, M, b, Lq, g, Lqq, Lqv, W, x = w
    m = 2 * n
    ok, H0 = _grad(mass, lagrangian, t, z, p, n, q, v, M, b, Lq, g)
    if not ok:
        return SINGULAR_MASS, 0, 0.0
    for j in range(n):
        znew[j] = z[j] + h * g[n + j]
        znew[n + j] = z[n + j] - h * g[j]
    rnorm = math.inf
    for it in range(1, max_iter + 1):
        for j in range(m):
            zm[j] = 0.5 * (z[j] + znew[j])
            d[j] = znew[j] - z[j]
        ok, H1 = _grad(mass, lagrangian, t, znew, p, n, q, v, M, b, Lq, g)
        if not ok:
            return SINGULAR_MASS, it, rnorm
        ok, _ = _grad(mass, lagrangian, t, zm, p, n, q, v, M, b, Lq, g)
        if not ok:
            return SINGULAR_MASS, it, rnorm
        dd = 0.0
        gd = 0.0
        for j in range(m):
            dd += d[j] * d[j]
            gd += g[j] * d[j]
        corr = 0.0 if dd < 1e-300 else (H1 - H0 - gd) / dd
        for j in range(n):
            R[j] = znew[j] - z[j] - h * (g[n + j] + corr * d[n + j])
            R[n + j] = znew[n + j] - z[n + j] + h * (g[j] + corr * d[j])
        rnorm, scale = _norms(R, znew, m)
        if not (math.isfinite(rnorm) and math.isfinite(scale)):
            return NEWTON_DIVERGED, it, math.inf
        if rnorm <= tol * scale:
            return OK, it - 1, rnorm
        if not _field_jacobian(mass, lagrangian, second, t, zm, p, n, q, v, M, b, Lq, g, Lqq, Lqv, W, x, Jf):
            return SINGULAR_JACOBIAN, it, rnorm
        for i in range(m):
            for j in range(m):
                Jac[i, j] = (1.0 if i == j else 0.0) - 0.5 * h * Jf[i, j]
        if not _lu_solve(Jac, R, m):
            return SINGULAR_JACOBIAN, it, rnorm
        dx = 0.0
        for j in range(m):
            znew[j] -= R[j]
            dx = max(dx, abs(R[j]))
        if dx <= 4e-16 * scale:
            return OK, it, rnorm
    return NEWTON_MAX_ITER, max_iter, rnorm


@njit(**_OPTIONS)
def _record(mass, lagrangian, t, z, p, n, w, T, Y, k):
    """``T[k] = t``, ``Y[k] = [q, q̇(t, z)]``; False when M is not positive definite."""
    q, v, M, b, Lq, g, Lqq, Lqv, W, x = w
    ok, _ = _grad(mass, lagrangian, t, z, p, n, q, v, M, b, Lq, g)
    T[k] = t
    for i in range(n):
        Y[k, i] = z[i]
        Y[k, n + i] = v[i] if ok else math.nan
    return ok


@njit(RUN, **_OPTIONS)
def run(scheme, mass, lagrangian, second, A, bb, c, t0, h, steps, stride, p, tol, max_iter, k_stop, z, T, Y, counts,
        info):
    """Steps ``counts[0]`` to ``min(k_stop, steps)`` of the run (see the module docstring); the state is in the
    arguments, updated in place after every step: ``z``, the records ``T``, ``Y`` (``steps // stride + 3``
    rows), ``counts = [next step k, n_out, total iterations, iterations of the last step]`` (all 0 for a new
    run: the initial state is recorded first) and ``info = [last residual]``. Returns a status of
    :data:`STATUS` (the failed step is ``counts[0]``) or :data:`PAUSED`; stepping on from a pause is
    bit-identical to one uninterrupted run."""
    m = z.size
    n = m // 2
    s = c.size
    w = (np.empty(n), np.empty(n), np.empty((n, n)), np.empty(n), np.empty(n), np.empty(m), np.empty((n, n)),
         np.empty((n, n)), np.empty((n, n)), np.empty(n))
    size = max(s, 1) * m
    K, R = np.empty(size), np.empty(size)
    Ys, Jac, Jf = np.empty((max(s, 1), m)), np.empty((size, size)), np.empty((m, m))
    zm, d = np.empty(m), np.empty(m)
    znew = np.empty(m)
    if counts[1] == 0:
        _record(mass, lagrangian, t0, z, p, n, w, T, Y, 0)
        counts[1] = 1
    n_out = counts[1]
    total = counts[2]
    for k in range(counts[0], min(k_stop, steps)):
        tk = t0 + k * h
        if scheme == GAUSS:
            status, its, rnorm = _gauss_step(mass, lagrangian, second, A, bb, c, tk, z, h, p, n, tol, max_iter, w, K,
                                             Ys, R, Jac, Jf, znew)
        elif scheme == VERLET or scheme == COMPOSE:  # Störmer–Verlet is the one-stage composition, γ = (1,)
            status, its, rnorm = _compose_step(mass, lagrangian, tk, z, h, bb, p, n, w, znew)
        else:
            status, its, rnorm = _dg_step(mass, lagrangian, second, tk, z, h, p, n, tol, max_iter, w, zm, d, R, Jac,
                                          Jf, znew)
        if status == OK:
            for j in range(m):
                if not math.isfinite(znew[j]):
                    status = NON_FINITE
        if status != OK:
            if T[n_out - 1] != tk:
                _record(mass, lagrangian, tk, z, p, n, w, T, Y, n_out)
                n_out += 1
            counts[0], counts[1], counts[3] = k, n_out, its
            info[0] = rnorm
            return status
        for j in range(m):
            z[j] = znew[j]
        total += its
        if (k + 1) % stride == 0 or k + 1 == steps:
            _record(mass, lagrangian, t0 + (k + 1) * h, z, p, n, w, T, Y, n_out)
            n_out += 1
        counts[0], counts[1], counts[2], counts[3] = k + 1, n_out, total, its
    if counts[0] < steps:
        return PAUSED
    info[0] = 0.0
    counts[3] = 0
    return OK


@njit(MOMENTA, **_OPTIONS)
def momenta(mass, t, q, v, p, out):
    """``out = p = M(t, q) q̇ + b(t, q)``; False when the model cannot evaluate M."""
    n = q.size
    M, b = np.empty((n, n)), np.empty(n)
    ok = mass(t, q, p, M, b)
    for i in range(n):
        out[i] = b[i]
        for j in range(n):
            out[i] += M[i, j] * v[j]
    return ok
