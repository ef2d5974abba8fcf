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

from sympy.printing.pycode import PythonCodePrinter

from .cse import FusedExpressions

__all__ = ["rhs_source", "print_expr"]


class _Printer(PythonCodePrinter):
    def _print_Float(self, expr):
        return repr(float(expr))


_PRINTER = _Printer({"fully_qualified_modules": True, "standard": "python3"})


def print_expr(expr) -> str:
    return _PRINTER.doprint(expr)


def _ldl_lines(n: int, upper: dict) -> tuple[list[str], list[str]]:
    """Straight-line LDLᵀ factorization and solve; returns (lines, names of the solution)."""
    lines: list[str] = []

    def a(i, j):
        i, j = min(i, j), max(i, j)
        return f"a{i}_{j}" if (i, j) in upper else None

    nz = {}  # structural nonzeros of L (strictly lower): nz[(i, j)] -> name
    d = {}
    for j in range(n):
        terms = [f"{nz[(j, k)]}*{nz[(j, k)]}*{d[k]}" for k in range(j) if (j, k) in nz]
        ajj = a(j, j)
        if ajj is None:
            lines.append("raise ZeroDivisionError('mass matrix has a zero diagonal entry')")
            return lines, []
        expr = ajj + "".join(f" - {s}" for s in terms)
        lines.append(f"d{j} = {expr}")
        lines.append(f"if not (d{j} > 1e-13 * abs({ajj})):")
        lines.append("    raise ZeroDivisionError('mass matrix is not positive definite')")
        d[j] = f"d{j}"
        for i in range(j + 1, n):
            aij = a(i, j)
            terms = [f"{nz[(i, k)]}*{nz[(j, k)]}*{d[k]}" for k in range(j) if (i, k) in nz and (j, k) in nz]
            if aij is None and not terms:
                continue
            head = aij if aij is not None else "0.0"
            lines.append(f"l{i}_{j} = ({head}{''.join(f' - {s}' for s in terms)})/d{j}")
            nz[(i, j)] = f"l{i}_{j}"
    # forward substitution L z = b
    for i in range(n):
        terms = [f"{nz[(i, k)]}*z{k}" for k in range(i) if (i, k) in nz]
        lines.append(f"z{i} = b{i}{''.join(f' - {s}' for s in terms)}")
    # diagonal and back substitution Lᵀ x = D⁻¹ z
    for i in reversed(range(n)):
        terms = [f"{nz[(k, i)]}*x{k}" for k in range(i + 1, n) if (k, i) in nz]
        lines.append(f"x{i} = z{i}/d{i}{''.join(f' - {s}' for s in terms)}")
    return lines, [f"x{i}" for i in range(n)]


def rhs_source(fused: FusedExpressions, *, n_params: int, flavour: str = "python", name: str = "rhs") -> str:
    """Source text of ``rhs(t, y, p)``.

    ``flavour="python"`` unpacks ``y.tolist()`` (fast Python floats) and returns a list;
    ``flavour="numba"`` indexes arrays and returns a new ``numpy`` array.
    """
    n = fused.n
    body: list[str] = []
    ys = [f"y{i}" for i in range(2 * n)]
    ps = [f"p{k}" for k in range(n_params)]
    if flavour == "python":
        body.append(f"{', '.join(ys)}, = y.tolist()" if ys else "pass")
        if ps:
            body.append(f"{', '.join(ps)}, = p")
    else:
        body += [f"y{i} = y[{i}]" for i in range(2 * n)]
        body += [f"p{k} = p[{k}]" for k in range(n_params)]
    body += [f"{s} = {print_expr(e)}" for s, e in fused.temporaries]
    body += [f"a{i}_{j} = {print_expr(e)}" for (i, j), e in fused.mass_upper.items()]
    body += [f"b{i} = {print_expr(e)}" for i, e in enumerate(fused.forcing)]
    ldl, xs = _ldl_lines(n, fused.mass_upper)
    body += ldl
    outs = ys[n:] + xs
    if flavour == "python":
        body.append(f"return [{', '.join(outs)}]")
    else:
        body.append(f"out = np.empty({2 * n})")
        body += [f"out[{k}] = {v}" for k, v in enumerate(outs)]
        body.append("return out")
    return f"def {name}(t, y, p):\n" + "\n".join("    " + line for line in body) + "\n"
