"""Text and LaTeX rendering of derived equations with dot notation: display only.

Everything here works on copies made for display: :func:`display_equations` tidies the trigonometry of
:meth:`System.equations <lagrange.System.equations>` (``sin a sin b + cos a cos b → cos(a − b)``,
``sin a cos b − cos a sin b → sin(a − b)``, ``sin² u + cos² u → 1``) under a size and time budget, and
:func:`format_expression` wraps pretty-printed equations to a width (default :data:`WIDTH` columns) by
breaking sums between terms. The derived :class:`~lagrange.derive.equations.Equations` and the generated
code never see either.
"""

from __future__ import annotations

import textwrap

import sympy as sp
from sympy.printing.latex import LatexPrinter
from sympy.printing.pretty.pretty import PrettyPrinter
from sympy.printing.pretty.pretty_symbology import pretty_symbol
from sympy.printing.pretty.stringpict import prettyForm, stringPict
from sympy.simplify.fu import TR5, TR6, TR10i

from ._text import printable
from .budget import PRINT_NODES, check, fits
from .conventions import t
from .errors import SymbolicTimeoutError
from .safe_sympify import sympify as _sympify
from .simplification import run_bounded

__all__ = ["WIDTH", "format_equations", "format_expression", "format_momenta", "display_equations", "tidy_trig",
           "terminal_width", "latex_equations", "latex", "pretty", "printable"]

#: Default width of text output (columns).
WIDTH = 100
#: Expressions above this many operations are shown as derived (no trigonometric tidy-up).
TIDY_LIMIT = 400
#: an equation with more nodes than this in its printed form is summarized by :func:`format_equations`
TERMINAL_NODES = 6_000
#: Wall-time budget of one expression's tidy-up (seconds); past it the expression is shown as derived.
TIDY_SECONDS = 2.0
_INDENT = "    "  # continuation lines of a wrapped equation


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
    """Unicode pretty-print with dot notation (θ̇, θ̈) for coordinates (one picture, not wrapped: see
    :func:`format_expression`)."""
    return _DotPretty({"use_unicode": True, "wrap_line": False}).doprint(expr)


# ------------------------------------------------------------------------------------------ user text



# ---------------------------------------------------------------------------------------- trigonometry

def _pythagoras(node):
    """``node`` with sin² u → 1 − cos² u or cos² u → 1 − sin² u (expanded), whichever is shortest, if
    shorter than ``node``; only sums holding a sin² or cos² are tried."""
    if not node.is_Add or not any(p.exp.is_Integer and p.exp >= 2 and isinstance(p.base, (sp.sin, sp.cos))
                                  for p in node.atoms(sp.Pow)) or not fits(node):
        return node
    best, cost = node, sp.count_ops(node)
    for rule in (TR5, TR6):
        e = sp.expand(rule(node), trig=False)
        c = sp.count_ops(e)
        if c < cost:
            best, cost = e, c
    return best


def _tidy(expr):
    e = TR10i(expr)  # sin a sin b + cos a cos b → cos(a − b), sin a cos b ± cos a sin b → sin(a ± b), …
    e2 = sp.bottom_up(e, _pythagoras)
    e = TR10i(e2) if e2 != e else e  # a Pythagorean step can expose another angle sum
    return e if sp.count_ops(e) <= sp.count_ops(expr) else expr


