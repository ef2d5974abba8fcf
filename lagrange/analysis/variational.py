r"""Hamilton's principle (Wells ch. 17): Euler–Lagrange equations of functionals, the action of a
trajectory, and a variational integrator built from the discrete action.

Calculus of variations: for ``I = ∫ F(x, y_1..y_k, y_1', y_1'', …) dx`` the stationarity conditions are the
Euler–Poisson equations

.. math:: \sum_{j\ge 0} (-1)^j \frac{d^j}{dx^j}\frac{\partial F}{\partial y^{(j)}} = 0 .

Variational integrator (Marsden & West 2001): with the midpoint discrete Lagrangian
``L_d(q_k, q_{k+1}) = h L((q_k + q_{k+1})/2, (q_{k+1} − q_k)/h, t_k + h/2)`` the discrete Euler–Lagrange
equations in position–momentum form are

.. math:: p_k = -D_1 L_d(q_k, q_{k+1}), \qquad p_{k+1} = D_2 L_d(q_k, q_{k+1}),

solved for ``q_{k+1}`` by Newton's method with the generated Jacobian ``−D_{12}L_d``. The map is
symplectic, conserves the momentum of every ignorable coordinate exactly (to the Newton tolerance) and
keeps the energy error bounded; it is second order. Conservative, unconstrained systems only.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import scipy.integrate
import sympy as sp

from ..codegen.numeric import bind_parameters
from ..conventions import t
from ..conventions import t as _t
from ..errors import IntegrationError, LagrangeError
from ..limits import bounded
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import simplify

__all__ = ["euler_lagrange", "action", "VariationalResult", "variational_integrate"]


@bounded("Euler–Lagrange equations")
def euler_lagrange(F, functions: Sequence, variable) -> list[sp.Eq]:
    """Euler–Poisson equations of ``∫ F dx`` for unknown functions ``functions`` (sympy functions of
    ``variable``), any order of derivatives."""
    out = []
    for y in functions:
        order = max([d.derivative_count for d in _sympify(F).atoms(sp.Derivative) if d.expr == y] + [0])
        e = sp.diff(F, y)
        for j in range(1, order + 1):
            e += (-1) ** j * sp.diff(sp.diff(F, sp.diff(y, (variable, j))), (variable, j))
        out.append(sp.Eq(simplify(e), 0))
    return out


def action(path, system=None, params: Mapping | None = None, *, t=None) -> float:
    r"""The action :math:`S = \int_{t_0}^{t_1} L(q, \dot q, t)\,dt`, ``L = T − V``, along a path.

    Parameters
    ----------
    path : one of
        - a :class:`~lagrange.results.trajectory.Trajectory` (``system``, ``params`` and ``t`` not needed):
          Simpson's rule on its output times;
        - a mapping ``{q: expression of t}`` (sympy, every coordinate): exact velocities, adaptive quadrature
          (``scipy.integrate.quad``) over ``t = (t0, t1)``;
        - a mapping ``{q: callable}`` or one callable ``path(t) -> q`` (shape (n,)): velocities by a
          fourth-order central difference (step ``1e-3 (t1 − t0)``), quadrature over ``t = (t0, t1)``;
        - an array sampled on the grid ``t`` (shape (n_times,)): shape (n_times, n) for q (velocities by
          ``numpy.gradient``, second order) or (n_times, 2n) for ``[q, q̇]``; Simpson's rule.
    system : :class:`~lagrange.System` — its ``T − V`` (P, Rayleigh and forces are not part of L)
    params : parameter values (keys: symbols or names)
    t : ``(t0, t1)`` or the sample times of an array path

    Raises
    ------
    LagrangeError
        A coordinate is missing from a mapping, the shapes do not match, ``system``/``t`` are missing, or
        the system has constraints (the action of the free L would ignore them).

    Examples
    --------
    >>> import lagrange as lg
    >>> x = lg.coordinates("x"); m = lg.parameters("m")
    >>> free = lg.System([x], T=m * x.diff(lg.t) ** 2 / 2)
    >>> round(action({x: 3 * lg.t}, free, {"m": 2}, t=(0, 1)), 12)  # m v² T / 2
    9.0
    """
    if hasattr(path, "diagnostics") and hasattr(path, "t"):
        d = path.diagnostics
        return float(scipy.integrate.simpson(d["T"] - d["V"], x=path.t))
    if system is None or t is None:
        raise LagrangeError("action of a path that is not a Trajectory needs the system and t")
    eqs = system.derived
    if eqs.m:
        raise LagrangeError("action of a constrained system: L = T − V alone ignores the constraints; "
                            "eliminate the superfluous coordinates first (lagrange.eliminate)")
    n = eqs.n
    pvals = dict(zip(eqs.parameters, bind_parameters(eqs, system.bindable(params))))
    Lf = _lambdify([list(eqs.q), list(eqs.qd), _t], (eqs.kinetic - eqs.potential).subs(pvals), "numpy")
    if isinstance(path, Mapping):
        missing = [str(c) for c in eqs.coordinates if c not in path]
        if missing:
            raise LagrangeError(f"the path must give every coordinate; missing {', '.join(missing)}")
        funcs = [path[c] for c in eqs.coordinates]
        if all(isinstance(f, sp.Basic) or isinstance(f, int | float) for f in funcs):
            qs = _lambdify(_t, [_sympify(f) for f in funcs], "numpy")
            vs = _lambdify(_t, [sp.diff(f, _t) for f in funcs], "numpy")
            return _quad(lambda s: Lf(qs(s), vs(s), s), t)
        path = _stack([f if callable(f) else (lambda s, c=float(f): c) for f in funcs])
    if callable(path):
        t0, t1 = map(float, t)
        h = 1e-3 * (t1 - t0)

        def q_of(s):
            return np.asarray(path(s), dtype=float).reshape(n)

        def v_of(s):  # fourth-order central difference
            return (8 * (q_of(s + h) - q_of(s - h)) - (q_of(s + 2 * h) - q_of(s - 2 * h))) / (12 * h)

        return _quad(lambda s: Lf(q_of(s), v_of(s), s), (t0, t1))
    Y = np.asarray(path, dtype=float)
    times = np.asarray(t, dtype=float)
    if Y.ndim != 2 or Y.shape[0] != times.shape[0] or Y.shape[1] not in (n, 2 * n):
        raise LagrangeError(f"a sampled path has shape (n_times, {n}) or (n_times, {2 * n}) matching t "
                            f"(n_times = {times.shape[0]}); got {Y.shape}")
    Q = Y[:, :n]
    V = Y[:, n:] if Y.shape[1] == 2 * n else np.gradient(Q, times, axis=0, edge_order=2)
    values = np.array([Lf(Q[i], V[i], times[i]) for i in range(len(times))], dtype=float)
    return float(scipy.integrate.simpson(values, x=times))


def _stack(funcs):
    return lambda s: np.array([f(s) for f in funcs], dtype=float)


def _quad(f, span) -> float:
    t0, t1 = map(float, span)
    value, _ = scipy.integrate.quad(lambda s: float(f(s)), t0, t1, epsabs=1e-13, epsrel=1e-12, limit=200)
    return float(value)


@record(frozen=True)
class VariationalResult:
    """Fixed-step results: times, positions and discrete momenta (steps+1, n), Newton iterations per step."""

    t: np.ndarray
    q: np.ndarray  # (steps+1, n)
    p: np.ndarray  # (steps+1, n) discrete momenta
    newton_iterations: np.ndarray


def _discrete_functions(system, params):
    eqs = system.derived
    if eqs.m or not eqs.is_conservative and (eqs.power_function != 0 or eqs.rayleigh != 0
                                             or any(f != 0 for f in eqs.applied)):
        raise LagrangeError("the variational integrator needs a conservative, unconstrained system")
    n = eqs.n
    h, tk = sp.symbols("h_ t_k", real=True)
    a = sp.symbols(f"a0:{n}", real=True)
    b = sp.symbols(f"b0:{n}", real=True)
    L = eqs.kinetic - eqs.potential
    sub = {eqs.q[i]: (a[i] + b[i]) / 2 for i in range(n)}
    sub.update({eqs.qd[i]: (b[i] - a[i]) / h for i in range(n)})
    sub[t] = tk + h / 2
    Ld = h * L.xreplace(sub)
    pvals = dict(zip(eqs.parameters, bind_parameters(eqs, params)))
    Ld = Ld.subs(pvals)
    D1 = [sp.diff(Ld, ai) for ai in a]
    D2 = [sp.diff(Ld, bi) for bi in b]
    J = sp.Matrix(D1).jacobian(b)
    args = (a, b, h, tk)
    return (_lambdify(args, D1, "numpy", cse=True), _lambdify(args, D2, "numpy", cse=True),
            _lambdify(args, J, "numpy", cse=True), n)


def variational_integrate(system, t_end: float, initial: Mapping, params: Mapping, *, h: float,
                          tol: float = 1e-12, max_newton: int = 20) -> VariationalResult:
    """Integrate with the midpoint variational integrator at fixed step ``h``.

    ``initial`` as for :meth:`System.simulate`; the initial discrete momentum is ``∂L/∂q̇`` at t = 0.
    Raises :class:`~lagrange.errors.IntegrationError` when Newton fails (time and state reported).
    """
    from ..integrate.run import initial_state

    eqs = system.derived
    D1, D2, J, n = _discrete_functions(system, params)
    y0 = initial_state(eqs.coordinates, initial)
    model = system.compile(params)
    # continuous momentum at t = 0
    L = eqs.kinetic - eqs.potential
    pfun = _lambdify([list(eqs.q), list(eqs.qd), t], [sp.diff(L, v).subs(dict(zip(eqs.parameters, model.params)))
                                                      for v in eqs.qd], "numpy")
    steps = int(round(t_end / h))
    qs = np.empty((steps + 1, n))
    ps = np.empty((steps + 1, n))
    its = np.zeros(steps, dtype=int)
    qs[0] = y0[:n]
    ps[0] = np.asarray(pfun(y0[:n], y0[n:], 0.0), dtype=float)
    for k in range(steps):
        tk = k * h
        qk, pk = qs[k], ps[k]
        qn = qk + h * np.asarray(model.fun(tk, np.concatenate([qk, _velocity(model, qk, pk, tk, pfun)])), float)[:n]
        for it in range(max_newton):  # noqa: B007 - the count is recorded below
            r = np.asarray(D1(qk, qn, h, tk), dtype=float) + pk  # p_k + D1 Ld = 0
            if np.max(np.abs(r)) <= tol * (1.0 + np.max(np.abs(pk))):
                break
            Jm = np.asarray(J(qk, qn, h, tk), dtype=float).reshape(n, n)
            dq = np.linalg.solve(Jm, r)
            qn = qn - dq
            if np.max(np.abs(dq)) <= 1e-15 * (1.0 + np.max(np.abs(qn))):  # at the round-off floor
                break
        else:
            raise IntegrationError(f"variational step did not converge at t={tk:.6g} (q={qk}); reduce h", t=tk)
        its[k] = it
        qs[k + 1] = qn
        ps[k + 1] = np.asarray(D2(qk, qn, h, tk), dtype=float)
    return VariationalResult(np.arange(steps + 1) * h, qs, ps, its)


def _velocity(model, q, p, tk, pfun):
    """q̇ from the momentum p (a Newton step on p(q̇) = p; exact for quadratic T) for the predictor."""
    n = len(q)
    v = np.zeros(n)
    p0 = np.asarray(pfun(q, v, tk), dtype=float)
    M, _ = model.mass_and_forcing(tk, np.concatenate([q, v]))
    return np.linalg.solve(M, p - p0)
