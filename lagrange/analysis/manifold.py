r"""Linearization on the constraint manifold (holonomic and non-holonomic constraints).

The derived equations (:class:`~lagrange.derive.equations.Equations`) are

.. math:: M(q)\,\ddot q = f(q, \dot q, u) + A(q)^T\lambda,\qquad A(q)\,\dot q + b(q) = 0,\qquad
          A(q)\,\ddot q = c(q, \dot q),\qquad \varphi(q) = 0\ \text{(holonomic rows)},

with inputs u (plain symbols). About a reference state ``(q₀, q̇₀, u₀)`` that satisfies the constraints the
reference acceleration and multipliers solve ``[M −Aᵀ; A 0][q̈₀; λ₀] = [f; c]``. Perturbing every quantity
(``δλ`` included) gives

.. math:: M_0\,\delta\ddot q - A_0^T\delta\lambda = K_q\,\delta q + K_v\,\delta\dot q + K_u\,\delta u,\qquad
          A_0\,\delta\ddot q = C_q\,\delta q + C_v\,\delta\dot q + C_u\,\delta u,

with ``K_q = ∂(f + Aᵀλ₀ − M q̈₀)/∂q``, ``K_v = ∂f/∂q̇``, ``K_u = ∂f/∂u``, ``C_q = ∂(c − A q̈₀)/∂q``,
``C_v = ∂c/∂q̇``, ``C_u = ∂c/∂u``, all at the reference (exact symbolic derivatives; no finite differences).

The perturbation must stay in the tangent space of the manifold ``{φ = 0, A q̇ + b = 0}``:
``Φ_q δq = 0`` (``Φ_q`` the holonomic rows of ``A₀``) and ``A₀ δq̇ + G_q δq = 0`` with
``G_q = ∂(A q̇ + b)/∂q``. Splitting the coordinates into independent ``s`` (n − p) and dependent ones
(p = number of holonomic constraints), and the speeds into independent ``w`` (n − m) and dependent ones, with
``Φ_q[:, dep]`` and ``A₀[:, dep]`` invertible (chosen by a pivoted Gram–Schmidt that prefers to keep the
coordinates declared first independent; overridable),

.. math:: \delta q = C_0\,s,\qquad \delta\dot q = C_w\,w + C_s\,s,\qquad C_s = -E\,G_q C_0,

where ``C₀``, ``C_w`` are the null-space bases of ``Φ_q`` and ``A₀`` with identity rows at the independent
variables and ``E`` (n × m) holds ``A₀[:, dep]⁻¹`` in the dependent-speed rows (so ``A₀E = I``). Then
``δq̈ = C_w ẇ + E(C_q δq + C_v δq̇ + C_u δu)`` and, projecting the dynamics on ``C_wᵀ`` (which removes δλ
since ``A₀C_w = 0``; Maggi's / Kane's form),

.. math:: \dot x = \mathcal A x + \mathcal B\,\delta u,\quad x = (s, w),\quad
   \mathcal A = \begin{bmatrix} C_s[\mathrm{ind}] & C_w[\mathrm{ind}] \\
   \bar M^{-1}C_w^T(H_qC_0 + H_vC_s) & \bar M^{-1}C_w^TH_vC_w\end{bmatrix},\quad
   \mathcal B = \begin{bmatrix}0\\ \bar M^{-1}C_w^TH_u\end{bmatrix},

with ``M̄ = C_wᵀM₀C_w``, ``H_• = K_• − M₀E C_•`` and ``[ind]`` the rows of the independent coordinates.
For holonomic constraints only, the independent speeds are the rates of the independent coordinates
(``C_w = C₀``, ``C_s[ind] = 0``) and this is Wells' second-order form ``a s̈ + b ṡ + c s = F`` with
``a = M̄``, ``b = −C₀ᵀH_vC₀``, ``c = −C₀ᵀ(H_qC₀ + H_vC_s)``. A non-holonomic system has fewer
independent speeds than coordinates: only the first-order form exists.

The eigenvalues of ``𝒜`` do not depend on the choice of independent variables (another choice is a
similarity transform). The numeric route lambdifies the exact Jacobians once per
:class:`~lagrange.derive.equations.Equations` (cached) and evaluates them per operating point.
"""

from __future__ import annotations

