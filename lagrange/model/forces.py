r"""Generalized forces from the three forms Wells uses.

1. A mapping ``{q: F_q}`` given directly.
2. Cartesian forces applied at points (:class:`~lagrange.model.bodies.Force`), Wells (4.10):

   .. math:: F_{q_r} = \sum_i \Big(F_{x_i}\frac{\partial x_i}{\partial q_r}
             + F_{y_i}\frac{\partial y_i}{\partial q_r} + F_{z_i}\frac{\partial z_i}{\partial q_r}\Big)

   with t and the other coordinates held fixed.
   At a material point P of a rigid body (``body.point(r)``, ``body.point_at(position)``, or
   ``Force(..., body=B)``) the same virtual work comes from the body's velocity field,
   :math:`F_{q_r} = F\cdot\partial v_P/\partial\dot q_r` with :math:`v_P = v_O + \omega\times r_{OP}`
   (:class:`~lagrange.model.bodies.MaterialPoint`); the two coincide for a point fixed in the body. Over all the
   coordinates, constrained ones included: the multipliers carry the constraints (Wells ch. 12).
3. Torques on rigid bodies (:class:`~lagrange.model.rigid_body.Torque`), ``F_q = τ·∂ω/∂q̇`` (Wells 8.12).
4. A virtual-work expression :math:`\delta W = \sum_r F_{q_r}\,\delta q_r` (Wells 4.12) written with
   :func:`~lagrange.model.coordinates.delta` or the ``delta_q`` symbols: the coefficients are the F_q.

The three forms may be combined in a list; contributions add.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy as sp

from ..conventions import t
from ..safe_sympify import sympify as _sympify
from .bodies import Force, MaterialPoint
from .coordinates import (
    coordinate_name,
    is_coordinate,
    to_functions,
    to_symbols,
    virtual_displacement,
)
from .rigid_body import Torque

__all__ = ["generalized_forces"]


def _from_force(force: Force, coords: Sequence) -> dict:
    if isinstance(force.at, MaterialPoint):
        # on a rigid body: F · ∂v_P/∂q̇ with the body's velocity field (Kane's partial velocities)
        return {q: (force.vector.T * dv)[0, 0] for q, dv in force.at.partial_velocities(coords).items()}
    if force.at.atoms(sp.Derivative):
        label = force.name or tuple(force.vector)
        raise ValueError(f"the point of application of force {label} contains velocities")
    pos = to_symbols(force.at, coords)
    out = {}
    for q in coords:
        jac = to_functions(pos.diff(to_symbols(q, coords)), coords)
        out[q] = (force.vector.T * jac)[0, 0]
    return out


def _from_virtual_work(expr, coords: Sequence, problems: list) -> dict:
    expr = sp.expand(_sympify(expr))
    deltas = {virtual_displacement(q): q for q in coords}
    stray = sorted(
        str(s) for s in expr.free_symbols if s.name.startswith("delta_") and s not in deltas
    )
    if stray:
        problems.append(
            f"virtual work contains {', '.join(stray)}, which are not virtual displacements of the "
            f"coordinates ({', '.join(coordinate_name(q) for q in coords)}); use delta() of the "
            "transformation equations instead"
        )
        return {}
    out = {}
    for d, q in deltas.items():
        out[q] = expr.coeff(d)
    rest = sp.expand(expr - sum(out[q] * d for d, q in deltas.items()))
    if rest != 0:
        problems.append(
            f"virtual work has a term without a virtual displacement: {rest}; every term of δW must be "
            "a force times some delta_q"
        )
    if any(_sympify(c).free_symbols & set(deltas) for c in out.values()):
        problems.append("virtual work is not linear in the virtual displacements")
    return out


def _is_torque(item) -> bool:
    return isinstance(item, Torque)


def generalized_forces(forces, coords: Sequence, problems: list) -> dict:
    """Normalize ``forces`` to ``{q: F_q}`` over ``coords`` (missing entries are 0).

    Problems found are appended to ``problems`` (validation collects and raises once).
    """
    total = {q: sp.S.Zero for q in coords}
    if forces is None:
        return total
    items = forces if isinstance(forces, (list, tuple)) else [forces]
    for item in items:
        if isinstance(item, Mapping):
            for key, value in item.items():
                q = key
                if isinstance(key, str):
                    match = [c for c in coords if coordinate_name(c) == key]
                    q = match[0] if match else None
                if q is None or not is_coordinate(q) or q not in total:
                    problems.append(
                        f"generalized force given for {key!r}, which is not a coordinate of this system "
                        f"({', '.join(coordinate_name(c) for c in coords)})"
                    )
                    continue
                total[q] += _sympify(value)
        elif _is_torque(item):
            w = to_symbols(item.angular_velocity(), coords)
            for q in coords:
                dw = to_functions(w.diff(to_symbols(q.diff(t), coords)), coords)
                total[q] += (item.vector.T * dw)[0, 0]
        elif isinstance(item, Force):
            try:
                for q, v in _from_force(item, coords).items():
                    total[q] += v
            except ValueError as exc:
                problems.append(str(exc))
        else:
            try:
                expr = _sympify(item)
            except (sp.SympifyError, TypeError):
                problems.append(
                    f"cannot read {item!r} as forces: give a dict {{q: F_q}}, lagrange.Force(at, vector) "
                    "objects or a virtual-work expression"
                )
                continue
            for q, v in _from_virtual_work(expr, coords, problems).items():
                total[q] += v
    return total
