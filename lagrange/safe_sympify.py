"""``sympify`` that never evaluates a string.

``sympy.sympify`` of a string is ``eval``: ``sympify("__import__('os').system(...)")`` runs the command. Every
place where lagrange turns a user's value into a sympy object goes through :func:`sympify` instead: a string
is read by the spec parser (:func:`lagrange.spec.expressions.parse_expression`, a whitelist AST walker that
evaluates nothing) as an expression of numbers only (``"2*pi"``, ``"1/3"``), and anything else goes through
``sympy.sympify(..., strict=True)``, which converts numbers, sympy objects and objects with ``_sympy_``
without ever parsing text. Expressions with names are built with sympy (:func:`lagrange.coordinates`,
:func:`lagrange.parameters`) or written in a TOML spec, whose parser knows the names.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from .errors import SpecError

__all__ = ["sympify"]


def sympify(value, *args, where: str = "value", **kwargs):
    """``sympy.sympify(value)`` for anything but text; a string (also inside a list, tuple, set or dict) is
    read as an expression of numbers by the spec parser, never evaluated.

    Raises
    ------
    SpecError
        (a :class:`ValueError`) when a string is not an expression of numbers; the message names ``where``.
    sympy.SympifyError
        when ``value`` is neither a number, a sympy object, a container of them nor a string.

    >>> sympify("2*pi") == 2 * sp.pi
    True
    >>> try:
    ...     sympify("__import__('os')")
    ... except SpecError as exc:
    ...     print("never evaluated" in str(exc))
    True
    """
    if isinstance(value, (str, bytes)):
        return _number(value.decode() if isinstance(value, bytes) else value, where)
    if isinstance(value, (list, tuple, set, frozenset)):
        if any(isinstance(v, (str, bytes, list, tuple, set, frozenset, Mapping)) for v in value):
            return sp.sympify(type(value)(sympify(v, where=where) for v in value), *args, **kwargs)
    elif isinstance(value, Mapping):
        value = {sympify(k, where=where): sympify(v, where=where) for k, v in value.items()}
    try:
        return sp.sympify(value, *args, strict=True, **kwargs)
    except sp.SympifyError:
        if isinstance(value, (list, tuple, set, frozenset, Mapping)) or value is None or hasattr(value, "shape"):
            return sp.sympify(value, *args, **kwargs)  # containers and arrays of numbers: no text is parsed
        raise


def _number(text: str, where: str) -> sp.Expr:
    from .spec.expressions import parse_expression

    try:
        return parse_expression(text, {}, where=where)
    except SpecError as exc:
        raise SpecError(f"{exc}; strings are read as numbers only, never evaluated: build expressions with "
                        "lagrange.coordinates and lagrange.parameters (or write a TOML spec)") from None
