r"""Generated code for :class:`~lagrange.derive.structural.StructuralEquations`: kinematics CSE'd and printed,
M and f assembled numerically, then the same solves as :mod:`lagrange.codegen.source`.

The generated ``rhs(t, y, p)`` (python and numba backends)::

    c0 = ...                                  # one CSE over J, a, W, ω_t, α, I, masses, Q, A, c
    J[r, j] = ...; w[r] = m; g[r] = a         # the point masses' rows (one per Cartesian component in use)
    M = Jᵀ diag(w) J;  f = Q − Jᵀ (w ∘ g)
    M += Wᵀ I W;  f −= Wᵀ (I α + ω × I ω)      # per rigid body, ω = W q̇ + ω_t
    q̈ = M⁻¹ f (Cholesky)                       # or, with constraints, the augmented Schur complement:
    (M + AᵀA) q̈ = f + Aᵀc + Bλ,  A q̈ = c      # exactly as codegen/source.py does it, B = Aᵀ unless rough

The work per call is O(rows · n²) floating-point operations instead of the O(n³)-sized expressions of the
expanded M and f; the symbolic work is linear in the size of the kinematics. The python flavour uses numpy
(``np.linalg.cholesky``), the numba flavours explicit loops (compiled). A mass matrix that is not positive
definite (pivot below 1e-13 of its diagonal entry) raises ``ZeroDivisionError`` (``numba_status``: returns
False), as the straight-line code does.
"""

from __future__ import annotations

import sympy as sp

from ..derive.structural import StructuralEquations
from ..symengine_bridge import FAILURES, carries, symengine
from .cse import _cse, rename_map
from .source import print_expr

__all__ = ["structural_source"]

_PY_HELPERS = '''
def _factor(M, n):
    try:
        L = np.linalg.cholesky(M)
    except np.linalg.LinAlgError:
        return M, False
    d = np.diag(M)
    if not np.all(np.diag(L) ** 2 > 1e-13 * np.abs(d)):
        return L, False
    return L, True


def _csolve(L, b, n):
    return np.linalg.solve(L.T, np.linalg.solve(L, b))


def _gram(J, w, n):
    return (J.T * w) @ J


def _tmv(J, v, n):
    return J.T @ v


def _mv(A, x):
    return A @ x


def _lsolve(S, r):
    return np.linalg.solve(S, r)
'''

_NUMBA_HELPERS = '''
def _factor(M, n):
    L = np.zeros((n, n))
    for j in range(n):
        s = M[j, j]
        for k in range(j):
            s -= L[j, k] * L[j, k]
        if not (s > 1e-13 * abs(M[j, j])):
            return L, False
        dj = math.sqrt(s)
        L[j, j] = dj
        for i in range(j + 1, n):
            s = M[i, j]
            for k in range(j):
                s -= L[i, k] * L[j, k]
            L[i, j] = s / dj
    return L, True


def _csolve(L, b, n):
    z = np.empty(n)
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= L[i, k] * z[k]
        z[i] = s / L[i, i]
    x = np.empty(n)
    for i in range(n - 1, -1, -1):
        s = z[i]
        for k in range(i + 1, n):
            s -= L[k, i] * x[k]
        x[i] = s / L[i, i]
    return x


def _gram(J, w, n):
    M = np.zeros((n, n))
    for r in range(J.shape[0]):
        for i in range(n):
            a = J[r, i]
            if a != 0.0:
                a *= w[r]
                for j in range(n):
                    M[i, j] += a * J[r, j]
    return M


def _tmv(J, v, n):
    out = np.zeros(n)
    for r in range(J.shape[0]):
        vr = v[r]
        if vr != 0.0:
            for i in range(n):
                out[i] += J[r, i] * vr
    return out


def _mv(A, x):
    out = np.zeros(A.shape[0])
    for r in range(A.shape[0]):
        s = 0.0
        for j in range(A.shape[1]):
            s += A[r, j] * x[j]
        out[r] = s
    return out


def _lsolve(S, r):
    return np.linalg.solve(S, r)
'''


def _printable_cse(exprs: list, ren: dict) -> tuple[list, list]:
    """CSE of ``exprs`` (plain symbols) in generated-code names: symengine's, printed directly, when installed
    and the expressions are carried exactly; else sympy's (:func:`lagrange.codegen.cse._cse`)."""
    se = symengine()
    if se is not None and carries(exprs, ren):
        try:
            names = {se.Symbol(old.name): se.Symbol(new.name) for old, new in ren.items()}
            renamed = [se.sympify(e).xreplace(names) for e in exprs]
            allowed = set(names.values())
            if all(e.free_symbols <= allowed for e in renamed):
                repl, red = se.cse(renamed)
                temps = {sym: se.Symbol(f"c{k}") for k, (sym, _) in enumerate(repl)}
                return ([(temps[sym], e.xreplace(temps)) for sym, e in repl], [e.xreplace(temps) for e in red])
        except FAILURES:
            pass
    return _cse([sp.sympify(e).xreplace(ren) for e in exprs])


