r"""Integrals that remain in the equations, evaluated in generated code by Gauss–Legendre quadrature.

An integral sympy cannot evaluate in closed form (dry friction over a rod or a plate, Wells Ex. 6.4, 6.5,
Prob. 6.24, 6.25; :mod:`lagrange.model.integrals`) stays an ``Integral`` through the derivation: ``∂P/∂q̇`` is
taken under the integral sign. Code generation replaces each one by a placeholder before the CSE
(:func:`split_integrals`) and computes it before the CSE'd lines (:func:`quadrature_lines`) as a sum over fixed
nodes — no call into scipy from the right-hand side.

**The rule.** Each integration variable's interval :math:`[a, b]` (the limits may depend on the outer
variables, on q, t and parameters) is cut into :attr:`Rule.panels` equal panels, each with an
:attr:`Rule.order`-point Gauss–Legendre rule (``numpy.polynomial.legendre.leggauss``); a multiple integral is
the tensor product, innermost variable first (sympy's order of limits). Integrals over the same limits are
evaluated in one pass over the nodes, their integrands CSE'd together (``∂P/∂ẋ``, ``∂P/∂ẏ``, ``∂P/∂θ̇`` share
the speed). The python backend evaluates the integrands on numpy arrays of all nodes at once; the numba backend
runs nested loops.

**Kinks.** Dry friction is not analytic where an element is at rest: ``|v|`` has a kink there and its
derivative ``v/|v|`` (the friction direction) a jump. Along one integration variable u, |v| of a rigid body's
element is the square root of a quadratic A u² + B u + C, smallest at u = −B/(2A), where the line of elements
passes closest to the instantaneous centre (through it, for a kink). Each variable's interval is therefore split
at the vertex of every square root of a quadratic in it, and at the root of every ``Abs`` or ``sign`` of a linear
function of it, whenever those points depend on the outer variables only (:func:`_breakpoints`); the rule is
applied on each segment. A rod (one variable, a quadratic under the root) then integrates to round-off wherever its
instantaneous centre is; over a plate the inner variable is split, and the outer one still meets the direction of
the centre, where the inner integral is not smooth (as a ring meets its centre in its one angle variable): there
the composite rule converges algebraically in the panels.

**Accuracy.** For an integrand analytic on the segments the error falls geometrically with the order (an
``order``-point rule is exact for polynomials of degree 2·order − 1). Measured on a uniform disc sliding and
spinning (``benchmarks/results/quadrature.md``, written by ``benchmarks/quadrature.py``, against the closed forms
of Farkas et al. 2003): with :data:`DEFAULT_RULE` (8 panels × 8 points per variable) the friction force and torque
are within 1e-4 relative (6e-5) while the instantaneous centre is inside the disc and within 1e-8 outside it
(3e-6 and 2e-14 with 8 panels × 16 points, ``Rule(16, 8)``, at four times the cost); a right-hand side with three
integrals over the disc costs about 0.4 ms in the python backend and 55 µs in numba. Choose a finer
:class:`Rule` for tighter runs (``System.compile(..., quadrature=Rule(16, 8))``,
:func:`lagrange.codegen.numeric.compile_equations`); ``simulate`` uses the default. Auxiliary functions
(diagnostics, the generated Jacobian of implicit methods, the power of the python backend) use
:data:`DEFAULT_RULE`.

Backends that need an analytic, closed right-hand side refuse equations with integrals
(:attr:`lagrange.derive.equations.Equations.has_quadrature`): the Taylor tape and heyoka
(:class:`~lagrange.codegen.tape.TapeError`), so ``method="auto"`` treats such systems as non-analytic.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter

from ..errors import OptionError
from ..records import record

__all__ = ["Rule", "DEFAULT_RULE", "QuadratureGroup", "split_integrals", "quadrature_lines", "has_integrals"]

#: the largest Gauss–Legendre order and number of panels accepted (numpy's ``leggauss`` is accurate far beyond
#: this order; a larger tensor product in two or three variables would cost seconds per right-hand side)
MAX_ORDER = 64
MAX_PANELS = 64


@record(frozen=True, slots=True)
class Rule:
    """A composite Gauss–Legendre rule: ``panels`` equal panels per integration variable, ``order`` nodes in
    each. Raises :class:`~lagrange.errors.OptionError` for a value out of range."""

    order: int = 8
    panels: int = 8

    def __post_init__(self):
        for name, value, top in (("order", self.order, MAX_ORDER), ("panels", self.panels, MAX_PANELS)):
            if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= top:
                raise OptionError(f"quadrature {name} must be an integer from 1 to {top}, got {value!r}")

    @property
    def size(self) -> int:
        """Nodes per integration variable."""
        return self.order * self.panels

    def nodes(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The nodes and weights on ``[-1, 1]``, each of length :attr:`size` (weights sum to 2)."""
        x, w = np.polynomial.legendre.leggauss(self.order)
        h = 2.0 / self.panels
        xs = np.concatenate([-1.0 + h * (k + 0.5) + h / 2 * x for k in range(self.panels)])
        ws = np.concatenate([h / 2 * w for _ in range(self.panels)])
        return tuple(float(v) for v in xs), tuple(float(v) for v in ws)