import functools
import random
from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import AnalysisError, ParameterError
from ..integrate.constrained import complete_speeds, pivot_columns
from ..model.coordinates import canonical_key, coordinate_name, position_symbol, velocity_symbol
from ..safe_sympify import expression as _expression
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify

__all__ = ["reference_state", "numeric_blocks", "symbolic_blocks", "choose_dependent", "reduce"]

_KINKS = (sp.sign, sp.Abs, sp.Heaviside)


# ------------------------------------------------------------------------------------------ reference state


def _key_maps(system, inputs: Sequence) -> tuple[dict, dict, dict]:
    """Accepted keys of a reference state: ``{key: position symbol}``, ``{key: velocity symbol}``,
    ``{key: input symbol}``."""
    pos, vel, inp = {}, {}, {}
    for q in system.coordinates:
        for k in (q, coordinate_name(q), position_symbol(q)):
            pos[k] = position_symbol(q)
        v = velocity_symbol(q)
        for k in (q.diff(t), v, v.name):
            vel[k] = v
    for u in inputs:
        inp[u] = inp[u.name] = u
    return pos, vel, inp


def reference_state(system, about: Mapping | None, velocities: Mapping | None, inputs: Sequence) -> tuple:
    """Split ``about`` (coordinates, velocities and inputs by object or name) into three dicts keyed by
    symbols; unknown keys raise :class:`~lagrange.errors.AnalysisError` listing the valid names."""
    pos, vel, inp = _key_maps(system, inputs)
    q0, v0, u0 = {}, {}, {}
    bad = []
    for src in (about or {}, velocities or {}):
        for k, val in src.items():
            key = canonical_key(k, system.coordinates, inputs)  # dynamicsymbols and their derivatives
            for table, out in ((pos, q0), (vel, v0), (inp, u0)):
                if key in table:
                    if isinstance(val, str):  # never parse user strings here (only the spec parser does)
                        raise AnalysisError(f"the reference value of {k} must be a number or a sympy expression, "
                                            f"not the string {val!r}")
                    out[table[key]] = _expression(val, where=f"the reference value of {k}")
                    break
            else:
                bad.append(str(k))
    if bad:
        valid = [coordinate_name(q) for q in system.coordinates]
        valid += [velocity_symbol(q).name for q in system.coordinates] + [u.name for u in inputs]
        raise AnalysisError(f"unknown name(s) in the reference state: {', '.join(bad)} (valid: {', '.join(valid)})")
    return q0, v0, u0


# ------------------------------------------------------------------------------------------------- checks


def check_supported(eqs) -> None:
    """Refuse combinations the linearization does not handle (named in the message)."""
    problem = _unsupported(eqs)
    if problem:
        raise AnalysisError(problem)


@functools.lru_cache(maxsize=32)
def _unsupported(eqs) -> str:
    try:
        _check_supported(eqs)
    except AnalysisError as exc:
        return str(exc)
    return ""


def _check_supported(eqs) -> None:
    if eqs.is_rough:
        raise AnalysisError("linearization of a system with rough (Coulomb-friction) constraints is not supported: "
                            f"the friction of {', '.join(eqs.constraint_names)} depends on the sign of the reaction")
    if eqs.m:
        moving = [nm for nm, row, b in zip(eqs.constraint_names, eqs.constraint_matrix.tolist(), eqs.constraint_bias)
                  if t in sp.Matrix([row]).free_symbols | _sympify(b).free_symbols]
        if moving:
            raise AnalysisError("linearization on the manifold of moving (explicit-time) constraints is not supported: "
                                f"{', '.join(moving)}; the linearized system would be time-varying. Eliminate the "
                                "constraint (lagrange.eliminate) or write it in a moving frame")
        if t in eqs.mass_matrix.free_symbols | eqs.forcing.free_symbols:
            raise AnalysisError("linearization of a constrained system with explicit time in M or f is not supported "
                                "(the linearized system would be time-varying)")
    bad = [e for e in eqs.forcing if e.has(sp.Piecewise, sp.Min, sp.Max, sp.floor, sp.ceiling)]
    if bad:
        raise AnalysisError(f"cannot linearize piecewise-defined forces: {bad[0]}")


@functools.lru_cache(maxsize=32)
def _kink_arguments(eqs) -> list:
    args = set()
    for e in eqs.forcing:
        for k in _KINKS:
            args |= {a.args[0] for a in _sympify(e).atoms(k)}
    return sorted(args, key=sp.default_sort_key)


