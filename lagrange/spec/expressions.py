"""A safe parser for the expressions of text (TOML) specs: data, never code.

``sympy.sympify`` and ``parse_expr`` call ``eval``; a shared spec file must not be able to run anything.
This parser walks Python's AST (``ast.parse`` only builds a tree, it runs nothing) and accepts only

* ASCII text (look-alike Unicode letters such as ``ｘ`` or ``𝐱`` would silently be read as ``x`` by
  Python's identifier normalization, so they are rejected);
* numbers: int literals up to ``10**30`` and decimal literals, converted exactly from their text
  (``0.1`` → ``1/10``, ``1e-3`` → ``1/1000``);
* names from an explicit namespace (coordinates, ``<coordinate>_dot``, declared parameters, ``t``) and
  the constants ``pi`` and ``E``. sympy's special names (``I``, ``S``, ``N``, ``Q``, ``O``, ``oo``,
  ``beta``, ``gamma``, ``zeta`` …) mean nothing here unless declared;
* ``+ - * / **`` and unary ``+ -``;
* calls of whitelisted functions (:data:`FUNCTIONS`) with exactly their number of positional arguments.

Everything else — attribute access, subscripts, keywords, ``*args``, lambdas, comprehensions, strings,
f-strings, walrus, comparisons, dunder names — is rejected, and so are expressions longer than
:data:`MAX_LENGTH` characters, with more than :data:`MAX_NODES` parts, nested deeper than
:data:`MAX_DEPTH`, raising to a constant power larger than :data:`MAX_EXPONENT` in magnitude (also after
sympy combines ``(x**a)**b``), and constants outside the floating-point range (:data:`MAX_MAGNITUDE`),
non-real (``sqrt(-1)``) or undefined (``0**-1``, ``log(0)``, ``atan2(0, 0)``), and expressions that would
multiply out to more than :data:`MAX_TERMS` terms. Nesting counts function calls, powers, signs and
parentheses; a long sum or product is one level. Every rejection is a
:class:`~lagrange.errors.SpecError` naming the expression's place and what is wrong.

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> parse_expression("0.5*x**2 + sin(pi/6)", {"x": x})
x**2/2 + 1/2
"""

from __future__ import annotations

import ast
import decimal
import math
import unicodedata
from collections.abc import Mapping

import sympy as sp

from ..budget import MAX_EXP_NESTING, abbreviate, exp_nesting
from ..errors import SpecError

__all__ = ["parse_expression", "FUNCTIONS", "MAX_LENGTH", "MAX_DEPTH", "MAX_NODES", "MAX_EXPONENT",
           "MAX_MAGNITUDE", "MAX_TERMS", "MAX_EXP_NESTING"]

MAX_LENGTH = 5000
MAX_DEPTH = 30
MAX_NODES = 2000
MAX_EXPONENT = 100
MAX_TERMS = 500
#: constants must lie within [1/MAX_MAGNITUDE, MAX_MAGNITUDE] in magnitude (or be 0): floats overflow beyond
MAX_MAGNITUDE = sp.Integer(10) ** 300
_MAX_INT_LITERAL = 10**30

#: name → (sympy function, number of positional arguments)
FUNCTIONS = {
    "sin": (sp.sin, 1), "cos": (sp.cos, 1), "tan": (sp.tan, 1), "cot": (sp.cot, 1), "sec": (sp.sec, 1),
    "csc": (sp.csc, 1), "asin": (sp.asin, 1), "acos": (sp.acos, 1), "atan": (sp.atan, 1),
    "atan2": (sp.atan2, 2), "sinh": (sp.sinh, 1), "cosh": (sp.cosh, 1), "tanh": (sp.tanh, 1),
    "exp": (sp.exp, 1), "log": (sp.log, 1), "sqrt": (sp.sqrt, 1), "Abs": (sp.Abs, 1), "abs": (sp.Abs, 1),
    "sign": (sp.sign, 1),
}
CONSTANTS = {"pi": sp.pi, "E": sp.E}
_UNDEFINED = (sp.zoo, sp.nan, sp.oo, -sp.oo)

