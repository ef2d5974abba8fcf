r"""Euler's equations (Wells ch. 9) — a second formulation of rigid-body dynamics, and support loads.

About a point O fixed in space or about the centre of mass, along the body axes (Wells 9.10, with
products of inertia as in Ex. 12.7):

.. math:: \boldsymbol\tau = J\dot{\boldsymbol\omega} + \boldsymbol\omega\times(J\boldsymbol\omega).

Lagrange's equations for any orientation coordinates are the projections
``Σ (Jω̇ + ω×Jω − τ) · ∂ω/∂q̇_r = 0`` (Wells 8.12), which :func:`projected_residuals` forms for a
cross-check. :func:`support_loads` gives the force and torque the supports must supply (bearing and
contact forces, Wells 9.2 and 9.10) along a motion.
"""

from __future__ import annotations

import sympy as sp

from ..conventions import t
from ..model.bodies import as_vector

__all__ = ["euler_equations", "projected_residuals", "support_loads"]


def euler_equations(body) -> sp.Matrix:
    """``Jω̇ + ω × (Jω)`` along the body axes (the torque about O needed for the body's motion)."""
    w = body.angular_velocity
    J = body.inertia
    return J * w.diff(t) + w.cross(J * w)


def projected_residuals(body, coordinates, torque=(0, 0, 0)) -> list:
    """``(Jω̇ + ω×Jω − τ) · ∂ω/∂q̇`` per coordinate: equals d/dt ∂T_rot/∂q̇ − ∂T_rot/∂q − F_q for a body
    turning about a fixed point (Wells 8.12), so it must match Lagrange's equations term by term."""
    res = euler_equations(body) - as_vector(torque, "torque")
    w = body.angular_velocity
    return [sp.expand((res.T * w.diff(q.diff(t)))[0, 0]) for q in coordinates]


def support_loads(body, applied_force=(0, 0, 0), applied_torque=(0, 0, 0)) -> tuple[sp.Matrix, sp.Matrix]:
    """Force (inertial components) and torque about the centre of mass (body axes) that the supports
    exert: ``F = M a_cm − F_applied`` (Wells 9.2) and ``τ = J_c ω̇ + ω × J_c ω − τ_applied`` with J_c the
    central inertia (parallel-axis shift from O).

    The torque about the centre of mass excludes the support force's own moment; add ``r × F`` for a
    support at body point r.
    """
    M = body.mass
    a_cm = body.centre_of_mass.diff(t, 2)
    F = M * a_cm - as_vector(applied_force, "applied force")
    c = body.com
    shift = M * ((c.T * c)[0, 0] * sp.eye(3) - c * c.T)
    Jc = body.inertia - shift
    w = body.angular_velocity
    tau = Jc * w.diff(t) + w.cross(Jc * w) - as_vector(applied_torque, "applied torque")
    return F, tau
