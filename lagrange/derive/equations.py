"""The frozen result of a derivation: ``M(q, t) q̈ = f(q, q̇, t)`` in plain symbols.

This is the boundary between the symbolic and the numeric stages: code generation reads only this.
"""

from __future__ import annotations

from dataclasses import fields

import sympy as sp

from ..records import record

__all__ = ["Equations"]


@record(frozen=True, eq=False)  # (its own __eq__ and __hash__ below)
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
    jacobi_rate : ``dh/dt = −∂L/∂t + Σ q̇ (F_q + ∂P/∂q̇ − ∂D/∂q̇ + (Aᵀλ)_q)`` (power balance; the last
        term is the power of moving constraints and contains the multiplier symbols)
    constraint_* : the velocity-level constraints ``A q̇ + b = 0``, their derivative ``A q̈ = c`` and, for
        holonomic ones, ``φ(q, t) = 0``; ``multipliers`` are the λ with ``M q̈ = f + Aᵀλ``
    inputs : tuple of :class:`~lagrange.model.inputs.Input` symbols, sorted by name — time-varying inputs
        (in f, the forces and ``jacobi_rate`` only), not parameters: the last entries of ``p``
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
    # --- constraints (empty when there are none); see lagrange.model.constraints -------------------
    constraint_names: tuple = ()
    constraint_matrix: sp.ImmutableMatrix = sp.ImmutableMatrix(0, 0, [])  # A (m, n), g = A q̇ + b
    constraint_bias: tuple = ()  # b_k(q, t)
    constraint_rhs: tuple = ()  # c_k(q, q̇, t) with A q̈ = c
    constraint_positions: tuple = ()  # φ_k(q, t) for holonomic constraints, None for non-holonomic
    multipliers: tuple = ()  # λ_k symbols; the generalized constraint force is Aᵀλ
    unilateral: tuple = ()  # True where the constraint may only push (λ_k ≥ 0)
    reaction_matrix: sp.ImmutableMatrix = sp.ImmutableMatrix(0, 0, [])  # B (n, m): M q̈ = f + Bλ; Aᵀ unless rough
    rough_signs: tuple = ()  # σ_k = sign(λ_k)·sign(v_s,k) symbols of rough constraints (bound per segment)
    sliding_velocities: tuple = ()  # ((k, v_s,k), ...) for rough constraints
    planar_friction: tuple = ()  # ((k, |v|²), ...) rough constraints sliding over a surface (v_s,k = |v| − 1e-9)
    inputs: tuple = ()  # u_k symbols: time-varying inputs, given at compile/simulate time

    def __hash__(self) -> int:
        """The hash of the fields, computed once: Equations key per-model caches (tapes, switches), and hashing
        every matrix on each lookup would cost tens of µs per ``simulate`` call."""
        h = self.__dict__.get("_hash")
        if h is None:
            h = hash(tuple(getattr(self, f.name) for f in fields(self)))
            object.__setattr__(self, "_hash", h)
        return h

    def __eq__(self, other: object) -> bool:
        if self is other:  # the common case of cache lookups, without comparing every expression
            return True
        if other.__class__ is not self.__class__:
            return NotImplemented
        return all(getattr(self, f.name) == getattr(other, f.name) for f in fields(self))

    def __getstate__(self) -> dict:
        # sympy hashes differ between processes (string hashing is salted): never pickle the cached one
        return {k: v for k, v in self.__dict__.items() if k not in ("_hash", "_quadrature")}

    @property
    def is_structural(self) -> bool:
        """True for :class:`~lagrange.derive.structural.StructuralEquations` (code generation assembles M and f
        from the system's structure)."""
        return False

    def energy_parts(self) -> tuple:
        """``(T, h, T₂, T₀)``: the kinetic energy, the Jacobi integral, and T's parts quadratic in and free of
        the velocities (``T₂ = ½ q̇ᵀ M q̇``, ``T₀ = T|_{q̇=0}``), for energy reports."""
        qd = sp.Matrix(self.qd)
        T2 = (qd.T * self.mass_matrix * qd)[0, 0] / 2
        return self.kinetic, self.jacobi, T2, self.kinetic.subs({v: 0 for v in self.qd})

    @property
    def has_quadrature(self) -> bool:
        """True when an integral sympy could not evaluate remains in M, f, the constraint blocks or the power
        ``dh/dt`` (:mod:`lagrange.model.integrals`): generated code evaluates it by quadrature
        (:mod:`lagrange.codegen.quadrature`), and the Taylor method and heyoka refuse the equations."""
        if self.is_structural:  # (never: System keeps integrals to the expanded derivation; M, f are lazy there)
            return False
        h = self.__dict__.get("_quadrature")
        if h is None:
            h = any(sp.sympify(e).has(sp.Integral) for e in (self.mass_matrix, self.forcing, self.jacobi_rate,
                                                              *self.constraint_rhs, self.constraint_matrix))
            object.__setattr__(self, "_quadrature", h)
        return h

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return len(self.q)

    @property
    def numeric_parameters(self) -> tuple:
        """Symbols bound to the ``p`` vector of generated code: the parameters, then the per-segment
        friction signs of rough constraints (default +1), then the inputs (:attr:`input_offset` on; a
        time-varying input's slots are refilled at every evaluation, see
        :mod:`lagrange.codegen.input_values`)."""
        return self.parameters + self.rough_signs + self.inputs

    @property
    def input_offset(self) -> int:
        """Index of the first input in the ``p`` vector (the inputs are its last ``len(inputs)`` entries)."""
        return len(self.parameters) + len(self.rough_signs)

    @property
    def is_rough(self) -> bool:
        return bool(self.rough_signs)

    @property
    def m(self) -> int:
        """Number of constraints."""
        return len(self.constraint_names)

    @property
    def is_autonomous(self) -> bool:
        """True when t appears nowhere in M and f."""
        from ..conventions import t

        return t not in self.mass_matrix.free_symbols | self.forcing.free_symbols

    @property
    def is_conservative(self) -> bool:
        """True when the Jacobi integral is conserved identically (no dissipation, forcing, explicit t or
        moving constraints).

        This is a property of the whole system's equations, not a classification of a force field: a system
        whose declared generalized forces ``F`` form a conservative field (say ``F = (−kx, −ky)`` written as
        forces instead of a potential) still answers False here when they enter as applied forces. To ask
        whether a force field is conservative (Wells 5.6/5.8), or to find its potential, use
        :func:`lagrange.is_conservative` and :func:`lagrange.potential_of`."""
        return self.jacobi_rate == 0
