r"""Numeric Hamiltonian of a system, for the structure-preserving integrators.

In canonical variables ``z = (q, p)`` the flow is ``ż = 𝕁 ∇H(z)`` with ``𝕁 = [[0, I], [−I, 0]]``.
Runge–Kutta methods that conserve quadratic invariants (Gauss–Legendre collocation, implicit midpoint)
are symplectic *in these variables* (not in (q, q̇)), so the fixed-step geometric integrators work on
(q, p) and convert back with ``q̇ = ∂H/∂p``. Built from the derived equations (no symbolic Legendre
transform): M, b, L, ∂L/∂q and the second derivatives of L are generated once
(:mod:`lagrange.codegen.hamiltonian_source`, kept in the derivation cache) and M⁻¹ is applied numerically.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Mapping

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import ParameterError
from ..records import record
from .hamiltonian_source import check_hamiltonian, hamiltonian_source

__all__ = ["HamiltonianModel", "hamiltonian_model", "generated_source", "compiled_module"]

_SOURCES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_MODELS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()  # Equations → {parameter values: model}


@record(frozen=True)
class HamiltonianModel:
    n: int
    H: object  # H(t, z) -> float
    grad: object  # ∇H(t, z) -> (2n,)
    hess: object  # ∇²H(t, z) -> (2n, 2n), from the generated second derivatives of L
    to_momenta: object  # (t, q, qd) -> p
    autonomous: bool
    separable: bool  # H = ½ pᵀ M⁻¹ p + V(q) with constant M
    equations: object = None  # the Equations it was built from
    params: np.ndarray | None = None  # parameter values, in the order of equations.numeric_parameters

    def field(self, t_, z) -> np.ndarray:
        """𝕁∇H."""
        g = self.grad(t_, z)
        n = self.n
        return np.concatenate([g[n:], -g[:n]])

    def field_jacobian(self, t_, z) -> np.ndarray:
        Hz = self.hess(t_, z)
        n = self.n
        return np.vstack([Hz[n:, :], -Hz[:n, :]])

    def compiled_module(self):
        """The numba module of the generated pieces for the compiled loops (:func:`compiled_module`)."""
        return compiled_module(self)


def compiled_module(hm: HamiltonianModel):
    """The numba module of ``hm``'s generated Hamiltonian pieces (compiled once, cached on disk), decorated by
    :func:`~lagrange.codegen.hamiltonian_source.compiled_source`."""
    from .hamiltonian_source import compiled_source
    from .numba_backend import load_cached

    return load_cached("ham", compiled_source(generated_source(hm.equations, len(hm.params))),
                       "the generated Hamiltonian pieces")


def generated_source(eqs, n_params: int) -> str:
    """:func:`~lagrange.codegen.hamiltonian_source.hamiltonian_source` of ``eqs``, from the derivation cache
    (and memoized per Equations in this process); the compiled loop decorates the same text
    (:func:`~lagrange.codegen.hamiltonian_source.compiled_source`)."""
    from .derivation_cache import cached_source

    memo = _SOURCES.setdefault(eqs, {})
    if n_params not in memo:
        memo[n_params] = cached_source(eqs, f"hamiltonian pieces; n_params {n_params}",
                                       lambda: hamiltonian_source(eqs, n_params))
    return memo[n_params]


def hamiltonian_model(system, params: Mapping) -> HamiltonianModel:
    r"""Compile H for ``system`` with ``params`` bound. Only conservative, unconstrained systems qualify
    (forces outside V break the Hamiltonian structure the geometric methods preserve).

    With ``T = ½ q̇ᵀM(q,t)q̇ + bᵀq̇ + T₀`` and ``L = T − V``:

    .. math:: \dot q = M^{-1}(p - b),\quad H = p\cdot\dot q - L,\quad
              \partial H/\partial p = \dot q,\quad \partial H/\partial q = -\partial L/\partial q\big|_{\dot q}

    — the exact gradient of H (so the discrete gradient conserves H to the Newton tolerance) — and the
    exact Hessian (Newton's matrix) from the generated second derivatives of L
    (:mod:`lagrange.codegen.hamiltonian_source` gives the formula). Built once per equations and parameter
    values in a process.
    """
    eqs = system.derived if hasattr(system, "derived") else system
    if eqs not in _MODELS:  # checked once per equations (130 µs on a 5-link pendulum); failures raise every time
        check_hamiltonian(eqs)
    pvals = params if isinstance(params, np.ndarray) else _bind(eqs, params)
    memo = _MODELS.setdefault(eqs, {})
    key = tuple(pvals.tolist())
    if key not in memo:
        memo[key] = _build(eqs, pvals)
    return memo[key]


def _bind(eqs, params: Mapping) -> np.ndarray:
    """The values of ``params`` (keys: symbols or names) in the order of ``eqs.numeric_parameters``;
    :class:`~lagrange.errors.ParameterError` listing every missing, unknown or non-finite value."""
    by_name = {getattr(k, "name", k): v for k, v in params.items()}
    wanted = [s.name for s in eqs.numeric_parameters]
    problems = []
    missing = [n for n in wanted if n not in by_name]
    if missing:
        problems.append(f"missing value(s) for parameter(s) {', '.join(missing)}")
    unknown = sorted(set(map(str, by_name)) - set(wanted))
    if unknown:
        problems.append(f"unknown parameter(s) {', '.join(unknown)} (this system's parameters: "
                        f"{', '.join(wanted) or 'none'})")
    values = []
    for n in wanted:
        try:
            v = float(by_name.get(n, math.nan))
        except (TypeError, ValueError):
            v = math.nan
        if n not in missing and not math.isfinite(v):
            problems.append(f"parameter {n} = {by_name[n]!r} is not a finite number")
        values.append(v)
    if problems:
        raise ParameterError("; ".join(problems))
    return np.array(values, dtype=float)


def _build(eqs, pvals: np.ndarray) -> HamiltonianModel:
    n = eqs.n
    namespace: dict = {}
    exec(compile(generated_source(eqs, len(pvals)), "<lagrange hamiltonian>", "exec"), namespace)
    mass, lagrangian, second = namespace["mass"], namespace["lagrangian"], namespace["second"]
    pc = tuple(float(v) for v in pvals)

    def mass_b(t_, qq):
        M, b = np.empty((n, n)), np.empty(n)
        mass(t_, qq, pc, M, b)
        return M, b

    def state(t_, zz):
        """(q as floats, M, q̇) at (t, z)."""
        qq = [float(x) for x in zz[:n]]
        M, b = mass_b(t_, qq)
        return qq, M, np.linalg.solve(M, np.asarray(zz[n:], dtype=float) - b)

    def H(t_, zz):
        qq, _, v = state(t_, zz)
        return float(np.dot(zz[n:], v) - lagrangian(t_, qq, v.tolist(), pc, np.empty(n)))

    def grad(t_, zz):
        qq, _, v = state(t_, zz)
        Lq = np.empty(n)
        lagrangian(t_, qq, v.tolist(), pc, Lq)
        return np.concatenate([-Lq, v])

    def hess(t_, zz):
        qq, M, v = state(t_, zz)
        Lqq, Lqv = np.empty((n, n)), np.empty((n, n))
        second(t_, qq, v.tolist(), pc, Lqq, Lqv)
        Minv = np.linalg.inv(M)
        W = Minv @ Lqv.T  # −∂q̇/∂q
        return np.block([[-Lqq + Lqv @ W, -W.T], [-W, Minv]])

    def to_momenta(t_, qq, vv):
        M, b = mass_b(t_, [float(x) for x in qq])
        return M @ np.asarray(vv, dtype=float) + b

    values = dict(zip(eqs.numeric_parameters, pvals))
    q, qd = list(eqs.q), list(eqs.qd)
    T = sp.sympify(eqs.kinetic).subs(values)
    V = sp.sympify(eqs.potential).subs(values)
    M = sp.Matrix(eqs.mass_matrix).subs(values)
    zero = {v: 0 for v in qd}
    Mconst = all(not (e.free_symbols & (set(q) | {t})) for e in M)
    separable = Mconst and all(sp.diff(T, v).subs(zero) == 0 for v in qd) and not (
        (V - T.subs(zero)).free_symbols & {t})
    return HamiltonianModel(n=n, H=H, grad=grad, hess=hess, to_momenta=to_momenta,
                            autonomous=t not in (T.free_symbols | V.free_symbols), separable=bool(separable),
                            equations=eqs, params=pvals)