def _no_delta(e):
    return e.replace(sp.DiracDelta, lambda *a: sp.S.Zero) if e.has(sp.DiracDelta) else e


# ------------------------------------------------------------------------------------------ numeric kernel


#: functions without a complex-analytic extension in numpy: complex-step differentiation would be wrong
_NON_ANALYTIC = (sp.sign, sp.Abs, sp.Heaviside, sp.atan2, sp.re, sp.im, sp.conjugate, sp.arg, sp.Piecewise, sp.Min,
                 sp.Max, sp.floor, sp.ceiling)
_STEP = 1e-30  # complex step: f'(x) = Im f(x + ih)/h, exact to rounding (no subtractive cancellation)


@functools.lru_cache(maxsize=16)
def _kernel(eqs, inputs: tuple):
    """Generated code for the blocks of ``eqs`` (built once per Equations and inputs: the frozen Equations is
    the cache key). Returns ``(first, second, params)``: ``first`` evaluates M, f, A, b, c, the arguments of
    sign/Abs terms and φ (also at complex arguments, for complex-step derivatives); ``second`` is None, or —
    when a non-analytic function (sign, Abs, atan2, …) appears — the exact symbolic Jacobians, lambdified."""
    n, m = eqs.n, eqs.m
    q, qd, qdd, lam = list(eqs.q), list(eqs.qd), list(eqs.qdd), list(eqs.multipliers)
    params = [p for p in eqs.parameters if p not in inputs]
    M = sp.Matrix(eqs.mass_matrix)
    f = sp.Matrix(eqs.forcing)
    A = sp.Matrix(eqs.constraint_matrix) if m else sp.zeros(0, n)
    b = sp.Matrix(list(eqs.constraint_bias)) if m else sp.zeros(0, 1)
    c = sp.Matrix(list(eqs.constraint_rhs)) if m else sp.zeros(0, 1)
    kinks = _kink_arguments(eqs)
    args = [q, qd, list(inputs), params, t]
    phis = [_sympify(ph) for ph in eqs.constraint_positions if ph is not None]
    first = [M, f, A, b, c, sp.Matrix(kinks) if kinks else sp.zeros(0, 1), sp.Matrix(phis) if phis else sp.zeros(0, 1)]
    if not any(_sympify(e).has(*_NON_ANALYTIC) for X in (M, f, A, b, c) for e in X):
        return _flat(args, first), None, tuple(params)
    res = f + A.T * sp.Matrix(lam) - M * sp.Matrix(qdd) if m else f - M * sp.Matrix(qdd)
    cres = c - A * sp.Matrix(qdd) if m else c
    g = A * sp.Matrix(qd) + b if m else b
    u = list(inputs)
    second = [res.jacobian(q), f.jacobian(qd), f.jacobian(u) if u else sp.zeros(n, 0),
              cres.jacobian(q) if m else sp.zeros(0, n), c.jacobian(qd) if m else sp.zeros(0, n),
              c.jacobian(u) if (m and u) else sp.zeros(m, len(u)), g.jacobian(q) if m else sp.zeros(0, n)]
    second = [X.applyfunc(_no_delta) for X in second]
    return _flat(args, first), _flat(args + [qdd, lam], second), tuple(params)


def _flat(args, mats):
    """One generated function returning the matrices ``mats`` as arrays (flattened, one CSE); float for real
    arguments, complex for complex ones."""
    shapes = [X.shape for X in mats]
    exprs = [e for X in mats for e in X]
    fn = _lambdify(args, exprs, modules="numpy", cse=True) if exprs else None

    def call(*a):
        cplx = any(np.iscomplexobj(x) for x in a)
        vals = np.asarray(fn(*a) if fn else [], dtype=complex if cplx else float).ravel()
        out, k = [], 0
        for r, cc in shapes:
            out.append(vals[k:k + r * cc].reshape(r, cc))
            k += r * cc
        return out

    return call


