r"""Integrals in a declaration (distributed drag or friction over a rod or plate, Wells §6.4–6.8).

Wells writes the power function or the generalized forces of a distributed resistance as an integral over the
body, e.g. a plate in a viscous film (Ex. 6.8), :math:`P = -\tfrac{\alpha}{2}\int\!\!\int v^2\,dA`. A
``sympy.Integral`` is accepted in T, V, P, the Rayleigh function and the forces and evaluated **in closed form
at declaration** (bounded in time: :data:`SECONDS` per attempt). Generated code has no quadrature, so an
integral sympy cannot evaluate within that budget (dry friction over a rod, Prob. 6.25, whose Piecewise/asinh
closed form takes sympy about 25 s; dry friction over a plate) is refused there with a
:class:`~lagrange.errors.DeclarationError` naming it — the same for derive, simulate and the CLI, which all
build the :class:`~lagrange.System` first. Give its closed form, or approximate the body by point contacts
(Wells Prob. 6.14 does this for the ring of Prob. 6.15).
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from ..errors import SymbolicTimeoutError
from ..safe_sympify import sympify as _sympify
from ..simplification import run_bounded

__all__ = ["evaluate_integrals", "SECONDS"]

SECONDS = 3.0
"""Wall-time limit of one attempt to evaluate one integral (seconds)."""


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


def evaluate_integrals(expr, what: str, problems: list):
    """``expr`` with every ``Integral`` replaced by its closed form.

    An integral sympy cannot evaluate within :data:`SECONDS` (per attempt) is left in place and a problem
    naming it and ``what`` is appended to ``problems`` (the caller raises one DeclarationError for all)."""
    expr = _sympify(expr)
    if not expr.has(sp.Integral):
        return expr

    def one(integral):
        if integral.function.has(sp.Integral):  # an inner integral already failed (and was reported)
            return integral
        value = _closed_form(integral)
        if value is None:
            problems.append(
                f"{what} contains the integral {integral}, which sympy cannot evaluate in closed form (and "
                "generated code has no quadrature); give its closed form, or approximate the body by point "
                "contacts (Wells Prob. 6.14)")
            return integral
        return value

    return expr.replace(lambda e: isinstance(e, sp.Integral), one)
