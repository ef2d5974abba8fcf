r"""Conventions used everywhere in :mod:`lagrange` — stated once, here.

Lagrange's equations (Wells, *Lagrangian Dynamics*, eqs. 4.9, 5.10, 6.10)
--------------------------------------------------------------------------
For every generalized coordinate :math:`q_r`

.. math::

    \frac{d}{dt}\frac{\partial T}{\partial \dot q_r} - \frac{\partial T}{\partial q_r}
    + \frac{\partial V}{\partial q_r}
    = F_{q_r} + \frac{\partial P}{\partial \dot q_r} - \frac{\partial D}{\partial \dot q_r}

* ``T`` is the kinetic energy reckoned relative to an inertial frame (it may depend on q, q̇, t).
* ``V`` is the potential energy V(q, t); it must not contain velocities.
* ``P`` is Wells' **power function**: the generalized force is ``+∂P/∂q̇``, so ``P < 0`` for losses,
  e.g. ``P = -b*x_dot**2/2`` for viscous drag and ``P = -mu*N*|v|`` for dry friction.
* ``D`` (argument ``rayleigh=``) is the usual positive Rayleigh dissipation function; its force is
  ``-∂D/∂q̇``. ``D = -P``. A force must never be counted twice (in V and in P, or in P and D).
* ``F_q`` are generalized forces of everything not in V, P or D, computed from Cartesian forces with
  time frozen (Wells 4.10): ``F_qr = Σ_i F_i · ∂r_i/∂q_r``.

Normal form
-----------
Every derivation returns :math:`M(q, t)\,\ddot q = f(q, \dot q, t)` with ``M`` the symmetric Hessian of T
in the velocities (``M = 2A`` in Wells' notation of eq. 2.55, whose ``A`` already contains the 1/2).
It never returns "expression = 0" with a path-dependent sign.

State and shapes
----------------
The state is ``y = [q_1..q_n, q̇_1..q̇_n]``, shape ``(2n,)``; a trajectory has shape ``(n_times, 2n)``.
Right-hand sides have the signature ``rhs(t, y, p)`` with ``p`` the parameter values in the order of
``Equations.parameters``.

Symbols
-------
* There is one time symbol, :data:`t` (real). Coordinates are undefined sympy functions of ``t``.
* Parameters are positive real symbols (``lagrange.parameters``) unless the user declares otherwise.
* The symbolic layer is exact (``Rational(1, 2)``, never ``0.5``); floats enter only at code generation.
* Angles are in radians. The engine is unit-agnostic: each problem states its units.

Multipliers: with constraints ``g = A q̇ + b = 0`` (``A = ∂φ/∂q`` for a holonomic ``φ(q, t) = 0``) the
equations read ``M q̈ = f + Aᵀλ``; ``λ_k A_kr`` is the generalized force of constraint on coordinate r
(Wells' 𝓕_qr, eq. 12.3). Details and examples: :mod:`lagrange.model.constraints`.

Euler angles and rotations: :mod:`lagrange.model.rotations` (Wells' z-x-z ψ, θ, φ; rotation matrices
map body to inertial components). Products of inertia are Wells' positive sums:
:mod:`lagrange.model.inertia`.
"""

from __future__ import annotations

import sympy as sp

#: The one time symbol.
t: sp.Symbol = sp.Symbol("t", real=True)

#: Suffix used for velocity names in text specs, printing of plain symbols and CSV headers.
VELOCITY_SUFFIX = "_dot"

#: Sign of the power function's contribution to the generalized force (Wells 6.10).
POWER_FUNCTION_SIGN = +1
#: Sign of the Rayleigh function's contribution to the generalized force.
RAYLEIGH_SIGN = -1

__all__ = ["t", "VELOCITY_SUFFIX", "POWER_FUNCTION_SIGN", "RAYLEIGH_SIGN"]
