r"""Source of the Lagrangian pieces the geometric integrators need: M, b, L, ∂L/∂q and the second derivatives.

The fixed-step geometric integrators (:mod:`lagrange.integrate.fixed`) work in canonical variables
``z = (q, p)``. With ``T = ½ q̇ᵀM(t,q)q̇ + b(t,q)ᵀq̇ + T₀(t,q)`` and ``L = T − V`` they need

.. math:: \dot q = M^{-1}(p - b), \qquad H = p\cdot\dot q - L, \qquad
          \nabla H = (-L_q,\ \dot q), \qquad
          \nabla^2 H = \begin{pmatrix} -L_{qq} + L_{q\dot q}W & -L_{q\dot q}M^{-1} \\ -W & M^{-1} \end{pmatrix},
          \quad W = M^{-1}L_{q\dot q}^{\mathsf T}

(``W = −∂q̇/∂q``, from differentiating ``M q̇ = p − b``; all evaluated at ``q̇(t, q, p)``). So H, its
gradient and its Hessian — the Newton matrix of the implicit steps — follow from the *generated* pieces
M, b, L, ``L_q``, ``L_qq`` and ``L_{q q̇}`` and one Cholesky factorization of M per evaluation; M⁻¹ is never
formed symbolically (it explodes beyond two or three degrees of freedom).

The generated module has three functions (plain Python; :func:`compiled_source` adds the numba decorators,
each function compiled eagerly for its signature below so the compiled loops of
:mod:`lagrange.integrate._geometric_loops` take them as first-class functions)::

    mass(t, q, p, M, b) -> True                 # writes M (full, symmetric) and b
    lagrangian(t, q, v, p, Lq) -> L             # writes ∂L/∂q, returns L      (v = q̇)
    second(t, q, v, p, Lqq, Lqv) -> True        # writes ∂²L/∂q∂q and ∂²L/∂q_i∂q̇_j

``p`` is the parameter vector in the order of ``eqs.numeric_parameters`` (values are not baked in).
"""

from __future__ import annotations

import sympy as sp

from ..derive.equations import Equations
from ..errors import LagrangeError
from .cse import _cse, rename_map
from .source import print_expr

__all__ = ["hamiltonian_source", "compiled_source", "check_hamiltonian", "MASS_SIGNATURE", "LAGRANGIAN_SIGNATURE",
           "SECOND_SIGNATURE"]

#: numba signatures of the generated functions (must equal those in ``lagrange.integrate._geometric_loops``)
MASS_SIGNATURE = "boolean(float64, float64[::1], float64[::1], float64[:, ::1], float64[::1])"
LAGRANGIAN_SIGNATURE = "float64(float64, float64[::1], float64[::1], float64[::1], float64[::1])"
SECOND_SIGNATURE = "boolean(float64, float64[::1], float64[::1], float64[::1], float64[:, ::1], float64[:, ::1])"
_SIGNATURES = {"mass": MASS_SIGNATURE, "lagrangian": LAGRANGIAN_SIGNATURE, "second": SECOND_SIGNATURE}


def check_hamiltonian(eqs: Equations) -> None:
    """Raise :class:`LagrangeError` unless ``eqs`` has the structure the geometric integrators preserve:
    no constraints, no forces outside V, and a mass matrix free of velocities."""
    if eqs.m:
        raise LagrangeError("the geometric integrators need an unconstrained system (eliminate the constraints)")
    if any(sp.sympify(Q) != 0 for Q in eqs.nonconservative):
        raise LagrangeError("the geometric integrators need a conservative system: forces, P or rayleigh present; "
                            "use a scipy method")
    if eqs.has_quadrature:
        raise LagrangeError("the geometric integrators need T and V in closed form: this system holds an integral "
                            "evaluated by quadrature (lagrange.codegen.quadrature); use a scipy method such as DOP853")
    qd = set(eqs.qd)
    if any(sp.sympify(e).free_symbols & qd for e in sp.Matrix(eqs.mass_matrix)):
        raise LagrangeError("the geometric integrators need T quadratic in the velocities (the mass matrix "
                            "depends on velocities here)")


