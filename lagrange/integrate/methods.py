"""The names of the integration methods of :func:`~lagrange.integrate.run.simulate`, without importing them.

A light view of the method registry (:mod:`lagrange.integrate.registry`, which imports no numpy, scipy or
sympy), so the command line can list and check methods before loading anything.
"""

from __future__ import annotations

from .registry import METHODS, find

__all__ = ["SCIPY", "ADAPTIVE", "FIXED_STEP", "ALL_METHODS", "canonical_method"]

#: scipy's solve_ivp methods (the implicit ones get the generated Jacobian)
SCIPY = tuple(m.name for m in METHODS if m.family.startswith("scipy"))
#: methods that choose their own steps from rtol/atol (``auto`` picks one of them)
ADAPTIVE = (*(m.name for m in METHODS if m.adaptive), "auto")
#: fixed-step geometric methods: they take ``step=h`` and no tolerances
FIXED_STEP = tuple(m.name for m in METHODS if m.step_required)
ALL_METHODS = (*ADAPTIVE, *FIXED_STEP)


def canonical_method(name: str) -> str | None:
    """The method's name as :func:`simulate` spells it (case-insensitive: ``dop853`` → ``DOP853``,
    ``Taylor`` → ``taylor``), or None for an unknown name.

    >>> canonical_method("dop853"), canonical_method("GL4"), canonical_method("rk4")
    ('DOP853', 'gl4', None)
    """
    if isinstance(name, str) and name.strip().lower() == "auto":
        return "auto"
    entry = find(name)
    return None if entry is None else entry.name
