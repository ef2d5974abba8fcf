r"""Python source of the fused right-hand side: CSE'd M and f, then an unrolled LDLᵀ solve.

The generated function is straight-line code, valid both as plain Python (the instant default
backend) and under ``numba.njit`` (the compiled backend)::

    def rhs(t, y, p):             # y: shape (2n,), p: shape (k,)
        y0, y1, ... = <state>
        c0 = ...                  # common subexpressions
        a0_0 = ...                # upper triangle of M
        b0 = ...                  # f
        <LDLᵀ of the symmetric positive-definite M, structural zeros skipped>
        return [y{n}, ..., acc0, ...]

M is symmetric positive definite for every physical kinetic energy, so LDLᵀ needs no pivoting; a
pivot that is not positive (relative to the diagonal entry, 1e-13) raises ``ZeroDivisionError`` (turned into
:class:`~lagrange.errors.SingularMassMatrixError` by the caller, with the state).
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from .cse import FusedExpressions

__all__ = ["rhs_source", "print_expr"]


class _Printer(PythonCodePrinter):
    def _print_Float(self, expr):
        return repr(float(expr))


_PRINTER = _Printer({"fully_qualified_modules": True, "standard": "python3"})


#: names symengine prints for the functions and constants it carries
#: (:data:`lagrange.symengine_bridge.FUNCTIONS`), and their Python spelling
_SYMENGINE_NAMES = {**{f: f"math.{f}" for f in ("sin", "cos", "tan", "exp", "log", "sinh", "cosh", "tanh", "asin",
                                                 "acos", "atan", "sqrt")}, "pi": "math.pi", "E": "math.e"}
_SYMENGINE_NAME = re.compile(r"(?<![\w.])(" + "|".join(_SYMENGINE_NAMES) + r")(?![\w.])")


def print_expr(expr) -> str:
    """Python source of ``expr``: a sympy expression (sympy's Python code printer) or a symengine expression
    from :func:`~lagrange.codegen.cse.fuse` (``printable=True``) (symengine's own printer, linear in the size of the
    expression, with its function names and constants qualified by ``math.``; integer ratios such as ``1/3``
    are float divisions in Python 3, as sympy prints them too)."""
    if isinstance(expr, sp.Basic):
        return _PRINTER.doprint(expr)
    text = str(expr)
    if "**(-1/2)" in text:  # sympy prints 1/math.sqrt(x): a domain error, not a complex number, when x < 0
        return _PRINTER.doprint(sp.sympify(expr))
    return _SYMENGINE_NAME.sub(lambda m: _SYMENGINE_NAMES[m.group(1)], text)


def _ldl_factor(n: int, entry, tag: str, what: str, fail: str | None = None) -> tuple[list[str], dict, list[str]]:
    """Straight-line LDLᵀ of a symmetric matrix whose upper entries are named by ``entry(i, j)``
    (None for a structural zero). Returns (lines, names of L's nonzeros, names of D). A pivot that is not
    positive runs ``fail`` (default: raise ZeroDivisionError)."""
    lines: list[str] = []
    nz: dict = {}
    d: list[str] = []
    for j in range(n):
        ajj = entry(j, j)
        if ajj is None:  # structurally zero: the runtime check below raises (singular matrix)
            ajj = "0.0"
        terms = [f"{nz[(j, k)]}*{nz[(j, k)]}*{d[k]}" for k in range(j) if (j, k) in nz]
        lines.append(f"{tag}d{j} = {ajj}{''.join(f' - {x}' for x in terms)}")
        lines.append(f"if not ({tag}d{j} > 1e-13 * abs({ajj})):")
        lines.append("    " + (fail or f"raise ZeroDivisionError('{what} is not positive definite')"))
        d.append(f"{tag}d{j}")
        for i in range(j + 1, n):
            aij = entry(min(i, j), max(i, j))
            terms = [f"{nz[(i, k)]}*{nz[(j, k)]}*{d[k]}" for k in range(j) if (i, k) in nz and (j, k) in nz]
            if aij is None and not terms:
                continue
            head = aij if aij is not None else "0.0"
            lines.append(f"{tag}l{i}_{j} = ({head}{''.join(f' - {x}' for x in terms)})/{tag}d{j}")
            nz[(i, j)] = f"{tag}l{i}_{j}"
    return lines, nz, d


def _ldl_solve(n: int, nz: dict, d: list[str], rhs: list, out: list[str], tag: str) -> list[str]:
    """Lines solving L D Lᵀ x = rhs (``rhs[i]`` a name or None for zero) into the names ``out``."""
    lines = []
    z = []
    for i in range(n):
        terms = [f"{nz[(i, k)]}*{z[k]}" for k in range(i) if (i, k) in nz and z[k] is not None]
        if rhs[i] is None and not terms:
            z.append(None)
            continue
        head = rhs[i] if rhs[i] is not None else "0.0"
        lines.append(f"{tag}z{i} = {head}{''.join(f' - {x}' for x in terms)}")
        z.append(f"{tag}z{i}")
    for i in reversed(range(n)):
        terms = [f"{nz[(k, i)]}*{out[k]}" for k in range(i + 1, n) if (k, i) in nz]
        head = f"{z[i]}/{d[i]}" if z[i] is not None else "0.0"
        lines.append(f"{out[i]} = {head}{''.join(f' - {x}' for x in terms)}")
    return lines


def _lu_lines(m: int, name, rhs: list[str], out: list[str]) -> list[str]:
    """Unrolled Doolittle LU without pivoting for a small dense non-symmetric system (rough constraints)."""
    lines = []
    a = {(i, j): name(i, j) for i in range(m) for j in range(m)}
    b = list(rhs)
    for k in range(m):
        lines.append(f"if abs({a[(k, k)]}) < 1e-300:")
        lines.append("    raise ZeroDivisionError('reaction system is singular (rough constraint)')")
        for i in range(k + 1, m):
            f = f"lf{i}_{k}"
            lines.append(f"{f} = {a[(i, k)]}/{a[(k, k)]}")
            for j in range(k + 1, m):
                new = f"lu{i}_{j}_{k}"
                lines.append(f"{new} = {a[(i, j)]} - {f}*{a[(k, j)]}")
                a[(i, j)] = new
            nb = f"lb{i}_{k}"
            lines.append(f"{nb} = {b[i]} - {f}*{b[k]}")
            b[i] = nb
    for i in reversed(range(m)):
        terms = "".join(f" - {a[(i, j)]}*{out[j]}" for j in range(i + 1, m))
        lines.append(f"{out[i]} = ({b[i]}{terms})/{a[(i, i)]}")
    return lines


def _constrained_lines(n: int, m: int, upper: dict, A: dict, B: dict | None = None
                       ) -> tuple[list[str], list[str], list[str]]:
    """q̈ and λ from ``M q̈ = f + Bλ``, ``A q̈ = c`` by the Schur complement ``S = A M⁻¹ B``.

    ``B = Aᵀ`` (``B is None``) makes S symmetric positive definite (LDLᵀ); rough constraints give a
    general B (unrolled LU). Names: M upper ``a{i}_{j}``, f ``b{i}``, A ``k{r}_{j}`` (``A`` maps present
    (r, j)), c ``e{r}``, B ``h{j}_{r}``.
    """
    lines, nz, d = _ldl_factor(n, lambda i, j: f"a{i}_{j}" if (i, j) in upper else None, "", "mass matrix")
    lines += _ldl_solve(n, nz, d, [f"b{i}" for i in range(n)], [f"xf{i}" for i in range(n)], "f")
    for r in range(m):
        if B is None:
            rhs = [f"k{r}_{j}" if (r, j) in A else None for j in range(n)]
        else:
            rhs = [f"h{j}_{r}" if (j, r) in B else None for j in range(n)]
        lines += _ldl_solve(n, nz, d, rhs, [f"xa{r}_{j}" for j in range(n)], f"a{r}")
    for r in range(m):
        for s_ in range(r if B is None else 0, m):
            terms = [f"k{r}_{j}*xa{s_}_{j}" for j in range(n) if (r, j) in A]
            lines.append(f"s{r}_{s_} = {' + '.join(terms) if terms else '0.0'}")
        terms = [f"k{r}_{j}*xf{j}" for j in range(n) if (r, j) in A]
        lines.append(f"rr{r} = e{r}{''.join(f' - {x}' for x in terms)}")
    lam = [f"lam{r}" for r in range(m)]
    if B is None:
        fl, snz, sd = _ldl_factor(m, lambda i, j: f"s{i}_{j}", "S",
                                  "constraint matrix A M^-1 A^T (redundant constraints?)")
        lines += fl
        lines += _ldl_solve(m, snz, sd, [f"rr{r}" for r in range(m)], lam, "S")
    else:
        lines += _lu_lines(m, lambda i, j: f"s{i}_{j}", [f"rr{r}" for r in range(m)], lam)
    acc = []
    for i in range(n):
        terms = [f"xa{r}_{i}*lam{r}" for r in range(m)]
        lines.append(f"x{i} = xf{i}{''.join(f' + {x}' for x in terms)}")
        acc.append(f"x{i}")
    return lines, acc, lam


def rhs_source(fused: FusedExpressions, *, n_params: int, flavour: str = "python", name: str = "rhs",
               with_mass: bool = False, rule=None) -> str:
    """Source text of ``rhs(t, y, p)``.

    ``flavour="python"`` unpacks ``y.tolist()`` (fast Python floats) and returns a list;
    ``flavour="numba"`` indexes arrays and returns a new ``numpy`` array; ``flavour="numba_status"``
    (unconstrained systems only) is ``name(t, y, p, out) -> ok``, writing into ``out[:2n]`` without
    allocating and returning False instead of raising on a mass matrix that is not positive definite (the
    body of the numba module that the compiled integrator loops call, :mod:`lagrange.codegen.rk_source`).
    With constraints the result is ``[q̇, q̈, λ]`` (length 2n + m), without them ``[q̇, q̈]``.
    Integrals that remain in the equations (``fused.quadratures``) are computed first, by ``rule``
    (:class:`lagrange.codegen.quadrature.Rule`, default :data:`~lagrange.codegen.quadrature.DEFAULT_RULE`): numpy
    arrays over the nodes in the python flavour, loops in the numba flavours.
    ``with_mass=True`` (python flavour, no constraints) appends ``mass(t, y, p)``: M as a nested list of rows, from
    the same printed lines (only the temporaries M needs), for
    :meth:`~lagrange.codegen.numeric.NumericModel.mass_matrix`.
    """
    n = fused.n
    if flavour == "numba_status" and fused.m:
        raise ValueError("flavour='numba_status' is for unconstrained systems (no multipliers)")
    body: list[str] = []
    ys = [f"y{i}" for i in range(2 * n)]
    ps = [f"p{k}" for k in range(n_params)]
    if flavour == "python":  # the unpacking, kept as the head of mass() too
        head = [f"{', '.join(ys)}, = y.tolist()" if ys else "pass"] + ([f"{', '.join(ps)}, = p"] if ps else [])
        body += head
    else:
        body += [f"y{i} = y[{i}]" for i in range(2 * n)]
        body += [f"p{k} = p[{k}]" for k in range(n_params)]
    if fused.quadratures:
        from .quadrature import DEFAULT_RULE, quadrature_lines

        quad = quadrature_lines(fused.quadratures, rule or DEFAULT_RULE, flavour, print_expr)
        body += quad
        if flavour == "python":
            head = head + quad  # mass() computes them too (T may hold an integral)
    temporaries = [(str(s), f"{s} = {print_expr(e)}") for s, e in fused.temporaries]
    mass_lines = [f"a{i}_{j} = {print_expr(e)}" for (i, j), e in fused.mass_upper.items()]
    body += [line for _, line in temporaries] + mass_lines
    body += [f"b{i} = {print_expr(e)}" for i, e in enumerate(fused.forcing)]
    if fused.m:
        body += [f"k{r}_{j} = {print_expr(e)}" for (r, j), e in fused.constraint_matrix.items()]
        body += [f"e{r} = {print_expr(e)}" for r, e in enumerate(fused.constraint_rhs)]
        if fused.reaction is not None:
            body += [f"h{j}_{r} = {print_expr(e)}" for (j, r), e in fused.reaction.items()]
        lines, xs, lam = _constrained_lines(n, fused.m, fused.mass_upper, fused.constraint_matrix, fused.reaction)
        body += lines
        outs = ys[n:] + xs + lam
    else:
        lines, nz, d = _ldl_factor(n, lambda i, j: f"a{i}_{j}" if (i, j) in fused.mass_upper else None, "",
                                   "mass matrix", "return False" if flavour == "numba_status" else None)
        body += lines
        xs = [f"x{i}" for i in range(n)]
        body += _ldl_solve(n, nz, d, [f"b{i}" for i in range(n)], xs, "")
        outs = ys[n:] + xs
    if flavour == "python":
        body.append(f"return [{', '.join(outs)}]")
        if with_mass and not fused.m:  # (with constraints the a{i}_{j} are M + AᵀA, the augmented matrix)
            return (_function(name, body) + "\n\n"
                    + _function("mass", _mass_body(n, head, temporaries, mass_lines, fused.mass_upper)))
    elif flavour == "numba_status":
        body += [f"out[{k}] = {v}" for k, v in enumerate(outs)] + ["return True"]
        return f"def {name}(t, y, p, out):\n" + "\n".join("    " + line for line in body) + "\n"
    else:
        body.append(f"out = np.empty({len(outs)})")
        body += [f"out[{k}] = {v}" for k, v in enumerate(outs)]
        body.append("return out")
    return _function(name, body)


def _function(name: str, body: list[str]) -> str:
    return f"def {name}(t, y, p):\n" + "\n".join("    " + line for line in body) + "\n"


_NAME = re.compile(r"[A-Za-z_]\w*")


def _mass_body(n: int, head: list[str], temporaries: list[tuple[str, str]], mass_lines: list[str],
               upper: dict) -> list[str]:
    """The body of ``mass(t, y, p)``: the unpacking ``head``, the temporaries the entries of M use (found by
    walking the CSE back from them), the entries, the rows (structural zeros as 0.0, the lower triangle by
    symmetry)."""
    needed = {w for line in mass_lines for w in _NAME.findall(line.partition(" = ")[2])}
    kept = []
    for name, line in reversed(temporaries):
        if name in needed:
            kept.append(line)
            needed |= set(_NAME.findall(line.partition(" = ")[2]))
    head = [h.replace(" = y.tolist()", " = y") for h in head]  # called with lists (mass_matrix)

    def entry(i, j):
        key = (min(i, j), max(i, j))
        return f"a{key[0]}_{key[1]}" if key in upper else "0.0"

    rows = ", ".join("[" + ", ".join(entry(i, j) for j in range(n)) + "]" for i in range(n))
    return head + kept[::-1] + mass_lines + [f"return [{rows}]"]