def _complex_step(first, qv, vv, uv, pv, t0, qdd, lam) -> tuple:
    """K_q, K_v, K_u, C_q, C_v, C_u, G_q by complex steps on the generated M, f, A, b, c."""

    def parts(qx, vx, ux):
        M, f, A, b, c = first(qx, vx, ux, pv, t0)[:5]
        return np.concatenate([f[:, 0] + A.T @ lam - M @ qdd, c[:, 0] - A @ qdd, A @ vx + b[:, 0]])

    def jac(which):
        base = [qv.astype(complex), vv.astype(complex), uv.astype(complex)]
        cols = []
        for j in range(len(base[which])):
            x = [v.copy() for v in base]
            x[which][j] += 1j * _STEP
            cols.append(parts(*x).imag / _STEP)
        size = len(parts(*base))
        return np.array(cols).T if cols else np.zeros((size, 0))

    n, m = len(qv), len(lam)
    Jq, Jv, Ju = jac(0), jac(1), jac(2)
    return (Jq[:n], Jv[:n], Ju[:n], Jq[n:n + m], Jv[n:n + m], Ju[n:n + m], Jq[n + m:])


def numeric_blocks(system, q0: Mapping, v0: Mapping, u0: Mapping, params: Mapping, inputs: tuple) -> dict:
    """The blocks at a numeric reference state (values may be expressions in the parameters)."""
    eqs = system.derived
    first, second, pnames = _kernel(eqs, tuple(inputs))
    by_name = {getattr(k, "name", str(k)): v for k, v in params.items()}
    # symbols of the reference state's expressions (e.g. a speed v of an operating point) are parameters too
    extra = set().union(*[_sympify(v).free_symbols for d in (q0, v0, u0) for v in d.values()]) - set(eqs.parameters)
    known = {p.name for p in eqs.parameters} | {u.name for u in inputs} | {s.name for s in extra} | {"t"}
    unknown = sorted(set(by_name) - known)
    if unknown:
        raise ParameterError(f"unknown parameter(s) {', '.join(unknown)} (parameters: "
                             f"{', '.join(sorted(known - {'t'})) or 'none'})")
    missing_ref = sorted(s.name for s in extra if s.name not in by_name)
    if missing_ref:
        raise ParameterError(f"missing value(s) for {', '.join(missing_ref)} (used in the reference state)")
    missing = [p.name for p in pnames if p.name not in by_name]
    if missing:
        raise ParameterError(f"missing parameter value(s) for {', '.join(missing)}")
    strings = [k for k, v in by_name.items() if isinstance(v, str)]
    if strings:
        raise ParameterError(f"parameter value(s) of {', '.join(strings)} must be numbers, not strings")
    psub = {p: _sympify(by_name[p.name]) for p in list(eqs.parameters) + list(extra) if p.name in by_name}

    def num(val, what):
        x = _sympify(val).xreplace(psub)
        try:
            out = complex(x)
        except (TypeError, ValueError):
            raise AnalysisError(f"the reference value of {what} is not a number: {val}") from None
        if out.imag != 0 or not np.isfinite(out.real):
            raise AnalysisError(f"the reference value of {what} is not a finite real number: {val}")
        return out.real

    qv = np.array([num(q0.get(s, 0), s.name) for s in eqs.q])
    vv = np.array([num(v0.get(s, 0), s.name) for s in eqs.qd])
    uv = np.array([num(u0.get(s, by_name.get(s.name, 0)), s.name) for s in inputs])
    pv = np.array([num(psub[p], p.name) for p in pnames])
    t0 = float(by_name.get("t", 0.0))
    with np.errstate(all="ignore"):
        M, f, A, b, c, kinks, phi = first(qv, vv, uv, pv, t0)
    if eqs.m and np.all(np.isfinite(A)) and np.all(np.isfinite(b)):  # the speeds left out: from A q̇ + b = 0
        done, computed, _ = complete_speeds(A, b[:, 0], vv, [s in v0 for s in eqs.qd])
        if computed and not np.array_equal(done, vv):
            vv = done
            with np.errstate(all="ignore"):
                M, f, A, b, c, kinks, phi = first(qv, vv, uv, pv, t0)
    _finite({"M": M, "f": f, "A": A, "b": b, "c": c}, eqs, qv, vv)
    _check_kinks(eqs, kinks)
    blk = dict(M=M, f=f[:, 0], A=A, b=b[:, 0], c=c[:, 0], q=qv, v=vv, u=uv, phi=phi[:, 0], numeric=True)
    _check_manifold(eqs, blk)
    if eqs.m:
        choose_dependent(A, [s.name for s in eqs.q], "constraints", eqs.constraint_names)  # rank check, named
    qdd, lam = _reference_accelerations(blk, eqs)
    with np.errstate(all="ignore"):
        if second is None:
            Kq, Kv, Ku, Cq, Cv, Cu, Gq = _complex_step(first, qv, vv, uv, pv, t0, qdd, lam)
        else:
            Kq, Kv, Ku, Cq, Cv, Cu, Gq = second(qv, vv, uv, pv, t0, qdd, lam)
    _finite({"the Jacobians": np.hstack([Kq, Kv])}, eqs, qv, vv)
    blk.update(qdd=qdd, lam=lam, Kq=Kq, Kv=Kv, Ku=Ku, Cq=Cq, Cv=Cv, Cu=Cu, Gq=Gq)
    return blk


