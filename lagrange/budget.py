r"""Size budgets of the symbolic stages: decided from the expression before the work, not by a clock.

(The work itself is budgeted by :mod:`lagrange.limits`: a CPU-time deadline and a node count of what was built.
The estimates here refuse only declared inputs; above :data:`EXPAND_NODES` they skip a clean-up, never refuse.)

A short expression can stand for an enormous amount of work: ``(x + y + m + g + k + 1)**(99/2)`` has 21
characters and multiplies out to about 3 million terms; ``exp(10**30*log(x))`` is ``x**(10**30)``, which
no exact evaluation can finish; ``exp(exp(exp(exp(exp(x)))))`` overflows any arbitrary-precision
evaluation at an ordinary point. Every symbolic stage of lagrange therefore measures its input first:

* :func:`expansion_estimate` — an upper estimate ``(terms, nodes)`` of ``sympy.expand(e)``, computed
  without expanding (sums add, products multiply, a power of a sum with a numeric exponent ``p`` —
  integer, rational or float — has the multinomial count of its integer part times the remaining
  fractional power, ``exp`` of a sum becomes a product of exponentials);
* :func:`max_exponent` — the largest constant exponent in magnitude (``exp(c*log(x))`` is already
  ``x**c`` in sympy);
* :func:`exp_nesting` — the depth of a tower of exponentials (``exp``, ``sinh``, ``cosh``);
* :func:`node_count` — the number of nodes of the expression tree (each shared subtree counted once).

A stage whose result is required (the declaration of a system, differentiation, common-subexpression
elimination, printing) raises :class:`~lagrange.errors.ExpressionTooLarge` naming the stage and the
expression (abbreviated) when a limit is exceeded (:func:`check`). A stage that only tidies (the
trigonometric clean-up of T and of the displayed equations, ``simplify``) skips the tidy-up instead
(:func:`fits`): its result is the same expression, less tidy. The limits are module constants:

======================  =========  ==========================================================================
limit                   value      applies to
======================  =========  ==========================================================================
:data:`MAX_EXPONENT`    1000       every declared expression (the spec parser allows 100)
:data:`MAX_EXP_NESTING` 3          every declared expression: ``exp(exp(exp(x)))`` is the deepest tower
:data:`MAX_NODES`       200,000    nodes of any expression a stage is given (distinct subtrees)
:data:`EXPAND_NODES`    20,000     estimated nodes of an expansion done to tidy (larger: the tidy-up is skipped)
:data:`PRINT_NODES`     20,000     nodes of an equation printed as text or LaTeX
======================  =========  ==========================================================================

>>> import sympy as sp
>>> x, y = sp.symbols("x y")
>>> expansion_estimate((x + y + 1)**3)
(10, 70)
>>> max_exponent(sp.exp(10**30*sp.log(x)))
1e+30
>>> exp_nesting(sp.exp(sp.exp(x)) + sp.cosh(x))
2
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import sympy as sp

from .errors import ExpressionTooLarge

__all__ = ["MAX_EXPONENT", "MAX_EXP_NESTING", "MAX_NODES", "EXPAND_NODES", "PRINT_NODES", "expansion_estimate",
           "max_exponent", "exp_nesting", "node_count", "abbreviate", "check", "check_declared", "fits"]

MAX_EXPONENT = 1000
MAX_EXP_NESTING = 3
MAX_NODES = 200_000
EXPAND_NODES = 20_000
PRINT_NODES = 20_000

_CAP = 10**15  # estimates are capped here: beyond any budget, and cheap to compute with
_EXPONENTIAL = (sp.exp, sp.sinh, sp.cosh)


def _postorder(e: sp.Basic) -> list:
    """The distinct nodes of ``e``, children before parents (iterative: no recursion limit)."""
    seen, out, stack = set(), [], [(e, False)]
    while stack:
        node, done = stack.pop()
        if done:
            out.append(node)
            continue
        if node in seen:
            continue
        seen.add(node)
        stack.append((node, True))
        stack.extend((a, False) for a in node.args if a not in seen)
    return out


def node_count(e: sp.Basic, cap: int = _CAP) -> int:
    """Nodes of ``e``'s expression tree, each distinct subtree once; stops counting above ``cap``."""
    seen, stack = set(), [e]
    while stack:
        node = stack.pop()
        if node in seen:
            continue
        seen.add(node)
        if len(seen) > cap:
            return cap + 1
        stack.extend(node.args)
    return len(seen)


