r"""Numeric Hamiltonian of a system, for the structure-preserving integrators.

In canonical variables ``z = (q, p)`` the flow is ``ż = 𝕁 ∇H(z)`` with ``𝕁 = [[0, I], [−I, 0]]``.
Runge–Kutta methods that conserve quadratic invariants (Gauss–Legendre collocation, implicit midpoint)
are symplectic *in these variables* (not in (q, q̇)), so the fixed-step geometric integrators work on
(q, p) and convert back with ``q̇ = ∂H/∂p``. Built from the derived equations (no symbolic Legendre transform):
M, b, L and ∂L/∂q are generated once (CSE'd lambdify) with parameters bound; M⁻¹ is applied numerically.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..codegen.numeric import bind_parameters
from ..conventions import t
from ..errors import LagrangeError

__all__ = ["HamiltonianModel", "hamiltonian_model"]


@dataclass(frozen=True)
class HamiltonianModel:
    n: int
    H: object  # H(t, z) -> float
    grad: object  # ∇H(t, z) -> (2n,)
    hess: object  # ∇²H(t, z) -> (2n, 2n)
    to_momenta: object  # (t, q, qd) -> p
    autonomous: bool
    separable: bool  # H = ½ pᵀ M⁻¹ p + V(q) with constant M

    def field(self, t_, z) -> np.ndarray:
        """𝕁∇H."""
        g = self.grad(t_, z)
        n = self.n
        return np.concatenate([g[n:], -g[:n]])

    def field_jacobian(self, t_, z) -> np.ndarray:
        Hz = self.hess(t_, z)
        n = self.n
        return np.vstack([Hz[n:, :], -Hz[:n, :]])


def hamiltonian_model(system, params: Mapping) -> HamiltonianModel:
    r"""Compile H for ``system`` with ``params`` bound. Only conservative, unconstrained systems qualify
    (forces outside V break the Hamiltonian structure the geometric methods preserve).

    M⁻¹ is never formed symbolically (it explodes beyond two or three degrees of freedom). With
    ``T = ½ q̇ᵀM(q,t)q̇ + bᵀq̇ + T₀`` and ``L = T − V`` the generated pieces are M, b, L and ∂L/∂q, and

    .. math:: \dot q = M^{-1}(p - b),\quad H = p\cdot\dot q - L,\quad
              \partial H/\partial p = \dot q,\quad \partial H/\partial q = -\partial L/\partial q\big|_{\dot q}

    — the exact gradient of H (so the discrete gradient still conserves H to the Newton tolerance). The
    Hessian, used only as Newton's matrix, is the central difference of that gradient.
    """
    eqs = system.derived
    if eqs.m:
        raise LagrangeError("the geometric integrators need an unconstrained system (eliminate the constraints)")
    if any(sp.sympify(Q) != 0 for Q in eqs.nonconservative):
        raise LagrangeError("the geometric integrators need a conservative system: forces, P or rayleigh present; "
                            "use a scipy method")
    values = dict(zip(eqs.parameters, bind_parameters(eqs, params)))
    n = eqs.n
    q, qd = list(eqs.q), list(eqs.qd)
    T = sp.sympify(eqs.kinetic).subs(values)
    V = sp.sympify(eqs.potential).subs(values)
    M = sp.Matrix(eqs.mass_matrix).subs(values)
    if any(e.free_symbols & set(qd) for e in M):
        raise LagrangeError("the geometric integrators need T quadratic in the velocities (the mass matrix "
                            "depends on velocities here)")
    zero = {v: 0 for v in qd}
    b = [sp.diff(T, v).subs(zero) for v in qd]
    L = T - V
    args = (t, q, qd)
    fM = sp.lambdify((t, q), M, "numpy", cse=True)
    fb = sp.lambdify((t, q), b, "numpy", cse=True)
    fL = sp.lambdify(args, L, "numpy", cse=True)
    fLq = sp.lambdify(args, [sp.diff(L, v) for v in q], "numpy", cse=True)

    def velocities(t_, zz):
        qq = list(zz[:n])
        rhs = np.asarray(zz[n:], dtype=float) - np.asarray(fb(t_, qq), dtype=float).reshape(n)
        return np.linalg.solve(np.asarray(fM(t_, qq), dtype=float).reshape(n, n), rhs)

    def H(t_, zz):
        v = velocities(t_, zz)
        return float(np.dot(zz[n:], v) - fL(t_, list(zz[:n]), list(v)))

    def grad(t_, zz):
        v = velocities(t_, zz)
        return np.concatenate([-np.asarray(fLq(t_, list(zz[:n]), list(v)), dtype=float).reshape(n), v])

    def hess(t_, zz):
        zz = np.asarray(zz, dtype=float)
        out = np.empty((2 * n, 2 * n))
        for j in range(2 * n):
            e = np.zeros(2 * n)
            e[j] = 1e-6 * (1.0 + abs(zz[j]))
            out[:, j] = (grad(t_, zz + e) - grad(t_, zz - e)) / (2 * e[j])
        return 0.5 * (out + out.T)

    def to_momenta(t_, qq, vv):
        Mq = np.asarray(fM(t_, list(qq)), dtype=float).reshape(n, n)
        return Mq @ np.asarray(vv, dtype=float) + np.asarray(fb(t_, list(qq)), dtype=float).reshape(n)

    Mconst = all(not (e.free_symbols & (set(q) | {t})) for e in M)
    separable = Mconst and all(sp.sympify(e) == 0 for e in b) and not ((V - T.subs(zero)).free_symbols & {t})
    return HamiltonianModel(n=n, H=H, grad=grad, hess=hess, to_momenta=to_momenta,
                            autonomous=t not in (T.free_symbols | V.free_symbols), separable=bool(separable))