def _finite(mats: dict, eqs, qv, vv) -> None:
    for name, X in mats.items():
        if X.size and not np.all(np.isfinite(X)):
            state = ", ".join(f"{s}={x:g}" for s, x in zip(eqs.q + eqs.qd, np.concatenate([qv, vv])))
            raise AnalysisError(f"the equations are singular at the reference state ({name} is not finite) "
                                f"at {state}")


def _check_kinks(eqs, kinks) -> None:
    args = _kink_arguments(eqs)
    for a, val in zip(args, np.asarray(kinks).ravel()):
        if abs(val) < 1e-12:
            raise AnalysisError(f"cannot linearize at a point where the force is not differentiable: the argument "
                                f"{a} of a sign/Abs term (friction) is zero at the reference state")


def _check_manifold(eqs, blk) -> None:
    """Refuse a reference state off the constraint manifold, with the residuals."""
    if not eqs.m:
        return
    A, b, qv, vv = blk["A"], blk["b"], blk["q"], blk["v"]
    phis = [k for k, ph in enumerate(eqs.constraint_positions) if ph is not None]
    bad = []
    if phis:
        for k, r in zip(phis, blk["phi"]):
            if abs(r) > 1e-9 * (1 + float(np.max(np.abs(qv)))):
                bad.append(f"{eqs.constraint_names[k]}: φ = {r:.3g}")
    vres = A @ vv + b
    scale = 1 + float(np.max(np.abs(vv))) * max(1.0, float(np.max(np.abs(A)))) if A.size else 1.0
    for k, r in enumerate(vres):
        if abs(r) > 1e-9 * scale:
            bad.append(f"{eqs.constraint_names[k]}: A q̇ + b = {r:.3g}")
    if bad:
        raise AnalysisError("the reference state does not satisfy the constraints (" + "; ".join(bad) + "): give "
                            "consistent coordinates, and only the independent velocities in `about` (the speeds "
                            "left out are computed from the velocity constraints)")


def _reference_accelerations(blk, eqs):
    """``q̈₀, λ₀`` from ``[M −Aᵀ; A 0][q̈; λ] = [f; c]``."""
    M, A, f, c = blk["M"], blk["A"], blk["f"], blk["c"]
    n, m = M.shape[0], A.shape[0]
    K = np.block([[M, -A.T], [A, np.zeros((m, m))]]) if m else M
    rhs = np.concatenate([f, c]) if m else f
    try:
        sol = np.linalg.solve(K, rhs)
    except np.linalg.LinAlgError:
        sol = None
    if sol is None or not np.all(np.isfinite(sol)) or np.linalg.cond(K) > 1e14:
        what = "the mass matrix with the constraint rows [M −Aᵀ; A 0]" if m else "the mass matrix"
        state = ", ".join(f"{s.name} = {x:.6g}" for s, x in zip(eqs.q, blk["q"]))
        raise AnalysisError(f"{what} is singular at the reference state {state} (a coordinate singularity): "
                            "linearize at another point (`about=`; in the shell `--about q=VALUE`)")
    return sol[:n], sol[n:]


# ------------------------------------------------------------------------------------------ symbolic blocks