#: the rule generated code uses unless another is given (see the module docstring for its measured accuracy)
DEFAULT_RULE = Rule(order=8, panels=8)


@record(frozen=True, slots=True)
class QuadratureGroup:
    """Integrals over the same limits: ``limits`` ((variable, lower, upper), innermost first, the variables
    renamed ``qv{g}_{d}``), ``integrands`` and the placeholder ``symbols`` standing for their values."""

    limits: tuple
    integrands: tuple
    symbols: tuple
    breakpoints: tuple = ()  # per dimension (innermost first): expressions of the outer variables where the
    #                          integrands may kink (each variable's interval is split there, see _breakpoints)


def has_integrals(exprs) -> bool:
    return any(isinstance(e, sp.Basic) and e.has(sp.Integral) for e in exprs)


def split_integrals(exprs: list) -> tuple[list, tuple[QuadratureGroup, ...]]:
    """``exprs`` with each ``Integral`` replaced by a placeholder symbol ``qs{k}`` (equal integrals share one),
    and the groups that compute the placeholders (integrals with equal limits share a group)."""
    found: dict = {}
    groups: dict = {}

    def one(integral):
        if integral in found:
            return found[integral]
        if integral.function.has(sp.Integral):
            raise ValueError(f"an integral inside the integrand of {integral}: write it as one multiple integral")
        groups.setdefault(integral.limits, len(groups))
        sym = found[integral] = sp.Symbol(f"qs{len(found)}", real=True)
        return sym

    out = [sp.sympify(e).replace(lambda e: isinstance(e, sp.Integral), one) for e in exprs]
    members: dict = {}
    for integral, sym in found.items():
        members.setdefault(groups[integral.limits], []).append((integral, sym))
    result = []
    for limits, g in groups.items():
        names = {lim[0]: sp.Symbol(f"qv{g}_{d}", real=True) for d, lim in enumerate(limits)}
        renamed = tuple((names[v], sp.sympify(lo).xreplace(names), sp.sympify(hi).xreplace(names))
                        for v, lo, hi in limits)
        integrands = tuple(i.function.xreplace(names) for i, _ in members[g])
        inner = {lim[0] for lim in renamed}
        known = set().union(*(e.free_symbols for e in integrands)) - inner
        points = tuple(tuple(_breakpoints(integrands, v, known | {w for w, *_ in renamed[d + 1:]}))
                       for d, (v, *_) in enumerate(renamed))
        result.append(QuadratureGroup(renamed, integrands, tuple(s for _, s in members[g]), points))
    return out, tuple(result)


def _breakpoints(integrands: tuple, var, known: set) -> list:
    """Where the integrands may have a kink or a jump as functions of ``var``, as expressions of ``known``
    symbols only (the outer integration variables, the state, t and the parameters): the vertex −B/(2A) of
    every square root of a quadratic A var² + B var + C (its smallest value: |v| of a rigid body's element along
    a line is such a root, with a kink where the line passes through the instantaneous centre) and the root of
    every Abs or sign of a linear function of ``var``, each as ``(numerator, denominator)`` (generated code skips
    a point whose denominator is zero: a rod that does not turn). Other integrands get none."""
    found = []
    for e in integrands:
        for node in sp.preorder_traversal(e):
            if isinstance(node, sp.Pow) and node.exp.is_Rational and node.exp.q == 2:
                arg, degree = node.base, 2
            elif isinstance(node, (sp.Abs, sp.sign)):
                arg, degree = node.args[0], 1
            else:
                continue
            if not arg.has(var):
                continue
            try:
                poly = sp.Poly(arg, var)
            except sp.PolynomialError:
                continue
            if poly.degree() != degree or not all(c.free_symbols <= known for c in poly.all_coeffs()):
                continue
            c = poly.all_coeffs()
            point = (-c[1], 2 * c[0]) if degree == 2 else (-c[1], c[0])  # (numerator, denominator)
            if point not in found:
                found.append(point)
    return found


