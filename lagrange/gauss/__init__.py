"""Gauss' principle of least constraint: an independent solver in redundant Cartesian coordinates of mass
points, rigid bodies as linked point clouds, balance laws, collisions, and the Lagrange-vs-Gauss check of
any :class:`~lagrange.System` (Sonneveld 2015, *Classical mechanics derived from self-evident axioms*).

Modules: :mod:`~lagrange.gauss.kkt` (the least-constraint KKT solve), :mod:`~lagrange.gauss.points`
(mass points, links, surfaces, dragging), :mod:`~lagrange.gauss.rigid` (point clouds and Newton–Euler),
:mod:`~lagrange.gauss.balance` (momentum, energy, angular momentum), :mod:`~lagrange.gauss.collisions`,
:mod:`~lagrange.gauss.masspoints` (a System as mass points), :mod:`~lagrange.gauss.check` (the cross-check),
:mod:`~lagrange.gauss.appell` (the Gibbs–Appell identity).
"""

from .appell import AppellResult, appell_identity
from .balance import BalanceReport, angular_momentum, balance_residuals, kinetic_energy, momentum, point_balance
from .check import GaussCheck, check_gauss, check_problem
from .collisions import CollisionOutcome, ball_collision, contact_row, impact
from .kkt import LeastConstraintSolution, solve_least_constraint
from .points import (
    Dragging,
    GaussAccelerations,
    Link,
    PointConstraint,
    PointSystem,
    PointTrajectory,
    Surface,
    point_symbols,
    simulate_points,
)
from .rigid import cloud_inertia, integrate_rigid_body, newton_euler_accelerations, rigid_cloud

__all__ = [
    "solve_least_constraint", "LeastConstraintSolution",
    "PointSystem", "Link", "Dragging", "Surface", "PointConstraint", "GaussAccelerations", "PointTrajectory",
    "point_symbols", "simulate_points",
    "rigid_cloud", "cloud_inertia", "newton_euler_accelerations", "integrate_rigid_body",
    "momentum", "angular_momentum", "kinetic_energy", "balance_residuals", "point_balance", "BalanceReport",
    "ball_collision", "impact", "contact_row", "CollisionOutcome",
    "check_gauss", "check_problem", "GaussCheck",
    "appell_identity", "AppellResult",
]
