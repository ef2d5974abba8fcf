"""The names of the integration methods of :func:`~lagrange.integrate.run.simulate`, without importing them.

A light module (no numpy, scipy or sympy) so the command line can list and check methods before loading
anything: ``tests/test_methods_table.py`` checks these tuples against
:data:`~lagrange.integrate.scipy_ivp.SCIPY_METHODS` and :data:`~lagrange.integrate.fixed.GEOMETRIC`.
"""

from __future__ import annotations

__all__ = ["SCIPY", "ADAPTIVE", "FIXED_STEP", "ALL_METHODS", "canonical_method"]

#: scipy's solve_ivp methods (the implicit ones get the generated Jacobian)
SCIPY = ("DOP853", "RK45", "RK23", "LSODA", "Radau", "BDF")
#: methods that choose their own steps from rtol/atol (``auto`` picks one of them)
ADAPTIVE = (*SCIPY, "taylor", "auto")
#: fixed-step geometric methods: they take ``step=h`` and no tolerances
FIXED_STEP = ("midpoint", "gl4", "gl6", "verlet", "dg")
ALL_METHODS = (*ADAPTIVE, *FIXED_STEP)
_BY_LOWER = {m.lower(): m for m in ALL_METHODS}


def canonical_method(name: str) -> str | None:
    """The method's name as :func:`simulate` spells it (case-insensitive: ``dop853`` → ``DOP853``,
    ``Taylor`` → ``taylor``), or None for an unknown name.

    >>> canonical_method("dop853"), canonical_method("GL4"), canonical_method("rk4")
    ('DOP853', 'gl4', None)
    """
    if not isinstance(name, str):
        return None
    return _BY_LOWER.get(name.strip().lower())