_NODE_WORDS = {"BoolOp": "'and'/'or'", "Compare": "a comparison", "IfExp": "'if ... else'", "Lambda": "lambda",
               "ListComp": "a list comprehension", "SetComp": "a set comprehension", "DictComp": "a dict "
               "comprehension", "GeneratorExp": "a generator expression", "JoinedStr": "an f-string",
               "NamedExpr": "':=' assignment", "Starred": "'*' unpacking", "Await": "await", "Tuple": "a tuple",
               "List": "a list", "Set": "a set", "Dict": "a dict", "Slice": "a slice"}
_BINOPS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
           ast.Div: lambda a, b: a / b, ast.Pow: None}


def parse_expression(text: str | int | float, names: Mapping[str, sp.Basic], *,
                     where: str = "expression", max_terms: int = MAX_TERMS) -> sp.Expr:
    """Parse ``text`` into a sympy expression using only ``names`` and the whitelist.

    Parameters
    ----------
    text : str, int or float
        The expression (a TOML string or number).
    names : mapping of str to sympy objects
        The only names the expression may use (besides ``pi`` and ``E``).
    where : str
        The expression's place in the spec, used in error messages.
    max_terms : int
        Limit on the number of terms the expression would have when multiplied out (``sympy.expand``,
        estimated without expanding): ``(x + 1)**100*(y - 1)**100`` is short but expands to 10⁴ terms,
        which would stall the derivation. Particle positions get a lower limit, since T squares them.

    Raises
    ------
    SpecError
        Naming ``where`` and what was rejected.
    """
    if not isinstance(text, (str, int, float)) or isinstance(text, bool):
        raise SpecError(f"{where}: expected an expression string or a number, got {type(text).__name__}")
    if isinstance(text, float):
        if text != text or text in (float("inf"), float("-inf")):
            raise SpecError(f"{where}: {text} is not a finite number")
        text = repr(text)  # converted exactly below
    text = str(text)
    if len(text) > MAX_LENGTH:
        raise SpecError(f"{where}: expression longer than {MAX_LENGTH} characters")
    for i, ch in enumerate(text):
        if not ch.isascii():
            raise SpecError(f"{where}: non-ASCII character {ch!r} (U+{ord(ch):04X} "
                            f"{unicodedata.name(ch, 'unnamed')}) at position {i}: spec expressions are ASCII "
                            "only, since look-alike letters would be read as other names")
    source = text.strip()
    try:
        tree = ast.parse(source, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        raise SpecError(f"{where}: cannot parse {text!r}: {getattr(exc, 'msg', exc)}") from None
    count = sum(1 for node in ast.walk(tree) if not isinstance(node, (ast.expr_context, ast.operator, ast.unaryop)))
    if count > MAX_NODES:
        raise SpecError(f"{where}: expression has more than {MAX_NODES} parts")
    expr = _Builder(names, where, source).build(tree.body, 0)
    if expr.has(*_UNDEFINED, sp.I):
        raise SpecError(f"{where}: {text!r} evaluates to {expr}, which is not a finite real expression")
    for number in expr.atoms(sp.Rational):  # coefficients folded into products and sums, e.g. 1e200*x*1e200
        if number != 0 and not 1 / MAX_MAGNITUDE <= abs(number) <= MAX_MAGNITUDE:
            raise SpecError(f"{where}: the coefficient {_short(number)} in {text!r} is outside the "
                            "floating-point range [1e-300, 1e300]")
    terms = _expanded_terms(expr, max_terms)
    if terms > max_terms:
        raise SpecError(f"{where}: {text!r} would expand to more than {max_terms} terms when multiplied out; "
                        "simplify it or split it")
    return expr


def _abbreviate(e: sp.Expr) -> str:
    return abbreviate(e, 60)


def _short(number: sp.Rational) -> str:
    """A rational in three significant digits (``str`` of a 10,000-digit integer raises in Python 3.11+)."""
    return str(number.evalf(3))


def _expanded_terms(e: sp.Basic, limit: int) -> int:
    """An upper estimate of the number of terms of ``sympy.expand(e)``, capped just above ``limit``."""
    if isinstance(e, sp.Add):
        return min(limit + 1, sum(_expanded_terms(a, limit) for a in e.args))
    if isinstance(e, sp.Mul):
        out = 1
        for a in e.args:
            out = min(limit + 1, out * _expanded_terms(a, limit))
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Number:  # integer, rational and float exponents alike:
        k = _expanded_terms(e.base, limit)  # (a + b)**(n + f) expands as (a + b)**n, times (a + b)**f
        n = int(abs(e.exp)) if abs(e.exp) <= MAX_EXPONENT else MAX_EXPONENT + 1
        if k > 1 and n >= 1:
            return min(limit + 1, math.comb(n + k - 1, k - 1))
    for a in e.args:  # functions and other powers: their arguments are expanded in place
        if _expanded_terms(a, limit) > limit:
            return limit + 1
    return 1


class _Builder:
    def __init__(self, names: Mapping[str, sp.Basic], where: str, source: str):
        self.names = dict(names)
        self.where = where
        self.source = source

    def fail(self, what: str):
        raise SpecError(f"{self.where}: {what} is not allowed in a spec expression")

    def error(self, what: str):
        raise SpecError(f"{self.where}: {what}")

    def build(self, node: ast.AST, depth: int) -> sp.Expr:
        if depth > MAX_DEPTH:
            self.error(f"expression nested deeper than {MAX_DEPTH} levels")
        d = depth + 1
        if isinstance(node, ast.Constant):
            return self.constant(node)
        if isinstance(node, ast.Name):
            return self.name(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self.build(node.operand, d)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
            return self.checked(self.power(self.build(node.left, d), self.build(node.right, d)))
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            return self.chain(node, depth)
        if isinstance(node, ast.Call):
            return self.call(node, d)
        if isinstance(node, ast.Attribute):
            self.fail("attribute access")
        if isinstance(node, ast.Subscript):
            self.fail("subscripting")
        if isinstance(node, ast.BinOp):
            self.fail(f"the operator {type(node.op).__name__}")
        if isinstance(node, ast.UnaryOp):
            self.fail(f"the unary operator {type(node.op).__name__}")
        kind = type(node).__name__
        self.fail(_NODE_WORDS.get(kind, kind))

    def chain(self, node: ast.BinOp, depth: int) -> sp.Expr:
        """``a + b - c * d / e …``: Python nests a long sum as a left spine; walk it iteratively, so a long
        sum counts as one level of nesting and never exhausts the recursion limit."""
        spine = []
        while isinstance(node, ast.BinOp) and type(node.op) in _BINOPS and not isinstance(node.op, ast.Pow):
            spine.append((node.op, node.right))
            node = node.left
        value = self.build(node, depth + 1)
        for op, right in reversed(spine):
            b = self.build(right, depth + 1)
            if isinstance(op, ast.Div) and b == 0:
                self.error("division by zero")
            value = self.checked(self.exponents(_BINOPS[type(op)](value, b)))
        return value

    def constant(self, node: ast.Constant) -> sp.Expr:
        v = node.value
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            self.fail(f"the literal {v!r}")
        if isinstance(v, int):
            if abs(v) > _MAX_INT_LITERAL:
                self.error(f"integer literal too large (limit {_MAX_INT_LITERAL:.0e}); use a decimal exponent")
            return sp.Integer(v)
        literal = (ast.get_source_segment(self.source, node) or repr(v)).replace("_", "")
        try:
            exact = decimal.Decimal(literal)
        except decimal.InvalidOperation:
            literal, exact = repr(v), decimal.Decimal(repr(v))
        # decided on the decimal exponent before any integer is built: 1e999999999 would take minutes
        if exact and not -301 <= exact.adjusted() <= 300:  # the exact bound is checked below
            self.error(f"the constant {literal} is outside the floating-point range [1e-300, 1e300]")
        return self.checked(sp.Rational(literal))  # exact, even where the float would overflow or underflow

    def name(self, ident: str) -> sp.Expr:
        if ident.startswith("_"):
            self.fail(f"the name {ident!r}")
        if ident in self.names:
            return self.names[ident]
        if ident in CONSTANTS:
            return CONSTANTS[ident]
        known = ", ".join(sorted(self.names)) or "none"
        self.error(f"unknown name {ident!r} (known: {known}, and the constants pi, E; declare parameters first)")

    def power(self, a: sp.Expr, b: sp.Expr) -> sp.Expr:
        if b.is_number:
            bv = self.real_value(b, "exponent")
            if abs(bv) > MAX_EXPONENT:
                self.error(f"exponent {b} exceeds the limit {MAX_EXPONENT}")
        if a == 0 and b.is_number and b.is_extended_nonpositive:
            self.error(f"0**{b} is undefined (division by zero)")
        return self.exponents(a**b)

    def exponents(self, result: sp.Expr) -> sp.Expr:
        """sympy folds ``(x**a)**b`` and ``x**a*x**b``, and rewrites ``exp(c*log(x))`` as ``x**c``: the
        combined exponent must obey the limit too."""
        for part in (result, *(result.args if isinstance(result, (sp.Mul, sp.Function)) else ())):
            if isinstance(part, sp.Pow) and part.exp.is_number and abs(self.real_value(part.exp, "exponent")) \
                    > MAX_EXPONENT:
                self.error(f"the combined exponent {part.exp} exceeds the limit {MAX_EXPONENT}")
        return result

    def call(self, node: ast.Call, d: int) -> sp.Expr:
        if not isinstance(node.func, ast.Name):
            self.fail("calling anything but a plain function name")
        name = node.func.id
        if name not in FUNCTIONS:
            self.error(f"function {name!r} is not allowed (allowed: {', '.join(sorted(FUNCTIONS))})")
        if node.keywords:
            self.fail("a keyword argument")
        fn, arity = FUNCTIONS[name]
        if len(node.args) != arity:
            self.error(f"{name} takes {arity} argument{'s' if arity > 1 else ''}, got {len(node.args)}")
        args = [self.build(a, d) for a in node.args]
        if fn in (sp.exp, sp.sinh, sp.cosh, sp.tanh):
            self.exp_argument(name, args[0])
        return self.checked(self.exponents(fn(*args)))

    def exp_argument(self, name: str, arg: sp.Expr) -> None:
        """Checked before sympy sees ``exp(arg)``: sympy rewrites ``exp(c*log(x))`` as ``x**c`` (and would
        compute ``2**(10**30)`` for ``exp(10**30*log(2))``), so the factor of a log obeys the exponent limit;
        and a tower of exponentials deeper than :data:`MAX_EXP_NESTING` overflows any number format."""
        for term in sp.Add.make_args(arg):
            factors = sp.Mul.make_args(term)
            if any(isinstance(f, sp.log) for f in factors):
                c = sp.Mul(*[f for f in factors if not isinstance(f, sp.log) and f.is_number])
                if abs(self.real_value(c, "factor of a log")) > MAX_EXPONENT:
                    self.error(f"{name}({_abbreviate(arg)}) raises to the power {_short(c) if c.is_Rational else c}, "
                               f"which exceeds the exponent limit {MAX_EXPONENT}")
        depth = exp_nesting(arg) + 1
        if depth > MAX_EXP_NESTING:
            self.error(f"{name}({_abbreviate(arg)}) nests exponential functions {depth} deep (limit "
                       f"{MAX_EXP_NESTING}): its values overflow any number format")

    def real_value(self, value: sp.Expr, what: str) -> float:
        """The float of a constant, or a SpecError when it is not a finite real number."""
        try:
            c = complex(sp.N(value, 17))
        except OverflowError:
            self.error(f"the {what} {value} is outside the floating-point range [1e-300, 1e300]")
        except (TypeError, ValueError, ZeroDivisionError):
            c = complex("nan")
        if c != c or (math.isfinite(abs(c)) and abs(c.imag) > 1e-12 * max(1.0, abs(c.real))):
            self.error(f"the {what} {value} is not a finite real number")
        if not math.isfinite(abs(c)):
            self.error(f"the {what} {value} is outside the floating-point range [1e-300, 1e300]")
        return c.real

    def checked(self, value: sp.Expr) -> sp.Expr:
        """Reject constants that are undefined, complex or outside the floating-point range."""
        if not value.is_number:
            return value
        if value.has(*_UNDEFINED) or value.has(sp.I):
            self.error(f"the constant {value} is not a finite real number (division by zero or a complex value)")
        if isinstance(value, sp.Rational):
            if abs(value) > MAX_MAGNITUDE or (value != 0 and abs(value) < 1 / MAX_MAGNITUDE):
                self.error(f"the constant {_short(value)} is outside the floating-point range "
                           "[1e-300, 1e300]")
            return value
        v = self.real_value(value, "constant")
        if abs(v) > 1e300 or (v != 0 and abs(v) < 1e-300):
            self.error(f"the constant {value} = {v:.3g} is outside the floating-point range [1e-300, 1e300]")
        return value
