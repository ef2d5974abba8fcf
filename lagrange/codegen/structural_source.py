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


def _collect(eqs: StructuralEquations, constraint_rhs) -> tuple[list, list]:
    """The rows of the stacked point Jacobian and ``(kind, key, expression)`` of every nonzero input of the
    assembly: ``J (r, j)``, ``w r`` (mass of row r), ``g r`` (its a), ``f i`` (Q), ``W (k, i, j)``, ``om (k, i)``
    (ω_t), ``al (k, i)``, ``I (k, i, j)``, ``A (r, j)``, ``c r``, ``B (j, r)`` (rough constraints only)."""
    n, m, s = eqs.n, eqs.m, eqs.structure
    rows = _rows(eqs)
    index = {(k, i): r for r, (k, i) in enumerate(rows)}
    items: list = []

    def put(kind, key, e):
        e = sp.sympify(e)
        if e != 0:
            items.append((kind, key, e))

    for k, p in enumerate(s.points):
        for (i, j), e in p.jacobian:
            put("J", (index[k, i], j), e)
        for i in range(3):
            if (k, i) in index:
                put("w", index[k, i], p.mass)
                put("g", index[k, i], p.acceleration_bias[i])
    for i, e in enumerate(s.generalized_force):
        put("f", i, e)
    for k, r in enumerate(s.rotors):
        for (i, j), e in r.jacobian:
            put("W", (k, i, j), e)
        for i in range(3):
            put("om", (k, i), r.omega_bias[i])
            put("al", (k, i), r.acceleration_bias[i])
            for j in range(3):
                put("I", (k, i, j), r.inertia[i, j])
    A = eqs.constraint_matrix
    crhs = list(constraint_rhs) if constraint_rhs is not None else list(eqs.constraint_rhs)
    for r in range(m):
        for j in range(n):
            put("A", (r, j), A[r, j])
        put("c", r, crhs[r])
    if eqs.is_rough:
        B = eqs.reaction_matrix
        for j in range(n):
            for r in range(m):
                put("B", (j, r), B[j, r])
    return rows, items


#: the python flavour prints M and f as straight-line scalar code (then the unrolled LDLᵀ of
#: :mod:`lagrange.codegen.source`) when assembling and solving takes at most this many products
#: (:func:`_scalar_work`), else numpy arrays. Measured per call (medians, one process): bicycle (1,553) 275 µs
#: straight-line against 1,813 µs with numpy (dozens of small-array calls and solves at several µs each);
#: 15-link pendulum (1,922) 548 against 655 µs; 20-link (about 4,400) 1,268 against 398 µs.
SCALAR_LIMIT = 2500


