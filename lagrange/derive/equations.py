"""The frozen result of a derivation: ``M(q, t) q̈ = f(q, q̇, t)`` in plain symbols.

This is the boundary between the symbolic and the numeric stages: code generation reads only this.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = ["Equations"]


@dataclass(frozen=True)
class Equations:
    """Lagrange's equations of a system in normal form, in plain symbols.

    Attributes
    ----------
    coordinates : tuple of coordinate functions q(t)
    q, qd, qdd : tuples of Symbols — positions, velocities, accelerations (``x``, ``x_dot``, ``x_ddot``)
    parameters : tuple of Symbols, sorted by name: the order of the ``p`` argument of ``rhs(t, y, p)``
    mass_matrix : ImmutableMatrix, shape (n, n), symmetric, ``∂²T/∂q̇∂q̇``
    forcing : ImmutableMatrix, shape (n, 1), ``f`` in ``M q̈ = f``
    inertial : tuple — ``d/dt(∂T/∂q̇) − ∂T/∂q`` with q̈ as symbols (Wells' left side without V)
    potential_gradient : tuple — ``∂V/∂q``
    applied : tuple — ``F_q`` from forces (virtual work, Cartesian forces, given F_q)
    dissipative : tuple — ``∂P/∂q̇ − ∂D/∂q̇``
    nonconservative : tuple — ``applied + dissipative``
    kinetic, potential, power_function, rayleigh : the scalar functions, in symbols
    jacobi : ``h = Σ q̇ ∂L/∂q̇ − L``
    jacobi_rate : ``dh/dt = −∂L/∂t + Σ q̇ (F_q + ∂P/∂q̇ − ∂D/∂q̇)`` (power balance)
    """

    coordinates: tuple
    q: tuple
    qd: tuple
    qdd: tuple
    parameters: tuple
    mass_matrix: sp.ImmutableMatrix
    forcing: sp.ImmutableMatrix
    inertial: tuple
    potential_gradient: tuple
    applied: tuple
    dissipative: tuple
    nonconservative: tuple
    kinetic: sp.Expr
    potential: sp.Expr
    power_function: sp.Expr
    rayleigh: sp.Expr
    jacobi: sp.Expr
    jacobi_rate: sp.Expr
    name: str = ""

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return len(self.q)

    @property
    def is_autonomous(self) -> bool:
        """True when t appears nowhere in M and f."""
        from ..conventions import t

        return t not in self.mass_matrix.free_symbols | self.forcing.free_symbols

    @property
    def is_conservative(self) -> bool:
        """True when the Jacobi integral is conserved identically (no dissipation, forcing or explicit t)."""
        return self.jacobi_rate == 0