def _pieces(eqs: Equations) -> dict:
    """M, b, L, L_q, L_qq, L_qq̇ of ``eqs`` (plain symbols of the derivation)."""
    q, qd = list(eqs.q), list(eqs.qd)
    T = sp.sympify(eqs.kinetic)
    L = T - sp.sympify(eqs.potential)
    zero = {v: 0 for v in qd}
    Lq = [sp.diff(L, x) for x in q]
    return {
        "M": sp.Matrix(eqs.mass_matrix),
        "b": [sp.diff(T, v).xreplace(zero) for v in qd],
        "L": L,
        "Lq": Lq,
        "Lqq": {(i, j): sp.diff(Lq[i], q[j]) for i in range(len(q)) for j in range(i, len(q))},  # symmetric
        "Lqv": [[sp.diff(Lq[i], v) for v in qd] for i in range(len(q))],
    }


def _function(name: str, arguments: str, reads: list[str], targets: list[tuple[str, object]], result: str) -> str:
    """One straight-line function: unpack ``reads``, CSE the target expressions, write them, return."""
    exprs = [e for _, e in targets]
    repl, red = _cse(exprs) if exprs else ([], [])
    body = list(reads) + [f"{s} = {print_expr(e)}" for s, e in repl]
    body += [f"{target} = {print_expr(e)}" for (target, _), e in zip(targets, red)]
    body.append(f"return {result}")
    return f"def {name}({arguments}):\n" + "".join(f"    {line}\n" for line in body)


def hamiltonian_source(eqs: Equations, n_params: int) -> str:
    """Plain-Python module text of ``mass``, ``lagrangian`` and ``second`` for ``eqs`` (module docstring)."""
    check_hamiltonian(eqs)
    n = eqs.n
    ren = rename_map(eqs)
    pieces = _pieces(eqs)

    def r(e):
        return sp.sympify(e).xreplace(ren)

    read_q = [f"y{i} = q[{i}]" for i in range(n)]
    read_v = [f"y{n + i} = v[{i}]" for i in range(n)]
    read_p = [f"p{k} = p[{k}]" for k in range(n_params)]
    M = pieces["M"]
    mass_targets = [(f"M[{i}, {j}]" if i == j else f"M[{i}, {j}] = M[{j}, {i}]", r(M[i, j]))
                    for i in range(n) for j in range(i, n)]
    mass_targets += [(f"b[{i}]", r(pieces["b"][i])) for i in range(n)]
    lag_targets = [(f"Lq[{i}]", r(pieces["Lq"][i])) for i in range(n)] + [("L", r(pieces["L"]))]
    second_targets = [(f"Lqq[{i}, {j}]" if i == j else f"Lqq[{i}, {j}] = Lqq[{j}, {i}]", r(e))
                      for (i, j), e in pieces["Lqq"].items()]
    second_targets += [(f"Lqv[{i}, {j}]", r(pieces["Lqv"][i][j])) for i in range(n) for j in range(n)]
    parts = [
        _function("mass", "t, q, p, M, b", read_q + read_p, mass_targets, "True"),
        _function("lagrangian", "t, q, v, p, Lq", read_q + read_v + read_p, lag_targets, "float(L)"),
        _function("second", "t, q, v, p, Lqq, Lqv", read_q + read_v + read_p, second_targets, "True"),
    ]
    return "import math\n\n\n" + "\n\n".join(parts)


def compiled_source(source: str) -> str:
    """The numba module of :func:`hamiltonian_source`'s text: each function compiled eagerly for its
    signature, with ``error_model='numpy'`` (a singular value gives inf or nan, which the loop reports)."""
    from .numba_backend import decorate

    return "import numba\n" + decorate(source, _SIGNATURES, "cache=True, error_model='numpy'")