def _numeric_exponent(node) -> float | None:
    if not (node.is_Pow and node.exp.is_Number):
        return None
    try:
        return abs(float(node.exp))
    except OverflowError:
        return math.inf


def expansion_estimate(e: sp.Basic) -> tuple[int, int]:
    """Upper estimate ``(terms, nodes)`` of ``sympy.expand(e)``: the number of top-level terms and of nodes,
    each capped at 10¹⁵. Exact for sums of products of sums; for powers of sums an upper bound."""
    est: dict = {}
    for node in _postorder(e):
        if not node.args:
            est[node] = (1, 1)
            continue
        parts = [est[a] for a in node.args]
        if node.is_Add:
            r = (sum(k for k, _ in parts), sum(s for _, s in parts))
        elif node.is_Mul:
            k = 1
            per = 1.0
            for ka, sa in parts:
                k = min(_CAP, k * ka)
                per += sa / ka
            r = (k, per * k)
        elif node.is_Pow:
            r = _power_estimate(node, est)
        elif isinstance(node, sp.exp):
            k, s = parts[0]
            r = (1, s + k + 1)  # exp(a + b) → exp(a)*exp(b)
        else:  # functions (expand leaves sin(a + b) alone) and everything else: arguments expanded in place
            r = (1, 1 + sum(s for _, s in parts))
        est[node] = (min(_CAP, int(r[0])), min(_CAP, int(r[1])))
    return est[e]


def _power_estimate(node, est) -> tuple[int, float]:
    (kb, sb), (_, se) = est[node.base], est[node.exp]
    p = _numeric_exponent(node)
    if p is None:  # x**(a + b) → x**a*x**b
        return 1, sb + se + 1
    n, frac = int(p) if p < _CAP else _CAP, p < _CAP and p % 1 != 0
    if kb == 1 or n < 1:
        return 1, 2 * sb + 2
    if node.exp.is_negative:  # 1/(expanded positive power)
        k, s = _multinomial(n, kb, sb)
        return 1, s + 2
    k, s = _multinomial(n, kb, sb)
    if frac:  # (a + b)**(n + f) → expand((a + b)**n)*(a + b)**f, distributed over the terms
        s += k * (sb + 2)
    return k, s


def _multinomial(n: int, kb: int, sb: int) -> tuple[int, float]:
    """Terms and nodes of ``(t1 + … + t_kb)**n`` multiplied out."""
    if n >= 10_000 or kb >= 10_000:
        k = _CAP
    else:
        k = min(_CAP, math.comb(n + kb - 1, kb - 1))
    per = 2 * (sb / kb) * min(n, kb) + 1
    return k, min(float(_CAP), k * per)


def max_exponent(e: sp.Basic) -> float:
    """The largest magnitude of a constant exponent in ``e`` (0 when there is none)."""
    out = 0.0
    for node in _postorder(e):
        p = _numeric_exponent(node)
        if p is not None and p > out:
            out = p
    return out


def exp_nesting(e: sp.Basic) -> int:
    """Depth of the deepest tower of exponentials (``exp``, ``sinh``, ``cosh``) in ``e``."""
    depth: dict = {}
    for node in _postorder(e):
        inner = max((depth[a] for a in node.args), default=0)
        depth[node] = inner + 1 if isinstance(node, _EXPONENTIAL) else inner
    return depth[e]


