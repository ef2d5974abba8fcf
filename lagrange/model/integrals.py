r"""Integrals in a declaration (distributed drag or friction over a rod or plate, Wells §6.4–6.8).

Wells writes the power function or the generalized forces of a distributed resistance as an integral over the
body, e.g. a plate in a viscous film (Ex. 6.8), :math:`P = -\tfrac{\alpha}{2}\int\!\!\int v^2\,dA`, or dry
friction over a plate (Ex. 6.5), :math:`P = -\int\!\!\int f\,|v|\,dA`. A ``sympy.Integral`` is accepted in T, V,
P, the Rayleigh function and the forces. Each one (except a :class:`Quadrature`, declared for quadrature) is
first evaluated **in closed form at declaration** (bounded in time: :data:`SECONDS` per attempt). An integral
sympy cannot evaluate within that budget is **kept** as an ``Integral``: the derivation differentiates under the
integral sign (``∂P/∂q̇`` is an integral of ``∂|v|/∂q̇``), the printed equations show it in Wells' form, and
generated code evaluates it by Gauss–Legendre quadrature over its limits (:mod:`lagrange.codegen.quadrature`,
which states the rule and its measured accuracy). An integral whose integrand is itself a kept integral is
written as one multiple integral.

What quadrature cannot take is refused here with a :class:`~lagrange.errors.DeclarationError` naming it: an
integral without both limits (indefinite), an infinite or non-real limit, a limit that depends on a velocity,
an integration variable that is not a plain symbol or has the name of a coordinate, a velocity or t, another
integral inside an integrand (other than the whole
integrand), and a ``Sum``, ``Product`` or unevaluated derivative of the integration variable inside the
integrand.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from ..errors import SymbolicTimeoutError
from ..safe_sympify import sympify as _sympify
from ..simplification import run_bounded

__all__ = ["Quadrature", "evaluate_integrals", "quadrature_problem", "SECONDS"]

SECONDS = 3.0
"""Wall-time limit of one attempt to evaluate one integral (seconds)."""


class Quadrature(sp.Integral):
    r"""A definite integral declared for numerical quadrature: :func:`evaluate_integrals` does not look for its
    closed form (which for dry friction over an area, :math:`\int\!\!\int f |v|\,dA`, sympy does not find
    and spends :data:`SECONDS` × 4 attempts looking for). Written and printed as ``sympy.Integral``; the
    derivation differentiates under its sign (the derivative is a plain ``Integral``) and generated code
    evaluates it by Gauss–Legendre quadrature (:mod:`lagrange.codegen.quadrature`).

    >>> import sympy as sp
    >>> from lagrange import Quadrature
    >>> r, v = sp.symbols("r v", real=True)
    >>> Quadrature(sp.sqrt(v**2 + r**2), (r, 0, 1)).diff(v)
    Integral(v/sqrt(r**2 + v**2), (r, 0, 1))
    """


def _closed_form(integral: sp.Integral):
    """The integral evaluated, or None. Coordinates and velocities are constants of the integration: they are
    replaced by real dummies so sympy treats them as symbols."""
    bound = set(integral.variables)
    atoms = [a for a in integral.atoms(AppliedUndef, sp.Derivative) if not a.free_symbols & bound]
    stand = {a: sp.Dummy(f"c{i}", real=True) for i, a in enumerate(sorted(atoms, key=sp.default_sort_key))}
    back = {d: a for a, d in stand.items()}
    try:
        value = run_bounded(lambda: integral.xreplace(stand).doit(), what=f"the integral {integral}",
                            seconds=SECONDS)
    except (SymbolicTimeoutError, RecursionError, NotImplementedError, ValueError, TypeError, AttributeError):
        return None
    if value.has(sp.Integral, sp.nan, sp.zoo) or value.free_symbols & bound:
        return None
    return value.xreplace(back)


def quadrature_problem(integral: sp.Integral) -> str | None:
    """Why generated code could not evaluate ``integral`` by quadrature over its limits (None when it can)."""
    for lim in integral.limits:
        if len(lim) != 3:
            return f"the variable {lim[0]} has no limits (an indefinite integral): give both limits"
        var, lo, hi = lim
        if isinstance(var, AppliedUndef) or not isinstance(var, sp.Symbol):
            return f"the integration variable {var} is not a plain symbol (integrate over a sympy.Symbol)"
        for end in (lo, hi):
            end = sp.sympify(end)
            if end.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or end.is_real is False:
                return f"the limit {end} of {var} is not finite and real (quadrature needs a bounded interval)"
            if end.atoms(sp.Derivative):
                return f"the limit {end} of {var} depends on a velocity (limits may depend on q, t and parameters)"
    if integral.function.has(sp.Integral):
        return ("its integrand holds another integral: write them as one multiple integral, "
                "Integral(f, (x, ..), (y, ..))")
    if integral.function.has(sp.Sum, sp.Product):
        return "its integrand holds a Sum or Product: write it in closed form"
    inner = [d for d in integral.function.atoms(sp.Derivative) if d.free_symbols & set(integral.variables)]
    if inner:
        return f"its integrand holds the unevaluated derivative {inner[0]}"
    return None


def evaluate_integrals(expr, what: str, problems: list, reserved=frozenset()):
    """``expr`` with every ``Integral`` replaced by its closed form where sympy finds one.

    An integral sympy cannot evaluate within :data:`SECONDS` (per attempt) is kept for quadrature in generated
    code when :func:`quadrature_problem` accepts it; otherwise a problem naming it and ``what`` is appended to
    ``problems`` (the caller raises one DeclarationError for all). ``reserved``: names an integration variable
    may not have (the coordinates, their velocities ``x_dot`` and ``t``: the derivation writes those as plain
    symbols of the same names, which the integral would capture)."""
    expr = _sympify(expr)
    if not expr.has(sp.Integral):
        return expr

    def one(integral):
        if isinstance(integral.function, sp.Integral):  # a kept inner integral: one multiple integral
            inner = integral.function
            kind = Quadrature if isinstance(inner, Quadrature) or isinstance(integral, Quadrature) else sp.Integral
            integral = kind(inner.function, *inner.limits, *integral.limits)
        value = None if isinstance(integral, Quadrature) else _closed_form(integral)
        if value is not None:
            return value
        taken = [v for v in integral.variables if getattr(v, "name", None) in reserved]
        why = (f"its integration variable {taken[0]} has the name of a coordinate, a velocity or t, which the "
               "derivation would confuse with it: rename the variable") if taken else quadrature_problem(integral)
        if why is not None:
            problems.append(f"{what} contains the integral {integral}, which sympy cannot evaluate in closed form "
                            f"and generated code cannot evaluate by quadrature: {why}")
        return integral

    return expr.replace(lambda e: isinstance(e, sp.Integral), one)
