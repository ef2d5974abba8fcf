"""``sympify`` that never evaluates a string, and ``lambdify`` that never prints a user's name as code.

``sympy.sympify`` of a string is ``eval``: ``sympify("__import__('os').system(...)")`` runs the command. Every
place where lagrange turns a user's value into a sympy object goes through :func:`sympify` instead: a string
is read by the spec parser (:func:`lagrange.spec.expressions.parse_expression`, a whitelist AST walker that
evaluates nothing) as an expression of numbers only (``"2*pi"``, ``"1/3"``), and anything else goes through
``sympy.sympify(..., strict=True)``, which converts numbers, sympy objects and objects with ``_sympy_``
without ever parsing text. Expressions with names are built with sympy (:func:`lagrange.coordinates`,
:func:`lagrange.parameters`) or written in a TOML spec, whose parser knows the names. :func:`matrix` and
:func:`expression` do the same for a matrix and for a single value.

``sympy.lambdify`` prints undefined functions and stray symbols by name into the code it runs;
:func:`lambdify` refuses them and renames arguments whose names are not plain, so every numeric evaluation of
a user's expression goes through it.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import sympy as sp

from .errors import ExpressionTypeError, SpecError

__all__ = ["sympify", "expression", "matrix", "lambdify"]


def sympify(value, *args, where: str = "value", **kwargs):
    """``sympy.sympify(value)`` for anything but text; a string (also inside a list, tuple, set or dict) is
    read as an expression of numbers by the spec parser, never evaluated.

    Raises
    ------
    SpecError
        (a :class:`ValueError`) when a string is not an expression of numbers; the message names ``where``.
    ExpressionTypeError
        (a :class:`TypeError`) when ``value`` is neither a number, a sympy object, a container of them nor a
        string; its text is never parsed.

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
        # element by element: sympy's own conversion of a container falls back to parsing ``str(item)``
        return type(value)(sympify(v, *args, where=where, **kwargs) for v in value)
    if isinstance(value, Mapping):
        return {sympify(k, where=where): sympify(v, *args, where=where, **kwargs) for k, v in value.items()}
    if getattr(getattr(value, "dtype", None), "kind", "") in ("U", "S", "O"):  # an array of text or objects
        return sp.Array(sympify(value.tolist(), *args, where=where, **kwargs))
    try:
        return sp.sympify(value, *args, strict=True, **kwargs)
    except sp.SympifyError:
        if value is None or isinstance(value, np.ndarray):
            return sp.sympify(value, *args, **kwargs)  # an array of numbers: no text is parsed
        raise ExpressionTypeError(f"{where}: {type(value).__name__} object is not a number or a sympy "
                                  "expression; build expressions with lagrange.coordinates and "
                                  "lagrange.parameters (its text is never parsed)") from None


def expression(value, where: str = "value") -> sp.Basic:
    """:func:`sympify` of a value that must be one number or expression: a list, a matrix, an array or any
    other container is refused with :class:`ExpressionTypeError` naming ``where``.

    >>> expression("1/2")
    1/2
    """
    out = sympify(value, where=where)
    if not isinstance(out, sp.Expr):
        from .errors import shown

        raise ExpressionTypeError(f"{where} = {shown(value)} is a {type(value).__name__}, not one number or "
                                  "expression")
    return out


def matrix(value, where: str = "matrix") -> sp.Matrix:
    """``sympy.Matrix(value)`` whose entries went through :func:`sympify` first (``sympy.Matrix`` of a nested
    list converts each entry with sympy's parsing ``sympify``: a string entry would be evaluated).

    >>> matrix([[1, "1/2"], [0, 1]])[0, 1]
    1/2
    """
    if isinstance(value, sp.MatrixBase):
        return sp.Matrix(value)
    if hasattr(value, "tolist") and not isinstance(value, sp.Basic):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        value = [list(sympify(row, where=where)) if isinstance(row, (list, tuple)) or hasattr(row, "tolist")
                 else sympify(row, where=where) for row in value]
    else:
        value = sympify(value, where=where)
    return sp.Matrix(value)


