"""Text and LaTeX rendering of derived equations with dot notation."""

from __future__ import annotations

import sympy as sp
from sympy.printing.latex import LatexPrinter
from sympy.printing.pretty.pretty import PrettyPrinter
from sympy.printing.pretty.pretty_symbology import pretty_symbol
from sympy.printing.pretty.stringpict import prettyForm

from .conventions import t

__all__ = ["format_equations", "latex_equations", "latex", "pretty"]


class _DotLatex(LatexPrinter):
    """LaTeX printer that writes ``theta(t)`` as ``\\theta`` and time derivatives with dots."""

    def _print_Derivative(self, expr):
        if len(expr.variables) and all(v == t for v in expr.variables) and expr.expr.args == (t,):
            order = len(expr.variables)
            if order <= 4:
                base = self._print(expr.expr)
                acc = {1: "dot", 2: "ddot", 3: "dddot", 4: "ddddot"}[order]
                return rf"\{acc}{{{base}}}"
        return super()._print_Derivative(expr)

    def _print_Function(self, expr, exp=None):
        if expr.args == (t,) and isinstance(expr, sp.core.function.AppliedUndef):
            name = self._deal_with_super_sub(expr.func.__name__)
            return name if exp is None else f"{name}^{{{exp}}}"
        return super()._print_Function(expr, exp)


class _DotPretty(PrettyPrinter):
    def _print_Derivative(self, deriv):
        if all(v == t for v in deriv.variables) and deriv.expr.args == (t,):
            order = len(deriv.variables)
            name = pretty_symbol(deriv.expr.func.__name__)
            marks = {1: "\u0307", 2: "\u0308"}
            text = name + marks[order] if order in marks else f"{name}^({order})"
            return prettyForm(text)
        return super()._print_Derivative(deriv)

    def _print_Function(self, e, sort=False, func_name=None, left="(", right=")"):
        if e.args == (t,) and isinstance(e, sp.core.function.AppliedUndef):
            return prettyForm(pretty_symbol(e.func.__name__))
        return super()._print_Function(e, sort=sort, func_name=func_name, left=left, right=right)


def latex(expr) -> str:
    """LaTeX with dot notation for time derivatives of coordinates."""
    return _DotLatex().doprint(expr)


def pretty(expr) -> str:
    """Unicode pretty-print with dot notation (θ̇, θ̈) for coordinates."""
    return _DotPretty({"use_unicode": True, "wrap_line": False}).doprint(expr)


def _header(system) -> str:
    from .model.coordinates import coordinate_name

    name = system.name or "system"
    coords = ", ".join(coordinate_name(q) for q in system.coordinates)
    n, cons = len(system.coordinates), system.constraints
    if not cons:
        return f"{name}: {n} degree(s) of freedom ({coords})"
    hol = sum(1 for c in cons if c.kind == "holonomic")
    dof = system.dof  # the same counts as repr(system)
    return (f"{name}: {n} coordinates ({coords}), {len(cons)} constraint(s) ({hol} holonomic): "
            f"{dof.configuration} degree(s) of freedom in configuration, {dof.velocity} in velocity")


def format_equations(system) -> str:
    """The system's equations of motion as terminal text, one block per coordinate."""
    lines = [_header(system)]
    eqs = system.equations()
    labels = [f"[{q.func.__name__}]" for q in system.coordinates]
    labels += [f"[constraint {name}, multiplier λ{k + 1}]" for k, name in enumerate(system.derived.constraint_names)]
    for label, eq in zip(labels, eqs):
        lines.append("")
        lines.append(label)
        lines.append(pretty(eq))
    return "\n".join(lines)


def latex_equations(system) -> str:
    """The equations as one LaTeX ``aligned`` block (for Jupyter)."""
    rows = [rf"{latex(eq.lhs)} &= {latex(eq.rhs)}" for eq in system.equations()]
    body = r" \\ ".join(rows)
    return rf"$\displaystyle \begin{{aligned}} {body} \end{{aligned}}$"
