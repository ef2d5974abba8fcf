r"""The numeric functions integration needs besides the right-hand side, generated here on request.

:class:`~lagrange.codegen.numeric.NumericModel` builds each of them lazily (its methods ``jacobian``,
``power``, ``sliding``, ``switched``, ``hamiltonian``), so :mod:`lagrange.integrate` reaches everything through the
compiled model and never generates code itself (the rule stated in :mod:`lagrange.integrate`).

* :func:`jacobian_function` — ``∂[q̇, q̈]/∂y`` of ``y' = [q̇, M⁻¹f]`` for the implicit methods,

  .. math:: \frac{\partial \ddot q}{\partial y_k} = M^{-1}\Big(\frac{\partial f}{\partial y_k}
            - \frac{\partial M}{\partial y_k}\,\ddot q\Big)

  from symbolic derivatives of M and f (one CSE'd lambdify), never finite differences;
* :func:`power_function` — ``dh/dt``, the power of everything not in L (the work integrand);
* :func:`sliding_functions` — the sliding velocities of rough constraints (Wells 12.5);
* :func:`switched_pieces` — the frozen-σ model, switching functions ``u_k`` and their gradients for the friction
  driver (:mod:`lagrange.integrate.switching`);
* :func:`baumgarte_rhs` — ``c − 2α g − β² φ`` for Baumgarte stabilization.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import sympy as sp

from ..conventions import t
from ..derive.equations import Equations
from ..errors import InputError
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from .cse import numeric_arguments, rename_map

__all__ = ["jacobian_function", "power_function", "sliding_functions", "switched_pieces", "SwitchedPieces",
           "baumgarte_rhs"]


def jacobian_function(model) -> Callable:
    """``jac(t, y) -> ndarray (2n, 2n)`` for the model's bound parameters."""
    eqs = model.equations
    n = eqs.n
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    M = eqs.mass_matrix.xreplace(ren)
    f = eqs.forcing.xreplace(ren)

    # d sign(u)/du = 2 δ(u): zero inside every segment the friction driver integrates (σ frozen there)
    def no_delta(expr):
        return expr.replace(sp.DiracDelta, lambda *args: sp.S.Zero)

    dM = [no_delta(M.diff(y)) for y in ys]
    df = no_delta(f.jacobian(ys))
    fn = (_quadrature_parts(tt, ys, ps, M, f, df, dM) if eqs.has_quadrature
          else _lambdify((tt, ys, ps), (M, f, df, dM), modules="numpy", cse=True))
    params = list(model.params)

    def jac(t_, y):
        Mv, fv, dfv, dMv = fn(t_, list(y), params)
        Mv = np.array(Mv, dtype=float)
        acc = np.linalg.solve(Mv, np.array(fv, dtype=float).ravel())
        R = np.array(dfv, dtype=float).reshape(n, 2 * n)
        for k in range(2 * n):
            R[:, k] -= np.array(dMv[k], dtype=float) @ acc
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:, :] = np.linalg.solve(Mv, R)
        return J

    return jac


def _quadrature_parts(tt, ys, ps, M, f, df, dM) -> Callable:
    """``(M, f, df, dM)`` as :func:`jacobian_function` takes them from lambdify, for equations holding integrals
    (differentiated under the integral sign, computed by :func:`lagrange.codegen.quadrature.python_function`)."""
    from .quadrature import python_function

    n = M.shape[0]
    flat = list(M) + list(f) + list(df) + [e for m in dM for e in m]
    fn = python_function((tt, ys, ps), flat)

    def parts(t_, y, p):
        v = np.array(fn(t_, y, p))
        k = n * n
        dm = v[k + n + 2 * n * n:].reshape(2 * n, n, n)
        return v[:k].reshape(n, n), v[k:k + n], v[k + n:k + n + 2 * n * n].reshape(n, 2 * n), list(dm)

    return parts


def _rate_function(eqs: Equations) -> Callable:
    """``(t, y, p, λ) ↦ dh/dt`` of ``eqs`` (plain floats; one CSE'd lambdify; its integrals by quadrature)."""
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    args = (tt, ys, ps, list(eqs.multipliers))
    if eqs.has_quadrature:
        from .quadrature import python_function

        fn = python_function(args, [eqs.jacobi_rate.xreplace(ren)])
        return lambda *a: fn(*a)[0]
    return _lambdify(args, eqs.jacobi_rate.xreplace(ren), modules="math", cse=True)