def _number(text: str, where: str) -> sp.Expr:
    from .spec.expressions import parse_expression

    try:
        return parse_expression(text, {}, where=where)
    except SpecError as exc:
        raise SpecError(f"{exc}; strings are read as numbers only, never evaluated: build expressions with "
                        "lagrange.coordinates and lagrange.parameters (or write a TOML spec)") from None


def _flat(args) -> list:
    if isinstance(args, (list, tuple)):
        return [s for a in args for s in _flat(a)]
    if isinstance(args, sp.MatrixBase):
        return list(args)
    return [args]


def lambdify(args, expr, modules=None, *, where: str = "an expression", **kwargs):
    """``sympy.lambdify(args, expr, modules, **kwargs)`` after making sure that no name from the user's
    expressions is printed into the generated code as code.

    ``lambdify`` prints an undefined function (``sympy.Function("f")``, also an ``implemented_function``) by
    its name and a symbol that is not an argument by its name, so a name such as
    ``__import__('os').system(...)`` would run as code. Both are refused up front (:class:`ExpressionTypeError`
    naming them and ``where``). An argument whose name is not a plain identifier, or would shadow a name of
    the generated code's namespace (``sin``, ``math``, a builtin), is replaced by a dummy first, so no
    argument name changes what the code means either.

    >>> x = sp.Symbol("x")
    >>> lambdify([x], x**2 + 1, "math")(2.0)
    5.0
    >>> try:
    ...     lambdify([x], sp.Function("f")(x), "math")
    ... except ExpressionTypeError as exc:
    ...     print(str(exc)[:47])
    an expression holds the undefined function(s) f
    """
    from sympy.core.function import AppliedUndef

    exprs = [e for e in _flat(expr if isinstance(expr, (list, tuple, sp.MatrixBase)) else [expr])
             if isinstance(e, sp.Basic)]
    undefined = sorted({type(f).__name__ for e in exprs for f in e.atoms(AppliedUndef)})
    if undefined:
        raise ExpressionTypeError(f"{where} holds the undefined function(s) {', '.join(undefined)}: lagrange cannot "
                                  "evaluate a function it has no definition of (and never prints its name as "
                                  "code); write it out as an expression of the variables, or, for an input, give a "
                                  "Python callable u(t)")
    given = set(_flat(args))
    loose = sorted({s.name for e in exprs for s in e.free_symbols if s not in given})
    if loose:
        raise ExpressionTypeError(f"{where} holds symbol(s) with no value: {', '.join(loose)}; substitute their "
                                  "values (or declare them as parameters) before evaluating it")
    renamed = {s: sp.Dummy() for s in given if not _plain(s)}
    if renamed:  # (lambdify also puts each argument's name in the code's namespace: renamed before it sees them)
        args, expr = _renamed(args, renamed), _renamed(expr, renamed)
    return sp.lambdify(args, expr, modules=modules, **kwargs)


def _renamed(obj, mapping: dict):
    """``obj`` (an expression, a matrix, or lists and tuples of them) with the symbols of ``mapping`` replaced."""
    if isinstance(obj, (list, tuple)):
        return type(obj)(_renamed(o, mapping) for o in obj)
    if isinstance(obj, (sp.Basic, sp.MatrixBase)):
        return obj.xreplace(mapping)
    return obj


def _plain(arg) -> bool:
    """True when ``arg`` is not a symbol, or its name is an identifier that means nothing else in the code
    lambdify generates (no keyword, builtin, module or function of the math, numpy or mpmath namespace)."""
    import builtins
    import keyword
    import math

    name = getattr(arg, "name", None)
    if not isinstance(arg, sp.Symbol) or name is None:
        return True
    return (name.isidentifier() and not keyword.iskeyword(name) and not name.startswith("_")
            and name not in ("math", "numpy", "np", "mpmath", "sympy")
            and not any(hasattr(space, name) for space in (builtins, math, np)))