def abbreviate(e, width: int = 80) -> str:
    """``e`` as text of at most ``width`` characters (``…`` marks a cut); a huge tree is not printed whole."""
    if not isinstance(e, sp.Basic):
        try:
            e = sp.sympify(e, strict=True)  # numbers and sympy objects only: a string is never parsed here
        except (sp.SympifyError, TypeError, ValueError):
            return repr(e)[:width]
    n = node_count(e, cap=2000)
    if n > 2000:
        head = sp.sstr(e.func) + "(" + ", ".join(abbreviate(a, width) for a in e.args[:2])
        text = head + (", …" if len(e.args) > 2 else "") + ")"
    else:
        try:
            text = sp.sstr(e)
        except ValueError:  # an integer of more digits than Python converts to text
            text = f"<{type(e).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= width else text[:width - 1] + "…"


def _raise(what: str, stage: str, e, problem: str):
    short = abbreviate(e)
    raise ExpressionTooLarge(f"{what} {short!s} {problem} (stage: {stage}); simplify the expression, "
                             "split it, or declare the expanded quantity as a parameter",
                             stage=stage, expression=short)


def check(e, *, stage: str, what: str = "the expression", max_nodes: int = MAX_NODES,
          max_expanded: int | None = None) -> None:
    """Raise :class:`~lagrange.errors.ExpressionTooLarge` when ``e`` has more than ``max_nodes`` nodes or,
    with ``max_expanded``, would expand to more than ``max_expanded`` nodes. ``stage`` and ``what`` name the
    stage and the expression in the message."""
    if not isinstance(e, sp.Basic):
        return
    n = node_count(e, cap=max_nodes)
    if n > max_nodes:
        _raise(what, stage, e, f"has more than {max_nodes:,} nodes")
    if max_expanded is not None:
        _, s = expansion_estimate(e)
        if s > max_expanded:
            _raise(what, stage, e, f"would expand to about {s:.2g} nodes (limit {max_expanded:,})")


def check_declared(e, *, what: str, stage: str = "declaration") -> None:
    """The budget of a declared expression (T, V, P, a force, a constraint): at most :data:`MAX_NODES`
    nodes, :data:`MAX_EXPONENT` as a constant exponent, :data:`MAX_EXP_NESTING` nested exponentials and
    constants within [1e-300, 1e300].
    Raises :class:`~lagrange.errors.ExpressionTooLarge` naming ``what``. (How far it would multiply out is
    not limited here: the derivation never expands an expression beyond :data:`EXPAND_NODES`, it skips the
    tidy-up instead; the spec parser limits terms for its own inputs.)"""
    if not isinstance(e, sp.Basic):
        return
    check(e, stage=stage, what=what)
    p = max_exponent(e)
    if p > MAX_EXPONENT:
        _raise(what, stage, e, f"has the exponent {p:.3g}, beyond the limit {MAX_EXPONENT}")
    for r in e.atoms(sp.Rational, sp.Float):
        if r != 0 and not 1e-300 <= abs(r) <= 1e300:
            _raise(what, stage, e, f"has the constant {sp.Float(r, 3)}, outside the floating-point range "
                   "[1e-300, 1e300] in which the generated code computes")
    d = exp_nesting(e)
    if d > MAX_EXP_NESTING:
        _raise(what, stage, e, f"nests exponentials {d} deep (limit {MAX_EXP_NESTING}); its values overflow "
               "any floating-point range")


def fits(e, limit: int = EXPAND_NODES) -> bool:
    """True when ``sympy.expand(e)`` is estimated at no more than ``limit`` nodes (a tidy-up may expand it)."""
    return not isinstance(e, sp.Basic) or expansion_estimate(e)[1] <= limit


def check_all(items: Iterable[tuple[str, sp.Basic]], *, stage: str) -> None:
    """:func:`check_declared` for each ``(what, expression)``."""
    for what, e in items:
        check_declared(e, what=what, stage=stage)
