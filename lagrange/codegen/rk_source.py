r"""Source of a model's numba module when the compiled integrator loops may run it (unconstrained systems).

The numba backend writes one module per model (:mod:`lagrange.codegen.numba_backend`); for an
unconstrained system it holds

``rhs_into(t, y, p, out) -> ok``
    the straight-line right-hand side ``[q̇, q̈]`` written into ``out`` (flavour ``"numba_status"`` of
    :func:`~lagrange.codegen.source.rhs_source`): False when the mass matrix is not positive definite;
``rhs(t, y, p)``
    the backend's ``rhs``: a new array, ``ZeroDivisionError`` on a singular mass matrix;
``power(t, y, p)``
    dh/dt, the power of everything not in L (non-conservative systems only);
``field(t, z, p, out) -> ok``
    the integrated field: ``z = y`` for conservative systems, ``z = [y, work]`` with ``work' = dh/dt``
    otherwise (the power-balance integral of :mod:`lagrange.results.trajectory`).

``field`` is compiled eagerly with the signature :data:`FIELD_SIGNATURE`, so it can be passed as a numba
first-class function to the DOP853/RK45 loops of :mod:`lagrange.integrate._rk_loops`, which are compiled
once per machine, not once per model. The model's expressions are compiled once, in ``rhs_into``, which
both ``rhs`` and ``field`` call. Exceptions do not cross first-class function calls, and catching them
(``try``) would make every call about twice as slow, so ``rhs_into`` reports a singular mass matrix by
its return value and is compiled with ``error_model='numpy'``: like a square root of a negative number
(nan), a division by an exact zero elsewhere in the model gives inf or nan rather than an exception,
which the loop reports as ``NON_FINITE`` and scipy's loop as a failed step.
"""

from __future__ import annotations

import sympy as sp

from ..derive.equations import Equations
from .cse import FusedExpressions, rename_map
from .source import print_expr, rhs_source

__all__ = ["field_module_source", "FIELD_SIGNATURE"]

#: numba signature of ``field`` (must equal ``lagrange.integrate._rk_loops.FIELD``)
FIELD_SIGNATURE = "boolean(float64, float64[::1], float64[::1], float64[::1])"
_NUMPY_ERRORS = "cache=True, error_model='numpy'"


def _power_source(eqs: Equations, n_params: int, rule=None) -> str:
    """``power(t, y, p)``: dh/dt (CSE'd), for the work integral of non-conservative systems."""
    ren = rename_map(eqs)
    rate = [sp.sympify(eqs.jacobi_rate).xreplace(ren)]
    body = [f"y{i} = y[{i}]" for i in range(2 * eqs.n)] + [f"p{k} = p[{k}]" for k in range(n_params)]
    if eqs.has_quadrature:  # its integrals by the rule of rhs_into (lagrange.codegen.quadrature)
        from .quadrature import DEFAULT_RULE, quadrature_lines, split_integrals

        rate, groups = split_integrals(rate)
        body += quadrature_lines(groups, rule or DEFAULT_RULE, "numba", print_expr)
    repl, (red,) = sp.cse(rate, symbols=sp.numbered_symbols("w", real=True), optimizations="basic")
    body += [f"{s} = {print_expr(e)}" for s, e in repl]
    body.append(f"return float({print_expr(red)})")
    return (f"@numba.njit({_NUMPY_ERRORS})\ndef power(t, y, p):\n"
            + "\n".join("    " + line for line in body) + "\n")


def field_module_source(eqs: Equations, fused: FusedExpressions, n_params: int, rule=None) -> str:
    """Module body for an unconstrained system: ``rhs_into``, ``rhs``, ``power`` (if not conservative) and
    ``field``. All but ``rhs`` carry their decorators; the backend decorates ``rhs``
    (:func:`lagrange.codegen.numba_backend.decorate`). ``n_params`` includes the rough-constraint signs, as
    in :func:`rhs_source`; ``rule``: the quadrature rule of remaining integrals (:mod:`lagrange.codegen.quadrature`)."""
    into = f"@numba.njit({_NUMPY_ERRORS})\n" + rhs_source(fused, n_params=n_params, flavour="numba_status",
                                                          name="rhs_into", rule=rule)
    return field_module_around(into, eqs, n_params, rule)


def field_module_around(into: str, eqs: Equations, n_params: int, rule=None) -> str:
    """The module of :func:`field_module_source` around ``into``, the decorated source of a status-returning
    ``rhs_into(t, y, p, out)`` (from the expanded equations, or from the structural assembly of
    :mod:`lagrange.codegen.structural_source`): ``rhs``, ``power`` (if not conservative) and ``field``."""
    n2 = 2 * eqs.n
    parts = [into,
             f"def rhs(t, y, p):\n    out = np.empty({n2})\n    if not rhs_into(t, y, p, out):\n"
             "        raise ZeroDivisionError('mass matrix is not positive definite')\n    return out\n"]
    if eqs.is_conservative:
        body = "    return rhs_into(t, z, p, out)\n"
    else:
        parts.append(_power_source(eqs, n_params, rule))
        body = (f"    if not rhs_into(t, z, p, out):\n        return False\n    out[{n2}] = power(t, z, p)\n"
                "    return True\n")
    parts.append(f"@numba.njit({FIELD_SIGNATURE!r}, {_NUMPY_ERRORS})\ndef field(t, z, p, out):\n" + body)
    return "\n\n".join(parts)