def _rows(eqs: StructuralEquations) -> list:
    """``(point index, component)`` of every row of the stacked point Jacobian (components with a J entry or a
    bias)."""
    rows = []
    for k, p in enumerate(eqs.structure.points):
        used = {i for (i, _), _ in p.jacobian} | {i for i, a in enumerate(p.acceleration_bias) if a != 0}
        rows += [(k, i) for i in sorted(used)]
    return rows


def structural_source(eqs: StructuralEquations, *, n_params: int, flavour: str = "python",
                      constraint_rhs=None, name: str = "rhs") -> str:
    """Source of ``rhs(t, y, p)`` (with its helper functions) for structural equations.

    ``flavour``: ``"python"`` (numpy), ``"numba"`` (loops; returns a new array) or ``"numba_status"``
    (unconstrained only: ``name(t, y, p, out) -> ok`` writing ``[q̇, q̈]`` into ``out``). With constraints the
    result is ``[q̇, q̈, λ]``. ``constraint_rhs`` replaces c (Baumgarte terms).
    """
    n, m = eqs.n, eqs.m
    if flavour == "numba_status" and m:
        raise ValueError("flavour='numba_status' is for unconstrained systems (no multipliers)")
    s = eqs.structure
    rows = _rows(eqs)
    index = {(k, i): r for r, (k, i) in enumerate(rows)}
    exprs: list = []
    slots: list[tuple[str, object]] = []  # (target text, expression index)

    def put(target: str, e) -> None:
        e = sp.sympify(e)
        if e != 0:
            slots.append((target, len(exprs)))
            exprs.append(e)

    for k, p in enumerate(s.points):
        for (i, j), e in p.jacobian:
            put(f"J[{index[k, i]}, {j}]", e)
        for i in range(3):
            if (k, i) in index:
                put(f"w[{index[k, i]}]", p.mass)
                put(f"g[{index[k, i]}]", p.acceleration_bias[i])
    for i, e in enumerate(s.generalized_force):
        put(f"f[{i}]", e)
    for k, r in enumerate(s.rotors):
        for (i, j), e in r.jacobian:
            put(f"W{k}[{i}, {j}]", e)
        for i in range(3):
            put(f"om{k}[{i}]", r.omega_bias[i])
            put(f"al{k}[{i}]", r.acceleration_bias[i])
            for j in range(3):
                put(f"I{k}[{i}, {j}]", r.inertia[i, j])
    A = eqs.constraint_matrix
    crhs = list(constraint_rhs) if constraint_rhs is not None else list(eqs.constraint_rhs)
    for r in range(m):
        for j in range(n):
            put(f"A[{r}, {j}]", A[r, j])
        put(f"c[{r}]", crhs[r])
    rough = eqs.is_rough
    if rough:
        B = eqs.reaction_matrix
        for j in range(n):
            for r in range(m):
                put(f"B[{j}, {r}]", B[j, r])
    repl, red = _printable_cse(exprs, rename_map(eqs))

    body: list[str] = []
    ys = [f"y{i}" for i in range(2 * n)]
    ps = [f"p{k}" for k in range(n_params)]
    if flavour == "python":
        body.append(f"{', '.join(ys)}, = y.tolist()")
        if ps:
            body.append(f"{', '.join(ps)}, = p")
    else:
        body += [f"y{i} = y[{i}]" for i in range(2 * n)]
        body += [f"p{k} = p[{k}]" for k in range(n_params)]
    body.append(f"J = np.zeros(({len(rows)}, {n}))")
    body.append(f"w = np.zeros({len(rows)})")
    body.append(f"g = np.zeros({len(rows)})")
    body.append(f"f = np.zeros({n})")
    for k in range(len(s.rotors)):
        body += [f"W{k} = np.zeros((3, {n}))", f"om{k} = np.zeros(3)", f"al{k} = np.zeros(3)",
                 f"I{k} = np.zeros((3, 3))"]
    if m:
        body += [f"A = np.zeros(({m}, {n}))", f"c = np.zeros({m})"]
        if rough:
            body.append(f"B = np.zeros(({n}, {m}))")
    body += [f"{sym} = {print_expr(e)}" for sym, e in repl]
    body += [f"{target} = {print_expr(red[i])}" for target, i in slots]
    body.append(f"M = _gram(J, w, {n})")
    body.append(f"f = f - _tmv(J, w * g, {n})")
    if s.rotors:
        body.append(f"qd = np.array([{', '.join(ys[n:])}])")
    for k in range(len(s.rotors)):
        body += [f"om{k} = om{k} + _mv(W{k}, qd)", f"Iw{k} = _mv(I{k}, om{k})",
                 f"h{k} = _mv(I{k}, al{k})",
                 f"h{k}[0] += om{k}[1] * Iw{k}[2] - om{k}[2] * Iw{k}[1]",
                 f"h{k}[1] += om{k}[2] * Iw{k}[0] - om{k}[0] * Iw{k}[2]",
                 f"h{k}[2] += om{k}[0] * Iw{k}[1] - om{k}[1] * Iw{k}[0]",
                 f"IW{k} = np.zeros((3, {n}))"]
        body += [f"IW{k}[{i}] = {' + '.join(f'I{k}[{i}, {j}] * W{k}[{j}]' for j in range(3))}" for i in range(3)]
        body += [f"M = M + np.dot(W{k}.T.copy(), IW{k})" if flavour != "python" else f"M = M + W{k}.T @ IW{k}",
                 f"f = f - _tmv(W{k}, h{k}, {n})"]
    fail = ("return False" if flavour == "numba_status"
            else "raise ZeroDivisionError('mass matrix is not positive definite')")
    if not m:
        body += [f"L, ok = _factor(M, {n})", "if not ok:", f"    {fail}", f"x = _csolve(L, f, {n})"]
        outs_len = 2 * n
    else:
        body += [f"Ma = M + _gram(A, np.ones({m}), {n})", f"fa = f + _tmv(A, c, {n})",
                 f"L, ok = _factor(Ma, {n})", "if not ok:", f"    {fail}", f"xf = _csolve(L, fa, {n})",
                 f"XA = np.zeros(({n}, {m}))"]
        col = "B[:, r].copy()" if rough else "A[r].copy()"
        body += [f"for r in range({m}):", f"    XA[:, r] = _csolve(L, {col}, {n})",
                 f"S = np.zeros(({m}, {m}))", f"for r in range({m}):", "    S[r] = _mv(XA.T.copy(), A[r].copy())",
                 "rr = c - _mv(A, xf)"]
        if rough:
            body.append("lam = _lsolve(S, rr)")
        else:
            body += ["S = 0.5 * (S + S.T)", f"LS, ok = _factor(S, {m})", "if not ok:",
                     "    raise ZeroDivisionError('constraint matrix A M^-1 A^T is not positive definite "
                     "(redundant constraints?)')", f"lam = _csolve(LS, rr, {m})"]
        body.append("x = xf + _mv(XA, lam)")
        outs_len = 2 * n + m
    if flavour == "numba_status":
        body += [f"out[{i}] = y{n + i}" for i in range(n)] + [f"out[{n + i}] = x[{i}]" for i in range(n)]
        body.append("return True")
        head = f"def {name}(t, y, p, out):\n"
    else:
        body.append(f"out = np.empty({outs_len})")
        body += [f"out[{i}] = y{n + i}" for i in range(n)]
        body.append(f"out[{n}:{2 * n}] = x")
        if m:
            body.append(f"out[{2 * n}:] = lam")
        body.append("return out")
        head = f"def {name}(t, y, p):\n"
    helpers = _PY_HELPERS if flavour == "python" else _NUMBA_HELPERS
    main = head + "\n".join("    " + line for line in body) + "\n"
    prefix = "import math\nimport numpy as np\n" if flavour == "python" else ""
    return prefix + helpers.strip("\n") + "\n\n\n" + main