def symbolic_blocks(system, q0: Mapping, v0: Mapping, u0: Mapping, inputs: tuple) -> dict:
    """The blocks at a symbolic reference state (small systems: Wells' way)."""
    eqs = system.derived
    n, m = eqs.n, eqs.m
    at = {s: q0.get(s, sp.S.Zero) for s in eqs.q}
    at.update({s: v0.get(s, sp.S.Zero) for s in eqs.qd})
    at.update({s: u0.get(s, sp.S.Zero) for s in inputs})
    M = sp.Matrix(eqs.mass_matrix)
    f = sp.Matrix(eqs.forcing)
    A = sp.Matrix(eqs.constraint_matrix) if m else sp.zeros(0, n)
    b = sp.Matrix(list(eqs.constraint_bias)) if m else sp.zeros(0, 1)
    c = sp.Matrix(list(eqs.constraint_rhs)) if m else sp.zeros(0, 1)
    ev = lambda X: X.xreplace(at).applyfunc(_tidy)  # noqa: E731
    A0, b0 = ev(A), ev(b)
    if m:
        at.update(_symbolic_speeds(eqs, A0, b0, at, v0))
    M0, f0, c0 = ev(M), ev(f), ev(c)
    for a in _kink_arguments(eqs):
        if _tidy(a.xreplace(at)) == 0:
            raise AnalysisError(f"cannot linearize at a point where the force is not differentiable: the argument "
                                f"{a} of a sign/Abs term (friction) is zero at the reference state")
    bad = []
    for k, ph in enumerate(eqs.constraint_positions):
        if ph is not None and _tidy(_sympify(ph).xreplace(at)) != 0:
            bad.append(f"{eqs.constraint_names[k]}: φ = {_tidy(_sympify(ph).xreplace(at))}")
    singular = [nm for nm, X in (("M", M0), ("f", f0), ("A", A0), ("c", c0)) if X.has(sp.nan, sp.zoo, sp.oo)]
    if singular and not bad:
        raise AnalysisError(f"the equations are singular at the reference state ({', '.join(singular)} not finite)")
    for k in range(m if not bad else 0):
        r = _tidy((A0[k, :] * sp.Matrix([at[s] for s in eqs.qd]))[0] + b0[k])
        if r != 0:
            bad.append(f"{eqs.constraint_names[k]}: A q̇ + b = {r}")
    if bad:
        raise AnalysisError("the reference state does not satisfy the constraints (" + "; ".join(bad) + "): give "
                            "consistent coordinates and velocities in `about`")
    if m:
        K = sp.BlockMatrix([[M0, -A0.T], [A0, sp.zeros(m, m)]]).as_explicit()
        sol = K.LUsolve(sp.Matrix.vstack(f0, c0)).applyfunc(_tidy)
        qdd, lam = sol[:n, :], sol[n:, :]
    elif all(e == 0 for e in f0):
        qdd, lam = sp.zeros(n, 1), sp.zeros(0, 1)
    else:
        qdd, lam = M0.LUsolve(f0).applyfunc(_tidy), sp.zeros(0, 1)
    u = list(inputs)
    q, qd = list(eqs.q), list(eqs.qd)
    atq = {**at, **dict(zip(eqs.qdd, qdd)), **dict(zip(eqs.multipliers, lam))}
    res = f + (A.T * sp.Matrix(eqs.multipliers) if m else sp.zeros(n, 1)) - M * sp.Matrix(eqs.qdd)
    ev2 = lambda X: _no_delta_matrix(X).xreplace(atq).applyfunc(_tidy)  # noqa: E731
    blk = dict(M=M0, f=f0, A=A0, b=b0, c=c0, qdd=qdd, lam=lam, numeric=False, v=[at[s] for s in eqs.qd],
               Kq=ev2(res.jacobian(q)), Kv=ev2(f.jacobian(qd)), Ku=ev2(f.jacobian(u)) if u else sp.zeros(n, 0))
    if m and all(at[s] == 0 for s in eqs.qd) and all(_sympify(e) == 0 for e in b):
        # c = −(∂(A q̇)/∂q) q̇ is quadratic in q̇: at rest its derivatives vanish (saves the costly ∂c/∂q)
        blk.update(Cq=ev2(-(A * sp.Matrix(qdd)).jacobian(q)),
                   Cv=sp.zeros(m, n), Cu=sp.zeros(m, len(u)), Gq=sp.zeros(m, n))
    elif m:
        cres = c - A * sp.Matrix(eqs.qdd)
        g = A * sp.Matrix(qd) + b
        blk.update(Cq=ev2(cres.jacobian(q)), Cv=ev2(c.jacobian(qd)),
                   Cu=ev2(c.jacobian(u)) if u else sp.zeros(m, 0), Gq=ev2(g.jacobian(q)))
    else:
        blk.update(Cq=sp.zeros(0, n), Cv=sp.zeros(0, n), Cu=sp.zeros(0, len(u)), Gq=sp.zeros(0, n))
    return blk