class _ArrayPrinter(NumPyPrinter):
    def _print_Float(self, expr):
        return repr(float(expr))


_ARRAY_PRINTER = _ArrayPrinter({"fully_qualified_modules": True})


class _ScalarPrinter(PythonCodePrinter):
    def _print_Float(self, expr):
        return repr(float(expr))


_SCALAR_PRINTER = _ScalarPrinter({"fully_qualified_modules": True, "standard": "python3"})


def quadrature_lines(groups: tuple[QuadratureGroup, ...], rule: Rule, flavour: str, scalar_print) -> list[str]:
    """Lines assigning each placeholder ``qs{k}`` its integral's value by ``rule``.

    ``flavour="python"``: numpy arrays over all nodes of a group (the source's namespace has ``numpy``), or
    loops when an integrand holds a function numpy does not apply elementwise; any other flavour: nested loops
    over scalars (numba; the namespace has ``np`` and ``math``). ``scalar_print`` prints a sympy expression for
    scalar code (the backend's printer)."""
    xi, wi = rule.nodes()
    lines = [f"qxi = {xi!r}", f"qwi = {wi!r}"] if groups else []
    for g, group in enumerate(groups):
        vector = _array_lines(g, group) if flavour == "python" else None
        lines += vector if vector is not None else _loop_lines(g, group, scalar_print)
    return lines


def _integrand_cse(g: int, integrands: tuple) -> tuple[list, list]:
    return sp.cse(list(integrands), symbols=sp.numbered_symbols(f"qc{g}_", real=True), optimizations="basic")


def _array_lines(g: int, group: QuadratureGroup) -> list[str] | None:
    """All nodes of the group at once: flattened tensor-product arrays, outermost variable first; a variable with
    breakpoints gets one copy of the rule per segment between them. None when an integrand holds a function numpy
    does not apply elementwise (printed from ``math`` or ``scipy``): the caller loops instead."""
    pr = _ARRAY_PRINTER.doprint
    repl, red = _integrand_cse(g, group.integrands)
    printed = [pr(e) for _, e in repl] + [pr(e) for e in red]
    if any("math." in text or "scipy." in text for text in printed):
        return None
    lines = [f"qw{g} = numpy.ones(1)"]
    outer: list[str] = []
    for d in reversed(range(len(group.limits))):  # outermost first
        var, lo, hi = group.limits[d]
        v = str(var)
        points = group.breakpoints[d] if group.breakpoints else ()
        n, k = f"len(qw{g})", len(points) + 1
        lines.append(f"qlo = numpy.broadcast_to({pr(lo)}, ({n},))")
        lines.append(f"qL = numpy.broadcast_to({pr(hi)}, ({n},)) - qlo")
        cuts = [f"numpy.zeros({n})"]
        if points:  # (a zero denominator or interval gives nan or inf: cut at an end instead)
            ratios = ", ".join(f"numpy.broadcast_to((({pr(a)})/({pr(b)}) - qlo)/qL, ({n},))" for a, b in points)
            lines.append("with numpy.errstate(divide='ignore', invalid='ignore'):")
            lines.append(f"    qt = numpy.sort(numpy.clip(numpy.nan_to_num(numpy.stack([{ratios}])), 0.0, 1.0), "
                         "axis=0)")
            cuts.append("qt")
        cuts.append(f"numpy.ones({n})")
        lines.append(f"qa = qlo + qL*numpy.vstack([{', '.join(cuts)}])")
        lines.append("qh = 0.5*(qa[1:] - qa[:-1]).T[:, :, None]")
        lines += [f"{name} = numpy.repeat({name}, {k}*len(qxi))" for name in outer]
        lines.append(f"{v} = (0.5*(qa[1:] + qa[:-1]).T[:, :, None] + qh*qxi).reshape(-1)")
        lines.append(f"qw{g} = (qw{g}[:, None, None]*qh*qwi).reshape(-1)")
        outer.append(v)
    lines += [f"{s} = {text}" for (s, _), text in zip(repl, printed)]
    lines += [f"{s} = float(numpy.dot(qw{g}, numpy.broadcast_to({text}, qw{g}.shape)))"
              for s, text in zip(group.symbols, printed[len(repl):])]
    return lines