def structural_module_source(eqs: StructuralEquations, backend: str, n_params: int, constraint_rhs) -> str:
    """The generated module of the ``python`` or ``numba`` backend for structural equations. For numba without
    constraints it holds, like :func:`lagrange.codegen.rk_source.field_module_source`, ``rhs_into``, ``rhs``,
    ``power`` (non-conservative systems) and ``field`` for the compiled integrator loops."""
    if backend == "python":
        return structural_source(eqs, n_params=n_params, flavour="python", constraint_rhs=constraint_rhs)
    if eqs.m:
        return structural_source(eqs, n_params=n_params, flavour="numba", constraint_rhs=constraint_rhs)
    from .numba_backend import decorate
    from .rk_source import _NUMPY_ERRORS, FIELD_SIGNATURE, _power_source

    into = structural_source(eqs, n_params=n_params, flavour="numba_status", name="rhs_into")
    n2 = 2 * eqs.n
    parts = [decorate(into, options=_NUMPY_ERRORS),
             f"def rhs(t, y, p):\n    out = np.empty({n2})\n    if not rhs_into(t, y, p, out):\n"
             "        raise ZeroDivisionError('mass matrix is not positive definite')\n    return out\n"]
    if eqs.is_conservative:
        body = "    return rhs_into(t, z, p, out)\n"
    else:
        parts.append(_power_source(eqs, n_params))
        body = (f"    if not rhs_into(t, z, p, out):\n        return False\n    out[{n2}] = power(t, z, p)\n"
                "    return True\n")
    parts.append(f"@numba.njit({FIELD_SIGNATURE!r}, {_NUMPY_ERRORS})\ndef field(t, z, p, out):\n" + body)
    return "\n\n".join(parts)