def power_function(model) -> Callable:
    """``power(t, y_list, lam_list)``: dh/dt, the power of everything not in L (incl. moving constraints), with
    the model's parameters (time-varying inputs at their values at (t, y))."""
    eqs = model.equations
    f = _rate_function(eqs)
    p = list(model.params)
    if model.schedule is not None:  # the inputs' power at their values now
        return lambda t_, y, lam=(): f(t_, y, model.parameters_at(t_, y), list(lam) + [0.0] * (eqs.m - len(lam)))
    return lambda t_, y, lam=(): f(t_, y, p, list(lam) + [0.0] * (eqs.m - len(lam)))


def sliding_functions(model) -> Callable:
    """``v(t, y, p) -> list``: the sliding velocity of each rough constraint."""
    eqs = model.equations
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)
    fn = _lambdify((tt, ys, ps), [v.xreplace(ren) for _, v in eqs.sliding_velocities], modules="math")
    return lambda t_, y, p: fn(t_, list(y), list(p))


@record(frozen=True)
class SwitchedPieces:
    """The numeric pieces of a run with frozen friction switches: ``model`` has the σ's among its parameters
    (after the ``nparam`` user parameters; σ = 1 bound, the inputs' constants after them), ``u(t, y, p)`` the
    switching functions, ``grad(t, y, p)`` their gradients ``[∂u/∂q, ∂u/∂q̇, ∂u/∂t]`` and ``power(t, y, p, λ)``
    the work integrand (time-varying inputs at their values at (t, y))."""

    model: object
    u: Callable
    grad: Callable
    power: Callable
    n_switches: int
    nparam: int


def switched_pieces(model, switches: list) -> SwitchedPieces:
    """The pieces of :class:`SwitchedPieces` for ``model`` and its ``switches``
    (:func:`~lagrange.codegen.switches.switching_functions`).

    Raises
    ------
    InputError
        A switch contains a time-varying input (locating its sign changes would need the input's rate).
    """
    from .switches import switched_equations

    eqs0 = model.equations
    eqs, sigmas = switched_equations(eqs0, switches)
    if model.schedule is not None:
        varying = {u for u, kind in zip(model.schedule.inputs, model.schedule.kinds) if kind != "constant"}
        inside = sorted({str(u) for u in varying for w in switches if u in w.free_symbols})
        if inside:
            raise InputError(f"the dry-friction switch sign() of {', '.join(map(str, switches))} contains the "
                             f"time-varying input(s) {', '.join(inside)}: locating its sign changes needs the "
                             "input's rate; use friction='regularize' or a constant input")
    base = dict(zip(eqs0.numeric_parameters, model.params))  # parameters and input constants
    backend = model.backend if model.backend != "reference" else "python"
    switched = type(model).build(eqs, {**base, **{s: 1.0 for s in sigmas}}, backend=backend)
    switched = switched.with_schedule(model.schedule) if model.schedule is not None else switched
    ren = rename_map(eqs)
    tt, ys, ps = numeric_arguments(eqs)  # switched eqs carry the σ's among their parameters
    u = _lambdify((tt, ys, ps), [w.xreplace(ren) for w in switches], modules="math")
    grad = _lambdify((tt, ys, ps), [[sp.diff(w, s).xreplace(ren) for s in (*eqs.q, *eqs.qd, t)]
                                      for w in switches], modules="math")
    rate = _rate_function(eqs)
    schedule = switched.schedule
    if schedule is None:
        power = rate
    else:
        k0, k = eqs.input_offset, len(eqs.inputs)

        def power(t_, y, p, lam):
            p = list(p)
            p[k0:k0 + k] = schedule(t_, y)
            return rate(t_, y, p, lam)

    return SwitchedPieces(switched, u, grad, power, len(switches), len(eqs0.parameters))


def baumgarte_rhs(eqs: Equations, alpha: float, beta: float) -> list:
    """``c_k − 2α g_k − β² φ_k`` (φ term only for holonomic constraints), in plain symbols: the right-hand side
    of ``A q̈ = c`` with Baumgarte stabilization (Baumgarte 1972; :mod:`lagrange.integrate.constrained`)."""
    qd = sp.Matrix(eqs.qd)
    out = []
    for k in range(eqs.m):
        g = (eqs.constraint_matrix[k, :] * qd)[0, 0] + eqs.constraint_bias[k]
        e = eqs.constraint_rhs[k] - 2 * sp.Float(alpha) * g
        if eqs.constraint_positions[k] is not None:
            e -= sp.Float(beta) ** 2 * eqs.constraint_positions[k]
        out.append(e)
    return out
