r"""The Gibbs–Appell identity, checked symbolically against the engine's Lagrange operator (test T-C).

With the acceleration energy (Sonneveld's frustration with ``C = m``)

.. math::

    S = \sum_k \tfrac12 m_k |\ddot x_k|^2
    \quad\text{(particles)},\qquad
    S_{\text{body}} = \tfrac12 M|\ddot x_c|^2 + \tfrac12\dot\omega^{\mathsf T}J_c\dot\omega
                      + \dot\omega\cdot(\omega\times J_c\omega) + \dots
    \quad\text{(rigid bodies, body axes)},

Appell's identity reads :math:`\partial S/\partial\ddot q_r = \frac{d}{dt}\partial T/\partial\dot q_r -
\partial T/\partial q_r` for every coordinate. The left side is built here from the transformation
equations (differentiated twice in time); the right side is the engine's derived ``Equations.inertial``.
A difference that is not identically zero exposes an error in the engine's chain rule or time
differentiation (or a body whose T and kinematics disagree).

Deciding ``difference ≡ 0`` is bounded: structural zero, then ``expand``; a numeric evaluation at random
points (a non-zero value is a definite counterexample: **failed**); then ``simplify`` only for expressions
below ``max_ops`` operations. What remains is reported **undecided** (numerically zero) — never a hang.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ..conventions import t
from ..model.bodies import Particle
from ..model.coordinates import coordinate_name, to_symbols
from ..model.rigid_body import RigidBody
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..simplification import is_zero

__all__ = ["AppellResult", "appell_identity", "acceleration_energy"]


@record(frozen=True)
class AppellResult:
    """``status``: ``"verified"``, ``"failed"``, ``"undecided"`` or ``"not applicable"``; ``per_coordinate``:
    ``{name: status}``; ``detail``: the counterexample or the reason."""

    status: str
    per_coordinate: dict
    detail: str = ""

    def __str__(self) -> str:
        items = ", ".join(f"{k}: {v}" for k, v in self.per_coordinate.items())
        return f"Gibbs-Appell identity: {self.status}" + (f" ({items})" if items else "") + \
            (f"; {self.detail}" if self.detail else "")


def acceleration_energy(system) -> sp.Expr:
    """``S`` of all bodies in the coordinate functions (terms free of q̈ included for particles; for rigid
    bodies only the q̈-dependent part above, which is all ``∂S/∂q̈`` needs)."""
    S = sp.S.Zero
    for body in system.bodies:
        if system.prescribed:
            body = body.subs(system.prescribed)
        if isinstance(body, Particle):
            a = body.position.diff(t, 2)
            S += body.mass * (a.T * a)[0, 0] / 2
        elif isinstance(body, RigidBody):
            c = body.com
            J_c = body.inertia - body.mass * ((c.T * c)[0, 0] * sp.eye(3) - c * c.T)
            w = body.angular_velocity
            al = w.diff(t)
            ac = body.centre_of_mass.diff(t, 2)
            S += (body.mass * (ac.T * ac)[0, 0] + (al.T * J_c * al)[0, 0]) / 2 + (al.T * w.cross(J_c * w))[0, 0]
        else:
            raise TypeError(f"{body!r} is not a particle or rigid body")
    return S


def _numeric_zero(d, scale_exprs, syms, rng, points) -> str | None:
    """A counterexample description, or None when ``d`` is ~0 at every random point."""
    f = _lambdify(syms, [d, *scale_exprs], modules="numpy")
    for _ in range(points):
        vals = [rng.uniform(0.15, 0.85) if not getattr(s, "is_positive", False) else rng.uniform(1.1, 2.3)
                for s in syms]
        with np.errstate(all="ignore"):
            out = [complex(v) for v in f(*vals)]
        if not all(np.isfinite(v) for v in out):
            continue
        scale = max(abs(v) for v in out[1:]) + 1e-300
        if abs(out[0]) > 1e-9 * scale:
            shown = ", ".join(f"{s}={v:.4g}" for s, v in zip(syms, vals))
            return f"difference {out[0].real:.6g} at {shown}"
    return None


def appell_identity(system, *, max_ops: int = 400, points: int = 4, seed: int = 0) -> AppellResult:
    """Check ``∂S/∂q̈_r ≡ d/dt ∂T/∂q̇_r − ∂T/∂q_r`` for every coordinate (see the module docstring).

    Examples
    --------
    >>> import sympy as sp, lagrange as lg
    >>> th = lg.coordinates("theta"); m, l = lg.parameters("m l")
    >>> s = lg.System([th], bodies=[lg.Particle(m, (l*sp.sin(th), -l*sp.cos(th)))])
    >>> appell_identity(s).status
    'verified'
    """
    if system.T_given != 0:
        return AppellResult("not applicable", {}, "T given directly: no kinematics")
    if not all(isinstance(b, (Particle, RigidBody)) for b in system.bodies):
        return AppellResult("not applicable", {}, "a body is neither a particle nor a rigid body")
    coords = system.coordinates
    eqs = system.derived
    S = to_symbols(acceleration_energy(system), coords)
    rng = np.random.default_rng(seed)
    per, details = {}, []
    for r, q in enumerate(coords):
        lhs = sp.diff(S, eqs.qdd[r])
        rhs = eqs.inertial[r]
        d = lhs - rhs
        name = coordinate_name(q)
        if d == 0 or (sp.count_ops(d) <= 20 * max_ops and sp.expand(d) == 0):
            per[name] = "verified"
            continue
        syms = sorted(d.free_symbols | lhs.free_symbols | rhs.free_symbols, key=lambda s: s.name)
        bad = _numeric_zero(d, [lhs, rhs], syms, rng, points)
        if bad:
            per[name] = "failed"
            details.append(f"{name}: {bad}")
        elif is_zero(d, limit=max_ops):
            per[name] = "verified"
        else:
            per[name] = "undecided"
    statuses = set(per.values())
    status = "failed" if "failed" in statuses else "undecided" if "undecided" in statuses else "verified"
    if status == "undecided":
        details.append(f"numerically zero at {points} random points; too large to simplify (> {max_ops} ops)")
    return AppellResult(status, per, "; ".join(details))
