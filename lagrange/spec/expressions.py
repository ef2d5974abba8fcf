"""A safe parser for the expressions of text (TOML) specs: data, never code.

``sympy.sympify`` and ``parse_expr`` call ``eval``; a shared spec file must not be able to run anything.
This parser walks Python's AST and accepts only

* numbers (int and decimal literals, converted exactly: ``0.1`` → ``1/10``),
* names from an explicit namespace (coordinates, ``<coordinate>_dot``, declared parameters, ``t``,
  ``pi``, ``E``),
* ``+ - * / **`` and unary ``+ -``,
* calls of whitelisted functions (``sin``, ``cos``, ``sqrt``, ``exp``, ``Abs`` …) with positional
  arguments.

Everything else — attribute access, subscripts, keywords, lambdas, comprehensions, strings, dunder
names — is rejected, and so are expressions longer than :data:`MAX_LENGTH` characters, nested deeper
than :data:`MAX_DEPTH`, or raising to a power larger than :data:`MAX_EXPONENT` in magnitude.
"""

from __future__ import annotations

import ast
from collections.abc import Mapping

import sympy as sp

from ..errors import SpecError

__all__ = ["parse_expression", "FUNCTIONS", "MAX_LENGTH", "MAX_DEPTH", "MAX_EXPONENT"]

MAX_LENGTH = 5000
MAX_DEPTH = 60
MAX_NODES = 2000
MAX_EXPONENT = 100

FUNCTIONS = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec, "csc": sp.csc,
    "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "atan2": sp.atan2,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh,
    "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt, "Abs": sp.Abs, "abs": sp.Abs, "sign": sp.sign,
}
CONSTANTS = {"pi": sp.pi, "E": sp.E}

_BINOPS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
           ast.Div: lambda a, b: a / b, ast.Pow: None}


def parse_expression(text: str, names: Mapping[str, sp.Basic], *, where: str = "expression") -> sp.Expr:
    """Parse ``text`` into a sympy expression using only ``names`` and the whitelist.

    Raises :class:`SpecError` naming ``where`` and what was rejected.
    """
    if not isinstance(text, (str, int, float)) or isinstance(text, bool):
        raise SpecError(f"{where}: expected an expression string or a number, got {type(text).__name__}")
    text = str(text)
    if len(text) > MAX_LENGTH:
        raise SpecError(f"{where}: expression longer than {MAX_LENGTH} characters")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        raise SpecError(f"{where}: cannot parse {text!r}: {getattr(exc, 'msg', exc)}") from None
    count = sum(1 for _ in ast.walk(tree))
    if count > MAX_NODES:
        raise SpecError(f"{where}: expression has more than {MAX_NODES} parts")
    return _Builder(names, where).build(tree.body, 0)


class _Builder:
    def __init__(self, names, where):
        self.names = dict(names)
        self.where = where

    def fail(self, what):
        raise SpecError(f"{self.where}: {what} is not allowed in a spec expression")

    def build(self, node, depth):
        if depth > MAX_DEPTH:
            raise SpecError(f"{self.where}: expression nested deeper than {MAX_DEPTH} levels")
        d = depth + 1
        if isinstance(node, ast.Constant):
            v = node.value
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                self.fail(f"the literal {v!r}")
            if isinstance(v, int):
                if abs(v) > 10**30:
                    raise SpecError(f"{self.where}: integer literal too large")
                return sp.Integer(v)
            return sp.Rational(repr(v))
        if isinstance(node, ast.Name):
            if node.id.startswith("_"):
                self.fail(f"the name {node.id!r}")
            if node.id in self.names:
                return self.names[node.id]
            if node.id in CONSTANTS:
                return CONSTANTS[node.id]
            known = ", ".join(sorted(self.names))
            raise SpecError(f"{self.where}: unknown name {node.id!r} (known: {known}; declare parameters first)")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self.build(node.operand, d)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            a = self.build(node.left, d)
            b = self.build(node.right, d)
            if isinstance(node.op, ast.Pow):
                if b.is_number and (not b.is_finite or abs(complex(b.evalf())) > MAX_EXPONENT):
                    raise SpecError(f"{self.where}: exponent {b} exceeds the limit {MAX_EXPONENT}")
                return a**b
            if isinstance(node.op, ast.Div) and b == 0:
                raise SpecError(f"{self.where}: division by zero")
            return _BINOPS[type(node.op)](a, b)
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name):
                self.fail("calling anything but a plain function name")
            name = node.func.id
            if name not in FUNCTIONS:
                raise SpecError(
                    f"{self.where}: function {name!r} is not allowed (allowed: {', '.join(sorted(FUNCTIONS))})"
                )
            if node.keywords:
                self.fail("a keyword argument")
            args = [self.build(a, d) for a in node.args]
            try:
                return FUNCTIONS[name](*args)
            except TypeError as exc:
                raise SpecError(f"{self.where}: bad call of {name}: {exc}") from None
        if isinstance(node, ast.Attribute):
            self.fail("attribute access")
        if isinstance(node, ast.Subscript):
            self.fail("subscripting")
        self.fail(type(node).__name__)