def tidy_trig(expr, *, limit: int = TIDY_LIMIT, seconds: float = TIDY_SECONDS):
    r"""A mathematically equal, more readable form of ``expr`` for display (never for computation).

    Applies Fu's rule TR10i (:math:`\sin a\sin b + \cos a\cos b \to \cos(a-b)`,
    :math:`\sin a\cos b - \cos a\sin b \to \sin(a-b)` and the sums) bottom-up, then the Pythagorean
    identity :math:`\sin^2 u + \cos^2 u = 1` in each sum where it shortens it, then TR10i again. The result
    is kept only if it has no more operations than ``expr``.

    Bounded: ``expr`` is returned unchanged above ``limit`` operations (:data:`TIDY_LIMIT`) or when the
    tidy-up takes longer than ``seconds`` (:data:`TIDY_SECONDS`, through
    :func:`lagrange.simplification.run_bounded`). An ``Eq`` is tidied side by side.

    >>> import sympy as sp
    >>> from lagrange import coordinates
    >>> a, b = coordinates("a b")
    >>> tidy_trig(sp.sin(a)*sp.sin(b) + sp.cos(a)*sp.cos(b) + sp.sin(a)**2 + sp.cos(a)**2)
    cos(a(t) - b(t)) + 1
    """
    expr = _sympify(expr, where="the expression to print")
    if isinstance(expr, sp.Equality):
        return sp.Eq(tidy_trig(expr.lhs, limit=limit, seconds=seconds),
                     tidy_trig(expr.rhs, limit=limit, seconds=seconds), evaluate=False)
    if not expr.has(sp.sin, sp.cos) or sp.count_ops(expr) > limit:
        return expr
    try:
        return run_bounded(_tidy, expr, what="a trigonometric tidy-up for display", seconds=seconds)
    except SymbolicTimeoutError:
        return expr
    except Exception:  # noqa: BLE001 - display only: a rule sympy cannot apply leaves the expression as derived
        return expr


def display_equations(system) -> list[sp.Eq]:
    """:meth:`System.equations <lagrange.System.equations>` with :func:`tidy_trig` applied: for reading only
    (the system's derived equations and generated code are untouched)."""
    return [tidy_trig(eq) for eq in system.equations()]


# ------------------------------------------------------------------------------------------- wrapping

def terminal_width(default: int = WIDTH) -> int:
    """The terminal's width in columns (``$COLUMNS`` first, ``default`` when not a terminal), at least 40."""
    import shutil

    return max(40, shutil.get_terminal_size((default, 24)).columns)


def _pieces(side, printer, room: int) -> list:
    """``[(sign, picture)]`` of the summands of ``side`` in print order, sign ``"+"`` or ``"-"``; a product wider
    than ``room`` is distributed over its largest sum factor (recursively), anything else stays whole."""

    def split(term) -> list:
        negative = term.could_extract_minus_sign()
        form = printer._print(-term if negative else term)
        adds = [f for f in term.args if f.is_Add] if term.is_Mul and form.width() > room else []
        if not adds:
            return [("-" if negative else "+", form)]
        widest = max(adds, key=sp.count_ops)
        rest = sp.Mul(*[f for f in term.args if f is not widest])
        return [piece for a in widest.as_ordered_terms() for piece in split(rest * a)]

    terms = side.as_ordered_terms() if side.is_Add else [side]
    return [piece for term in terms for piece in split(term)]


def format_expression(expr, width: int = WIDTH, indent: str = "") -> str:
    """Pretty-printed ``expr`` (an expression or an ``Eq``) in lines of at most ``width`` columns.

    Sums are broken between terms; continuation lines start with the operator (``+``, ``-`` or ``=``),
    indented by four spaces; a product wider than a line is distributed over its widest sum factor. A
    single term still wider than the line (a long quotient) is cut by sympy's own line wrapping, so no line
    is ever longer than ``width``. ``indent`` prefixes every line.
    """
    printer = _DotPretty({"use_unicode": True, "wrap_line": False})
    expr = _sympify(expr, where="the expression to print")
    check(expr, stage="printing", what="the equation", max_nodes=PRINT_NODES)
    sides = [expr.lhs, expr.rhs] if isinstance(expr, sp.Equality) else [expr]
    room = width - len(indent) - len(_INDENT) - 2
    pieces = []
    for k, side in enumerate(sides):
        side_pieces = _pieces(side, printer, room)
        if k == 1:  # the first piece of the right side carries the "="
            sign, form = side_pieces[0]
            side_pieces[0] = ("=", prettyForm(*stringPict.next("-", form)) if sign == "-" else form)
        pieces += side_pieces
    lines, line = [], None
    for op, form in pieces:
        if line is None:
            start = [indent] + ([] if op == "+" else [op + " "] if op == "=" else ["-"])
            line = prettyForm(*stringPict.next(*start, form))
            continue
        joined = prettyForm(*stringPict.next(line, f" {op} ", form))
        if joined.width() <= width:
            line = joined
        else:
            lines.append(line)
            line = prettyForm(*stringPict.next(indent + _INDENT, f"{op} ", form))
    lines.append(line)
    return "\n".join(pic.render(wrap_line=pic.width() > width, num_columns=width, use_unicode=True) for pic in lines)