def _scalar_work(eqs: StructuralEquations, rows, items) -> int:
    n, m = eqs.n, eqs.m
    per_row: dict = {}
    for kind, key, _ in items:
        if kind == "J":
            per_row[key[0]] = per_row.get(key[0], 0) + 1
    work = sum(c * (c + 1) // 2 for c in per_row.values())
    work += len(eqs.structure.rotors) * (9 * n + 3 * n * (n + 1) // 2)
    return work + m * n * n + n ** 3 // 6 + m * n * n


def structural_source(eqs: StructuralEquations, *, n_params: int, flavour: str = "python",
                      constraint_rhs=None, name: str = "rhs") -> str:
    """Source of ``rhs(t, y, p)`` (with its helper functions) for structural equations.

    ``flavour``: ``"python"`` (straight-line scalar code up to :data:`SCALAR_LIMIT` products, numpy above),
    ``"numba"`` (loops; returns a new array) or ``"numba_status"`` (unconstrained only:
    ``name(t, y, p, out) -> ok`` writing ``[q̇, q̈]`` into ``out``). With constraints the result is
    ``[q̇, q̈, λ]``. ``constraint_rhs`` replaces c (Baumgarte terms).
    """
    n, m = eqs.n, eqs.m
    if flavour == "numba_status" and m:
        raise ValueError("flavour='numba_status' is for unconstrained systems (no multipliers)")
    rows, items = _collect(eqs, constraint_rhs)
    repl, red = _printable_cse([e for _, _, e in items], rename_map(eqs))
    head: list[str] = []
    ys = [f"y{i}" for i in range(2 * n)]
    ps = [f"p{k}" for k in range(n_params)]
    if flavour == "python":
        head.append(f"{', '.join(ys)}, = y.tolist()")
        if ps:
            head.append(f"{', '.join(ps)}, = p")
    else:
        head += [f"y{i} = y[{i}]" for i in range(2 * n)]
        head += [f"p{k} = p[{k}]" for k in range(n_params)]
    head += [f"{sym} = {print_expr(e)}" for sym, e in repl]
    printed = [(kind, key, print_expr(e)) for (kind, key, _), e in zip(items, red)]
    if flavour == "python" and _scalar_work(eqs, rows, items) <= SCALAR_LIMIT:
        return _scalar_source(eqs, rows, printed, head, name)
    return _array_source(eqs, rows, printed, head, flavour, name)


def _array_source(eqs, rows, printed, head, flavour: str, name: str) -> str:
    n, m = eqs.n, eqs.m
    s = eqs.structure
    rough = eqs.is_rough
    ys = [f"y{i}" for i in range(2 * n)]
    body = []
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
    body = head + body
    target = {"J": lambda k: f"J[{k[0]}, {k[1]}]", "w": lambda k: f"w[{k}]", "g": lambda k: f"g[{k}]",
              "f": lambda k: f"f[{k}]", "W": lambda k: f"W{k[0]}[{k[1]}, {k[2]}]",
              "om": lambda k: f"om{k[0]}[{k[1]}]", "al": lambda k: f"al{k[0]}[{k[1]}]",
              "I": lambda k: f"I{k[0]}[{k[1]}, {k[2]}]", "A": lambda k: f"A[{k[0]}, {k[1]}]",
              "c": lambda k: f"c[{k}]", "B": lambda k: f"B[{k[0]}, {k[1]}]"}
    body += [f"{target[kind](key)} = {text}" for kind, key, text in printed]
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
                 f"L, ok = _factor(Ma, {n})", "if not ok:", f"    {fail}"]
        col = "B" if rough else "A.T"
        if flavour == "python":  # one pair of triangular solves for f and every column of B
            body += [f"X = _csolve(L, np.column_stack((fa, {col})), {n})", "xf = X[:, 0]", "XA = X[:, 1:]",
                     "S = A @ XA", "rr = c - A @ xf"]
        else:
            col = "B[:, r].copy()" if rough else "A[r].copy()"
            body += [f"xf = _csolve(L, fa, {n})", f"XA = np.zeros(({n}, {m}))",
                     f"for r in range({m}):", f"    XA[:, r] = _csolve(L, {col}, {n})",
                     f"S = np.zeros(({m}, {m}))", f"for r in range({m}):",
                     "    S[r] = _mv(XA.T.copy(), A[r].copy())", "rr = c - _mv(A, xf)"]
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
        top = f"def {name}(t, y, p, out):\n"
    else:
        body.append(f"out = np.empty({outs_len})")
        body += [f"out[{i}] = y{n + i}" for i in range(n)]
        body.append(f"out[{n}:{2 * n}] = x")
        if m:
            body.append(f"out[{2 * n}:] = lam")
        body.append("return out")
        top = f"def {name}(t, y, p):\n"
    helpers = _PY_HELPERS if flavour == "python" else _NUMBA_HELPERS
    main = top + "\n".join("    " + line for line in body) + "\n"
    prefix = "import math\nimport numpy as np\n" if flavour == "python" else ""
    return prefix + helpers.strip("\n") + "\n\n\n" + main


def _scalar_source(eqs, rows, printed, head, name: str) -> str:
    """Straight-line python: M's upper triangle ``a{i}_{j}`` and f ``b{i}`` summed from the named J, W, I, …
    entries, then :mod:`lagrange.codegen.source`'s unrolled LDLᵀ (and its Schur complement with constraints,
    on the augmented ``M + AᵀA``, ``f + Aᵀc`` as there)."""
    from .source import _constrained_lines, _ldl_factor, _ldl_solve

    n, m = eqs.n, eqs.m
    s = eqs.structure
    name_of = {"J": lambda k: f"j{k[0]}_{k[1]}", "w": lambda k: f"w{k}", "g": lambda k: f"g{k}",
               "f": lambda k: f"q{k}", "W": lambda k: f"W{k[0]}_{k[1]}_{k[2]}", "om": lambda k: f"om{k[0]}_{k[1]}",
               "al": lambda k: f"al{k[0]}_{k[1]}", "I": lambda k: f"I{k[0]}_{k[1]}_{k[2]}",
               "A": lambda k: f"k{k[0]}_{k[1]}", "c": lambda k: f"e{k}", "B": lambda k: f"h{k[0]}_{k[1]}"}
    present = {(kind, key) for kind, key, _ in printed}
    body = head + [f"{name_of[kind](key)} = {text}" for kind, key, text in printed]

    def nm(kind, key):
        return name_of[kind](key) if (kind, key) in present else None

    upper: dict = {}  # (i, j): list of product terms
    force: dict = {i: ([nm("f", i)] if nm("f", i) else []) for i in range(n)}
    by_row: dict = {}
    for kind, key, _ in printed:
        if kind == "J":
            by_row.setdefault(key[0], []).append(key[1])
    for r, cols in by_row.items():
        w, g = nm("w", r), nm("g", r)
        if w is None:
            continue
        cols = sorted(cols)
        if g is not None:
            body.append(f"wg{r} = {w}*{g}")
        for a, i in enumerate(cols):
            for j in cols[a:]:
                upper.setdefault((i, j), []).append(f"{w}*j{r}_{i}*j{r}_{j}")
            if g is not None:
                force[i].append(f"-j{r}_{i}*wg{r}")
    qd = [f"y{n + j}" for j in range(n)]
    for k in range(len(s.rotors)):
        Wn = {(i, j): nm("W", (k, i, j)) for i in range(3) for j in range(n)}
        In = {(i, j): nm("I", (k, i, j)) for i in range(3) for j in range(3)}
        for i in range(3):
            terms = [f"{Wn[i, j]}*{qd[j]}" for j in range(n) if Wn[i, j]] + ([nm("om", (k, i))] if nm("om", (k, i))
                                                                              else [])
            body.append(f"o{k}_{i} = {' + '.join(terms) if terms else '0.0'}")
        for i in range(3):
            terms = [f"{In[i, j]}*o{k}_{j}" for j in range(3) if In[i, j]]
            body.append(f"io{k}_{i} = {' + '.join(terms) if terms else '0.0'}")
            terms = [f"{In[i, j]}*{nm('al', (k, j))}" for j in range(3) if In[i, j] and nm("al", (k, j))]
            body.append(f"ia{k}_{i} = {' + '.join(terms) if terms else '0.0'}")
        cyc = ((1, 2), (2, 0), (0, 1))
        for i, (a, b) in enumerate(cyc):
            body.append(f"hh{k}_{i} = ia{k}_{i} + o{k}_{a}*io{k}_{b} - o{k}_{b}*io{k}_{a}")
        cols = sorted({j for (i, j), v in Wn.items() if v})
        for j in cols:
            for i in range(3):
                terms = [f"{In[i, a]}*{Wn[a, j]}" for a in range(3) if In[i, a] and Wn[a, j]]
                if terms:
                    body.append(f"iw{k}_{i}_{j} = {' + '.join(terms)}")
        have = {(i, j) for j in cols for i in range(3)
                if any(In[i, a] and Wn[a, j] for a in range(3))}
        for a_, i in enumerate(cols):
            for j in cols[a_:]:
                terms = [f"{Wn[b, i]}*iw{k}_{b}_{j}" for b in range(3) if Wn[b, i] and (b, j) in have]
                if terms:
                    upper.setdefault((i, j), []).extend(terms)
            force[i] += [f"-{Wn[b, i]}*hh{k}_{b}" for b in range(3) if Wn[b, i]]
    Aset = {(key[0], key[1]) for kind, key, _ in printed if kind == "A"}
    for r in range(m):  # the augmented form of codegen/cse.py: (M + AᵀA) q̈ = f + Aᵀc + Bλ
        cols = sorted(j for (rr, j) in Aset if rr == r)
        for a_, i in enumerate(cols):
            for j in cols[a_:]:
                upper.setdefault((i, j), []).append(f"k{r}_{i}*k{r}_{j}")
            if nm("c", r):
                force[i].append(f"k{r}_{i}*e{r}")
    for (i, j), terms in sorted(upper.items()):
        body.append(f"a{i}_{j} = {' + '.join(terms)}")
    for i in range(n):
        body.append(f"b{i} = {' + '.join(force[i]) if force[i] else '0.0'}".replace("+ -", "- "))
    if m:
        body += [f"e{r} = 0.0" for r in range(m) if not nm("c", r)]
        B = None
        if eqs.is_rough:
            B = {(key[0], key[1]): True for kind, key, _ in printed if kind == "B"}
        lines, xs, lam = _constrained_lines(n, m, upper, {rj: True for rj in Aset}, B)
        body += lines
        outs = qd + xs + lam
    else:
        lines, nz, d = _ldl_factor(n, lambda i, j: f"a{i}_{j}" if (i, j) in upper else None, "", "mass matrix")
        body += lines
        xs = [f"x{i}" for i in range(n)]
        body += _ldl_solve(n, nz, d, [f"b{i}" for i in range(n)], xs, "")
        outs = qd + xs
    body.append(f"return [{', '.join(outs)}]")
    return f"def {name}(t, y, p):\n" + "\n".join("    " + line for line in body) + "\n"


def structural_module_source(eqs: StructuralEquations, backend: str, n_params: int, constraint_rhs) -> str:
    """The generated module of the ``python`` or ``numba`` backend for structural equations. For numba without
    constraints it holds, like :func:`lagrange.codegen.rk_source.field_module_source`, ``rhs_into``, ``rhs``,
    ``power`` (non-conservative systems) and ``field`` for the compiled integrator loops."""
    if backend == "python":
        return structural_source(eqs, n_params=n_params, flavour="python", constraint_rhs=constraint_rhs)
    if eqs.m:
        return structural_source(eqs, n_params=n_params, flavour="numba", constraint_rhs=constraint_rhs)
    from .numba_backend import decorate
    from .rk_source import _NUMPY_ERRORS, field_module_around

    into = structural_source(eqs, n_params=n_params, flavour="numba_status", name="rhs_into")
    return field_module_around(decorate(into, options=_NUMPY_ERRORS), eqs, n_params)