def _loop_lines(g: int, group: QuadratureGroup, scalar_print) -> list[str]:
    """Nested loops, outermost variable first; each integrand accumulated with the product of the weights. A
    variable with breakpoints loops over the segments between them (sorted in a small array), the rule on each."""
    lines = [f"{s} = 0.0" for s in group.symbols]
    indent = ""
    weight = "1.0"
    for d in reversed(range(len(group.limits))):
        var, lo, hi = group.limits[d]
        points = group.breakpoints[d] if group.breakpoints else ()
        tag = f"{g}_{d}"
        lines.append(f"{indent}qlo{tag} = {scalar_print(lo)}")
        lines.append(f"{indent}qL{tag} = ({scalar_print(hi)}) - qlo{tag}")
        lines.append(f"{indent}qt{tag} = np.empty({len(points) + 2})")
        lines.append(f"{indent}qt{tag}[0] = 0.0")
        lines.append(f"{indent}qt{tag}[{len(points) + 1}] = 1.0")
        for j, (a, b) in enumerate(points, start=1):
            lines.append(f"{indent}qd = {scalar_print(b)}")
            lines.append(f"{indent}qr = (({scalar_print(a)})/qd - qlo{tag})/qL{tag} if qd != 0.0 and qL{tag} != 0.0 "
                         "else 0.0")
            lines.append(f"{indent}qt{tag}[{j}] = min(max(qr, 0.0), 1.0) if qr == qr else 0.0")
        if points:
            lines.append(f"{indent}qt{tag}.sort()")
        lines.append(f"{indent}for qj{tag} in range({len(points) + 1}):")
        indent += "    "
        lines.append(f"{indent}qh{tag} = 0.5*qL{tag}*(qt{tag}[qj{tag} + 1] - qt{tag}[qj{tag}])")
        lines.append(f"{indent}qm{tag} = qlo{tag} + 0.5*qL{tag}*(qt{tag}[qj{tag} + 1] + qt{tag}[qj{tag}])")
        lines.append(f"{indent}for qk{tag} in range(len(qxi)):")
        indent += "    "
        lines.append(f"{indent}{var} = qm{tag} + qh{tag}*qxi[qk{tag}]")
        lines.append(f"{indent}qw{tag} = {weight}*qh{tag}*qwi[qk{tag}]")
        weight = f"qw{tag}"
    repl, red = _integrand_cse(g, group.integrands)
    lines += [f"{indent}{s} = {scalar_print(e)}" for s, e in repl]
    lines += [f"{indent}{s} += {weight}*({scalar_print(e)})" for s, e in zip(group.symbols, red)]
    return lines


def python_function(args: tuple, exprs: list, rule: Rule = DEFAULT_RULE):
    """A plain-Python ``fn(*args) -> list of floats`` of scalar ``exprs`` whose integrals are computed by
    ``rule`` (what ``sympy.lambdify`` is to expressions without integrals). ``args``: symbols or sequences of
    symbols, as lambdify takes them; each call takes scalars (no broadcasting over arrays)."""
    rest, groups = split_integrals([sp.sympify(e) for e in exprs])
    head, names = [], []
    for k, a in enumerate(args):
        names.append(f"qa{k}")
        if isinstance(a, sp.Basic):
            head.append(f"{a} = qa{k}")
        elif len(a):
            head.append(f"{', '.join(str(s) for s in a)}, = qa{k}")
    body = head + quadrature_lines(groups, rule, "python", _SCALAR_PRINTER.doprint)
    body.append(f"return [{', '.join(f'float({_ARRAY_PRINTER.doprint(e)})' for e in rest)}]")
    source = f"def fn({', '.join(names)}):\n" + "\n".join("    " + line for line in body) + "\n"
    namespace: dict = {"numpy": np, "np": np, "math": math}
    exec(compile(source, "<lagrange quadrature function>", "exec"), namespace)  # noqa: S102 - generated here
    return namespace["fn"]