def _symbolic_speeds(eqs, A0, b0, at: dict, v0: Mapping) -> dict:
    """The speeds left out of ``v0`` that the velocity constraints determine, solved symbolically from
    ``A₀ q̇ + b₀ = 0``; the dependent set is chosen as the numeric route chooses it
    (:func:`~lagrange.integrate.constrained.complete_speeds`), on ``A₀`` at random parameter values."""
    free = [i for i, s in enumerate(eqs.qd) if s not in v0]
    if not free:
        return {}
    syms = sorted(A0.free_symbols | b0.free_symbols, key=lambda s: s.name)
    rnd = random.Random(1234)
    sample = {s: sp.Float(rnd.uniform(1.1, 2.3)) for s in syms}
    try:
        An = np.array(A0.xreplace(sample).evalf(), dtype=float)
    except (TypeError, ValueError):
        return {}
    if not np.all(np.isfinite(An)):  # singular here: the check of the reference state names it
        return {}
    dep = [free[j] for j in pivot_columns(An[:, free])]
    if not dep:
        return {}
    rest = [i for i in range(eqs.n) if i not in dep]
    rhs = -(b0 + A0.extract(list(range(A0.shape[0])), rest) * sp.Matrix([at[eqs.qd[i]] for i in rest]))
    AD = A0.extract(list(range(A0.shape[0])), dep)
    try:
        sol = (AD.LUsolve(rhs) if AD.shape[0] == AD.shape[1] else (AD.T * AD).LUsolve(AD.T * rhs))
    except (ValueError, ZeroDivisionError):
        return {}
    return {eqs.qd[i]: _tidy(v) for i, v in zip(dep, sol)}


def _no_delta_matrix(X):
    return X.applyfunc(_no_delta)


def _tidy(e):
    """Cheap normalisation for symbolic blocks: bounded simplify of small expressions only."""
    e = _sympify(e)
    if e.is_number or sp.count_ops(e) > 150:
        return e
    from ..simplification import simplify

    return simplify(e, limit=150)


# ------------------------------------------------------------------------------ choice of independent vars


def _sample_matrix(X, free_values: dict) -> np.ndarray:
    if isinstance(X, np.ndarray):
        return X
    return np.array(X.xreplace(free_values).evalf(), dtype=float) if X.shape[0] * X.shape[1] else np.zeros(X.shape)


def random_values(blk) -> dict:
    """Random parameter values in [1.1, 2.3] for symbolic blocks (to choose pivots numerically)."""
    syms = set()
    for key in ("A", "M"):
        syms |= blk[key].free_symbols
    rnd = random.Random(1234)
    return {s: sp.Float(rnd.uniform(1.1, 2.3)) for s in sorted(syms, key=lambda s: s.name)}


def choose_dependent(J: np.ndarray, names: Sequence[str], what: str, rows: Sequence[str]) -> list[int]:
    """Column indices of ``J`` (k × n, full row rank) to make dependent, by the rule of
    :func:`lagrange.integrate.constrained.pivot_columns` (a pivoted Gram–Schmidt that takes the last declared
    column whose remaining norm is at least 0.1 of the largest: well conditioned, and keeps the variables
    declared first independent; the same rule computes the speeds left out of an initial state). Raises when
    ``J`` is rank deficient (redundant constraints)."""
    chosen = pivot_columns(J)
    if len(chosen) < J.shape[0]:
        raise AnalysisError(f"the {what} are redundant or singular at the reference state (rank "
                            f"{len(chosen)} < {J.shape[0]}: {', '.join(rows)})")
    return chosen


# ----------------------------------------------------------------------------------------------- reduction


