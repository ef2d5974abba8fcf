r"""Numeric Hamiltonian of a system, for the structure-preserving integrators.

In canonical variables ``z = (q, p)`` the flow is ``ż = 𝕁 ∇H(z)`` with ``𝕁 = [[0, I], [−I, 0]]``.
Runge–Kutta methods that conserve quadratic invariants (Gauss–Legendre collocation, implicit midpoint)
are symplectic *in these variables* (not in (q, q̇)), so the fixed-step geometric integrators work on
(q, p) and convert back with ``q̇ = ∂H/∂p``. Built from :func:`lagrange.analysis.hamilton.hamiltonian`:
H, its gradient and its Hessian are generated once (CSE'd lambdify) with parameters bound.
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
    """Compile H for ``system`` with ``params`` bound. Only conservative, unconstrained systems qualify
    (forces outside V break the Hamiltonian structure the geometric methods preserve)."""
    from ..analysis.hamilton import hamiltonian

    eqs = system.derived
    if eqs.m:
        raise LagrangeError("the geometric integrators need an unconstrained system (eliminate the constraints)")
    if any(sp.sympify(Q) != 0 for Q in eqs.nonconservative):
        raise LagrangeError("the geometric integrators need a conservative system: forces, P or rayleigh present; "
                            "use a scipy method")
    h = hamiltonian(system)
    values = dict(zip(eqs.parameters, bind_parameters(eqs, params)))
    n = eqs.n
    z = list(h.q) + list(h.p)
    H = sp.sympify(h.H).subs(values)
    grad = [sp.diff(H, v) for v in z]
    hess = sp.Matrix(2 * n, 2 * n, lambda i, j: sp.diff(grad[i], z[j]))
    fH = sp.lambdify((t, z), H, "numpy", cse=True)
    fg = sp.lambdify((t, z), grad, "numpy", cse=True)
    fh = sp.lambdify((t, z), hess, "numpy", cse=True)
    L = eqs.kinetic - eqs.potential
    mom = sp.lambdify((t, list(eqs.q), list(eqs.qd)), [sp.diff(L, v).subs(values) for v in eqs.qd], "numpy", cse=True)
    Mconst = all(not (e.free_symbols & (set(eqs.q) | {t})) for e in eqs.mass_matrix)
    linear_T = all(sp.diff(eqs.kinetic, v).subs({w: 0 for w in eqs.qd}) == 0 for v in eqs.qd)
    separable = Mconst and linear_T and not (eqs.potential.free_symbols & {t})
    return HamiltonianModel(
        n=n,
        H=lambda t_, zz: float(fH(t_, list(zz))),
        grad=lambda t_, zz: np.asarray(fg(t_, list(zz)), dtype=float),
        hess=lambda t_, zz: np.asarray(fh(t_, list(zz)), dtype=float).reshape(2 * n, 2 * n),
        to_momenta=lambda t_, q, qd: np.asarray(mom(t_, list(q), list(qd)), dtype=float),
        autonomous=t not in H.free_symbols,
        separable=bool(separable),
    )
