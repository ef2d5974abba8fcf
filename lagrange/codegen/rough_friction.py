r"""Numeric form of Coulomb friction over a surface (rough constraints with a sliding-velocity vector).

The derived equations (:mod:`lagrange.derive.multipliers`) carry the friction of a rough constraint ``k`` that
slides over a surface as the column

.. math:: B_{jk} = A_{kj} - \mu\,n\,\sigma_k\,|v|^{-1}\sum_i v_i\,\frac{\partial v_i}{\partial\dot q_j},
          \qquad |v| = \Big(\sum_i v_i^2\Big)^{1/2},

exact, with ``σ_k = sign(λ_k)`` fixed per segment by :mod:`lagrange.integrate.rough` and the sliding function
``|v| − 1e-9`` that ends the run when sliding stops (``friction="events"``). :func:`regularized_planar_friction`
gives the ``friction="regularize"`` form: ``|v| → sqrt(|v|² + ε²)`` in the friction and in the sliding function
(which then stays positive: the run continues through a stop, where the friction fades to zero like the
regularized ``sign(u) → u/sqrt(u² + ε²)`` of dry friction, :func:`lagrange.integrate.switching.regularized_equations`).
"""

from __future__ import annotations

import dataclasses

import sympy as sp

from ..derive.equations import Equations

__all__ = ["regularized_planar_friction", "planar_friction_for"]

_TINY = sp.Float(1e-300)  # added to |v|² in the exact form: at rest the friction is 0/√1e-300 = 0, not 0/0


def planar_friction_for(eqs: Equations, friction: str, epsilon: float) -> Equations:
    """The numeric form for ``simulate(friction=...)``: ``"regularize"`` → :func:`regularized_planar_friction`;
    ``"events"`` → ``|v|² + 1e-300`` (exact in double precision for any sliding speed above the 1e-9 stop), so
    that the state at rest evaluates (the friction is 0 there instead of 0/0) and the run can end with a message
    instead of NaNs. (Not ``Max``: sympy's ``Max`` re-simplifies on every substitution, seconds per segment.)"""
    if not eqs.planar_friction:
        return eqs
    if friction == "regularize":
        return regularized_planar_friction(eqs, epsilon)
    return _replace_bases(eqs, {s2: s2 + _TINY for _, s2 in eqs.planar_friction}, regularized=False)


def _replace_bases(eqs: Equations, bases: dict, *, regularized: bool) -> Equations:
    def reg(expr):
        return expr.replace(lambda a: a.is_Pow and a.base in bases, lambda a: sp.Pow(bases[a.base], a.exp))

    B = sp.ImmutableMatrix(eqs.reaction_matrix.applyfunc(reg))
    if not regularized:
        return dataclasses.replace(eqs, reaction_matrix=B, jacobi_rate=reg(eqs.jacobi_rate))
    by_k = dict(eqs.planar_friction)
    sliding = tuple((k, sp.sqrt(bases[by_k[k]]) if k in by_k else v) for k, v in eqs.sliding_velocities)
    return dataclasses.replace(eqs, reaction_matrix=B, sliding_velocities=sliding, jacobi_rate=reg(eqs.jacobi_rate))


def regularized_planar_friction(eqs: Equations, epsilon: float) -> Equations:
    """``eqs`` with ``|v| → sqrt(|v|² + ε²)`` for every rough constraint sliding over a surface.

    Raises ``TypeError`` for a non-positive or non-finite ``epsilon`` (the same rule as the ``sign()``
    regularization)."""
    eps = float(epsilon)
    if not (eps > 0 and eps < float("inf")):
        raise TypeError(f"friction_epsilon must be a positive finite number, got {epsilon!r}")
    if not eqs.planar_friction:
        return eqs
    e2 = sp.Float(eps) ** 2
    return _replace_bases(eqs, {s2: s2 + e2 for _, s2 in eqs.planar_friction}, regularized=True)