# ------------------------------------------------------------------------------------------- systems

def _header(system, width: int) -> str:
    import textwrap

    from .model.coordinates import coordinate_name

    name = printable(system.name or "system")
    coords = ", ".join(coordinate_name(q) for q in system.coordinates)
    n, cons = len(system.coordinates), system.constraints
    if not cons:
        text = f"{name}: {n} degree(s) of freedom ({coords})"
    else:
        hol = sum(1 for c in cons if c.kind == "holonomic")
        dof = system.dof  # the same counts as repr(system)
        text = (f"{name}: {n} coordinates ({coords}), {len(cons)} constraint(s) ({hol} holonomic): "
                f"{dof.configuration} degree(s) of freedom in configuration, {dof.velocity} in velocity")
    return textwrap.fill(text, width, subsequent_indent=_INDENT, break_on_hyphens=False)


def _tree_size(e, cap: int) -> int:
    """Nodes of ``e``'s expression tree with repeated subtrees counted each time (what a printed form shows);
    stops counting above ``cap``."""
    n = 0
    for _ in sp.preorder_traversal(e):
        n += 1
        if n > cap:
            break
    return n


def format_equations(system, width: int = WIDTH, *, full: bool = False) -> str:
    """The system's equations of motion as terminal text, one block per coordinate, lines of at most
    ``width`` columns (:func:`display_equations` wrapped by :func:`format_expression`).

    An equation with more than :data:`TERMINAL_NODES` nodes in its printed form (the Whipple bicycle's have
    up to ~70,000) is not printed but summarized in one line: a screenful of it cannot be read, and sympy's
    pretty printer needs minutes for it. ``full=True`` prints every equation whole (``lagrange derive --full``).
    """
    lines = [_header(system, width)]
    labels = [f"[{q.func.__name__}]" for q in system.coordinates]
    labels += [f"[constraint {name}, multiplier λ{k + 1}]" for k, name in enumerate(system.derived.constraint_names)]
    for label, eq in zip(labels, system.equations()):
        lines.append("")
        lines.append(label)
        if not full and _tree_size(eq, TERMINAL_NODES) > TERMINAL_NODES:
            lines.append(textwrap.fill(
                f"(more than {TERMINAL_NODES:,} terms and factors: too long to read here; `lagrange derive "
                "--full` prints it whole, `--latex` as LaTeX, System.equations() gives it to Python)",
                width, initial_indent=_INDENT, subsequent_indent=_INDENT))
        else:
            lines.append(format_expression(tidy_trig(eq), width))
    return "\n".join(lines)


def format_momenta(system, width: int = WIDTH) -> str:
    """The conserved momenta ``p_q = ∂L/∂q̇`` of the ignorable coordinates as terminal text (empty when
    there are none), one wrapped equation ``p_q = …`` per coordinate."""
    ign = system.ignorable_coordinates()
    if not ign:
        return ""
    lines = ["ignorable coordinates (conserved momenta):"]
    for q, p in ign.items():
        eq = sp.Eq(sp.Symbol(f"p_{q.func.__name__}"), tidy_trig(p), evaluate=False)
        lines.append(format_expression(eq, width, indent="  "))
    return "\n".join(lines)


def latex_equations(system) -> str:
    """The equations (:func:`display_equations`) as one LaTeX ``aligned`` block (for Jupyter)."""
    eqs = display_equations(system)
    for eq in eqs:
        check(eq, stage="printing", what="the equation", max_nodes=PRINT_NODES)
    rows = [rf"{latex(eq.lhs)} &= {latex(eq.rhs)}" for eq in eqs]
    body = r" \\ ".join(rows)
    return rf"$\displaystyle \begin{{aligned}} {body} \end{{aligned}}$"
