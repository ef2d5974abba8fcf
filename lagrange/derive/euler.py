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

import warnings

import sympy as sp

from ..conventions import t
from ..errors import ConventionChangeWarning, DeclarationError
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


_FRAMES = ("inertial", "body")
_UNSET = object()


def support_loads(body, applied_force=(0, 0, 0), applied_torque=(0, 0, 0), *,
                  frame: str = _UNSET) -> tuple[sp.Matrix, sp.Matrix]:
    r"""Force and torque about the centre of mass that the supports exert, both in the components of ``frame``.

    .. math:: \mathbf F = M\mathbf a_{cm} - \mathbf F_{applied}\ \text{(Wells 9.2)},\qquad
              \boldsymbol\tau = J_c\dot{\boldsymbol\omega} + \boldsymbol\omega\times J_c\boldsymbol\omega
              - \boldsymbol\tau_{applied}

    with ``J_c`` the central inertia (parallel-axis shift from O) and ω along the body axes.

    Parameters
    ----------
    body : :class:`~lagrange.RigidBody`
    applied_force, applied_torque : 3-vectors in the components of ``frame`` (the torque about the centre of
        mass)
    frame : ``"inertial"`` (components along the inertial axes) or ``"body"`` (along the body axes, ``R^T``
        times the inertial components, R the body's orientation). Give it: a call without ``frame`` keeps the
        earlier mixed convention — force (given and returned) along the inertial axes, torque (given and
        returned) along the body axes — and warns with
        :class:`~lagrange.errors.ConventionChangeWarning`; ``frame`` will become a required keyword.

    Returns
    -------
    (F, tau) : two 3×1 Matrices, both in the components of ``frame``.

    Raises
    ------
    ValueError
        ``frame`` is neither ``"inertial"`` nor ``"body"``.
    DeclarationError
        ``body`` is not a rigid body.

    The torque about the centre of mass excludes the support force's own moment; add ``r × F`` for a
    support at body point r (r and F in the same frame).
    """
    legacy = frame is _UNSET
    if not legacy and frame not in _FRAMES:
        raise ValueError(f"frame must be 'inertial' or 'body', got {frame!r}")
    if not all(hasattr(body, a) for a in ("angular_velocity", "inertia", "R", "com", "centre_of_mass")):
        raise DeclarationError(f"support_loads needs a RigidBody, got {body!r} (a particle's support force is "
                               "m a − F_applied, with no torque)", subject="support_loads")
    if legacy:
        warnings.warn("support_loads(body, ...) without frame= returns the force along the inertial axes and the "
                      "torque along the body axes (and reads applied_torque along the body axes), as it always "
                      "has; frame= will become required. Pass frame='inertial' for both along the inertial "
                      "axes, or frame='body' for both along the body axes", ConventionChangeWarning, stacklevel=2)
        frame = "inertial"
    M = body.mass
    R = body.R
    Fa = as_vector(applied_force, "applied force")
    Ta = as_vector(applied_torque, "applied torque")
    if frame == "body":
        Fa = R * Fa
    elif not legacy:
        Ta = R.T * Ta
    F = M * body.centre_of_mass.diff(t, 2) - Fa  # inertial components
    c = body.com
    shift = M * ((c.T * c)[0, 0] * sp.eye(3) - c * c.T)
    Jc = body.inertia - shift
    w = body.angular_velocity
    tau = Jc * w.diff(t) + w.cross(Jc * w) - Ta  # body axes
    if frame == "body":
        return R.T * F, tau
    return F, tau if legacy else R * tau