class _Ops:
    """The few linear-algebra operations of the reduction for numpy arrays or sympy matrices."""

    def __init__(self, numeric: bool):
        self.numeric = numeric

    def zeros(self, r, c):
        return np.zeros((r, c)) if self.numeric else sp.zeros(r, c)

    def eye(self, k):
        return np.eye(k) if self.numeric else sp.eye(k)

    def cols(self, X, idx):
        return X[:, list(idx)] if self.numeric else X.extract(list(range(X.shape[0])), list(idx))

    def rows(self, X, idx):
        return X[list(idx), :] if self.numeric else X.extract(list(idx), list(range(X.shape[1])))

    def solve(self, X, Y):
        if Y.shape[1] == 0 or X.shape[0] == 0:
            return self.zeros(X.shape[1], Y.shape[1])
        if self.numeric:
            return np.linalg.solve(X, Y)
        return X.LUsolve(Y).applyfunc(_tidy)

    def scatter(self, n, idx_a, Xa, idx_b, Xb):
        """An n-row matrix with rows ``idx_a`` from Xa and ``idx_b`` from Xb."""
        cols = Xa.shape[1]
        out = self.zeros(n, cols)
        for r, i in enumerate(idx_a):
            out[i, :] = Xa[r, :]
        for r, i in enumerate(idx_b):
            out[i, :] = Xb[r, :]
        return out

    def block(self, rows):
        if self.numeric:
            return np.block(rows)
        return sp.Matrix.vstack(*[sp.Matrix.hstack(*r) for r in rows])

    def tidy(self, X):
        return X + 0.0 if self.numeric else X.applyfunc(_tidy)  # (+ 0.0 turns -0.0 into 0.0)


def reduce(blk: dict, dep_q: Sequence[int], dep_u: Sequence[int], holonomic_rows: Sequence[int]) -> dict:
    """The reduced state-space model (see the module docstring) from the blocks and the dependent sets."""
    ops = _Ops(blk["numeric"])
    M, A = blk["M"], blk["A"]
    n = M.shape[0]
    ind_q = [i for i in range(n) if i not in dep_q]
    ind_u = [i for i in range(n) if i not in dep_u]
    Phi = ops.rows(A, holonomic_rows)
    # δq = C0 s
    C0 = ops.scatter(n, ind_q, ops.eye(len(ind_q)), dep_q,
                     -ops.solve(ops.cols(Phi, dep_q), ops.cols(Phi, ind_q)))
    # E: A E = I, zero on the independent speeds;  Cw: null space of A with identity rows at ind_u
    m = A.shape[0]
    AD = ops.cols(A, dep_u)
    E = ops.scatter(n, ind_u, ops.zeros(len(ind_u), m), dep_u, ops.solve(AD, ops.eye(m)))
    Cw = ops.scatter(n, ind_u, ops.eye(len(ind_u)), dep_u, -ops.solve(AD, ops.cols(A, ind_u)))
    Cs = -(E @ (blk["Gq"] @ C0)) if m else ops.zeros(n, len(ind_q))
    Hq = blk["Kq"] - M @ (E @ blk["Cq"]) if m else blk["Kq"]
    Hv = blk["Kv"] - M @ (E @ blk["Cv"]) if m else blk["Kv"]
    Hu = blk["Ku"] - M @ (E @ blk["Cu"]) if m else blk["Ku"]
    Cs, Hq, Hv, Hu = ops.tidy(Cs), ops.tidy(Hq), ops.tidy(Hv), ops.tidy(Hu)
    Mbar = ops.tidy(Cw.T @ M @ Cw)
    low_s = ops.tidy(Cw.T @ (Hq @ C0 + Hv @ Cs))
    low_w = ops.tidy(Cw.T @ Hv @ Cw)
    low_u = ops.tidy(Cw.T @ Hu)
    nq, nw, k = len(ind_q), len(ind_u), Hu.shape[1]
    try:
        rhs = ops.solve(Mbar, ops.block([[low_s, low_w, low_u]]))
    except np.linalg.LinAlgError:
        raise AnalysisError("the reduced mass matrix is singular at the reference state") from None
    state = ops.block([[ops.rows(Cs, ind_q), ops.rows(Cw, ind_q)],
                       [ops.cols(rhs, range(nq)), ops.cols(rhs, range(nq, nq + nw))]])
    inp = ops.block([[ops.zeros(nq, k)], [ops.cols(rhs, range(nq + nw, nq + nw + k))]]) if k else ops.zeros(nq + nw, 0)
    state, inp = ops.tidy(state), ops.tidy(inp)
    out = dict(A=state, B=inp, C0=C0, Cw=Cw, Cs=Cs, ind_q=ind_q, ind_u=ind_u, Mbar=Mbar)
    if len(holonomic_rows) == m and list(ind_q) == list(ind_u):
        out.update(a=Mbar, b=-low_w, c=-low_s, G=low_u, forcing=ops.tidy(Mbar @ ops.rows(_col(blk["qdd"], ops), ind_q)))
    return out


def _col(x, ops):
    if ops.numeric:
        return np.asarray(x, dtype=float).reshape(-1, 1)
    return sp.Matrix(x)
