r"""A :class:`~lagrange.System` seen as mass points: the data Gauss' principle needs, built without
Lagrange's equations.

Every body becomes point masses whose inertial positions are expressions in ``(q, t)``:

* a :class:`~lagrange.Particle` is one point;
* a :class:`~lagrange.RigidBody` becomes six **equimomental** points ``m/6`` on its central principal axes
  at ``±d_i`` with ``d_i² = 3 s_i / m``, ``s_i = ½(I_1 + I_2 + I_3) − I_i`` (Wells Sec. 7.10, the rule of
  :func:`lagrange.model.inertia.equimomental_particles`, here with numeric principal axes because the
  parameters are bound): same mass, centre of mass and inertia tensor, hence the same kinetic energy
  (Wells 8.10) and the same Gibbs–Appell function. An inertia no positive masses can carry (a lamina
  declared with I_z only, a massless flywheel) gets signed pseudo-masses (:func:`equimomental_offsets`).

A point is ``x_k = E_k X(q, t)`` for one base vector ``X`` (particle positions; body origins and rotation
matrices), so only ``X`` is differentiated — symbolically, twice in time:

.. math:: \ddot x = J\ddot q + a_0, \qquad J = \partial x/\partial q, \qquad
          a_0 = \ddot x\big|_{\ddot q = 0} = \dot J\dot q + 2\,\partial_t J\,\dot q + \partial_{tt}x .

The applied-force data are the generalized forces ``Q = −∂V/∂q + ∂P/∂q̇ − ∂D/∂q̇ + F_q`` (Wells' sign of
P) and the q-level constraints ``g = A q̇ + b = 0`` differentiated once, ``A q̈ = c``.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import sympy as sp

from ..conventions import t
from ..errors import LagrangeError, ParameterError, shown
from ..model.bodies import Particle
from ..model.coordinates import position_symbol, to_symbols, velocity_symbol
from ..model.rigid_body import RigidBody
from ..records import record
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify

__all__ = ["NotApplicable", "MassPointModel", "mass_point_model", "equimomental_offsets", "declared_symbols"]


class NotApplicable(Exception):  # noqa: N818 - a verdict, not a failure
    """The system cannot be represented by mass points (the message says why)."""


def equimomental_offsets(mass: float, J_c) -> tuple[np.ndarray, np.ndarray]:
    """Points with the mass, centre of mass and central inertia tensor ``J_c`` (3, 3, body axes) of a
    body: ``(offsets (k, 3) from the centre of mass along the body axes, masses (k,))``.

    When the inertia is realizable by positive masses (``I_i ≤ I_j + I_k``) these are Wells' six points
    ``m/6`` at ``±d_i`` on the principal axes, ``d_i² = 3 s_i/m``, ``s_i = ½ΣI − I_i``. Otherwise (a lamina
    declared with I_z only, a massless flywheel, independently chosen moments) a central point plus pairs at
    ``±d`` with **signed** pseudo-masses ``s_i/(2d²)``: the acceleration energy S and the kinetic energy T
    are quadratic forms in mass, first and second moments only, so Gauss' function is still exact.

    >>> off, m = equimomental_offsets(6.0, np.diag([4.0, 4.0, 4.0]))
    >>> off[0].round(12).tolist(), m.tolist()
    ([1.0, 0.0, 0.0], [1.0, 1.0, 1.0, 1.0, 1.0, 1.0])
    """
    I, P = np.linalg.eigh(np.asarray(J_c, dtype=float))
    s = 0.5 * I.sum() - I
    tiny = 1e-12 * max(float(np.max(np.abs(I))), 1e-300)
    if mass > 0 and np.all(s >= -tiny):
        d = np.sqrt(np.clip(3.0 * s / mass, 0.0, None))
        off = np.array([sign * d[i] * P[:, i] for i in range(3) for sign in (1.0, -1.0)])
        return off, np.full(6, mass / 6.0)
    d2 = float(np.max(np.abs(s))) / mass if mass > 0 and np.max(np.abs(s)) > 0 else 1.0
    mu = s / (2.0 * d2)
    off = np.array([np.zeros(3)] + [sign * np.sqrt(d2) * P[:, i] for i in range(3) for sign in (1.0, -1.0)])
    return off, np.concatenate([[mass - 2.0 * mu.sum()], np.repeat(mu, 2)])


@record(frozen=True)
class MassPointModel:
    """Numeric mass-point kinematics and force data of a system (parameters bound).

    Attributes
    ----------
    masses : (K,) point masses; labels : (K,) which body each point belongs to
    signed_bodies : rigid bodies represented with signed pseudo-masses (see :func:`equimomental_offsets`)
    n : number of coordinates; m : number of q-level constraints; constraint_names : their names
    """

    masses: np.ndarray
    labels: tuple
    n: int
    m: int
    constraint_names: tuple
    _E: np.ndarray
    _kin: object
    _data: object
    _p: tuple
    signed_bodies: tuple = ()

    def kinematics(self, t_: float, q, qd) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(x, J, a0, xdot, x_t)`` at a state: positions (K, 3), ``J = ∂x/∂q`` (3K, n), the bias ``a0`` with
        ``ẍ = J q̈ + a0`` (3K,), the velocities ``ẋ`` (3K,) and their explicit-time part ``∂x/∂t`` (3K,)."""
        X, JX, aX, vX, tX = (np.asarray(a, dtype=float) for a in self._kin(t_, list(q), list(qd), self._p))
        B = self._E.shape[1]
        E = self._E
        return ((E @ X.reshape(B)).reshape(-1, 3), E @ JX.reshape(B, self.n), E @ aX.reshape(B),
                E @ vX.reshape(B), E @ tX.reshape(B))

    def forces(self, t_: float, q, qd) -> dict[str, np.ndarray]:
        """Generalized force data: ``Q`` (n,), its non-potential part ``Q_nc`` (n,), ``V``, ``dV_dt`` (explicit),
        and the constraints ``A`` (m, n), ``c`` (m,) with ``A q̈ = c``, ``b`` (m,) with ``A q̇ + b = 0``,
        ``phi`` (holonomic values, NaN for non-holonomic rows)."""
        vals = self._data(t_, list(q), list(qd), self._p)
        Qc, Qnc, V, Vt, A, c, b, phi = (np.asarray(v, dtype=float) for v in vals)
        return {"Q": (Qc + Qnc).reshape(self.n), "Q_nc": Qnc.reshape(self.n), "V": float(V), "dV_dt": float(Vt),
                "A": A.reshape(self.m, self.n), "c": c.reshape(self.m), "b": b.reshape(self.m),
                "phi": phi.reshape(self.m)}

    @property
    def mass_vector(self) -> np.ndarray:
        return np.repeat(self.masses, 3)


def _numeric(expr, values: dict, what: str) -> float:
    e = _sympify(expr).xreplace(values)
    try:
        return float(e)
    except TypeError:
        raise ParameterError(f"{what} = {expr} needs values for {', '.join(sorted(map(str, e.free_symbols)))}") \
            from None


def _bodies(system, values) -> tuple[list, list, list]:
    """Base expressions; points as (base offset, weights, mass, label); bodies with signed pseudo-masses."""
    base, points, signed = [], [], []
    for k, body in enumerate(system.bodies):
        if system.prescribed:
            body = body.subs(system.prescribed)
        label = body.name or f"body {k + 1}"
        if isinstance(body, Particle):
            m = _numeric(body.mass, values, f"mass of {label}")
            if m == 0:
                continue
            points.append((len(base), np.array([1.0]), m, label))
            base += list(body.position)
        elif isinstance(body, RigidBody):
            m = _numeric(body.mass, values, f"mass of {label}")
            J_O = np.array([[_numeric(v, values, f"inertia of {label}") for v in row] for row in body.inertia.tolist()])
            c = np.array([_numeric(v, values, f"centre of mass of {label}") for v in body.com])
            J_c = J_O - m * (c @ c * np.eye(3) - np.outer(c, c))
            if m == 0 and not np.any(J_c):
                continue
            off = len(base)
            base += list(body.origin) + list(body.R.T.reshape(9, 1))  # origin, then the columns of R
            offsets, pm = equimomental_offsets(m, J_c)
            if np.any(pm < 0):
                signed.append(label)
            for r, mk in zip(offsets + c, pm):
                if mk != 0:
                    points.append((off, np.concatenate([[1.0], r]), float(mk), label))
        else:
            raise NotApplicable(f"{label} is a {type(body).__name__}, not a particle or rigid body")
    return base, points, signed


def _selection(points, B) -> tuple[np.ndarray, np.ndarray, tuple]:
    E = np.zeros((3 * len(points), B))
    for k, (off, w, _, _) in enumerate(points):
        for j, wj in enumerate(w):
            E[3 * k:3 * k + 3, off + 3 * j:off + 3 * j + 3] += wj * np.eye(3)
    return E, np.array([p[2] for p in points]), tuple(p[3] for p in points)


def _bind(exprs, coords, params: Mapping) -> tuple[list, tuple]:
    qsyms = {position_symbol(q) for q in coords} | {velocity_symbol(q) for q in coords}
    free = set().union(*(_sympify(e).free_symbols for e in exprs)) - qsyms - {t}
    by_name = {(k.name if isinstance(k, sp.Symbol) else str(k)): v for k, v in params.items()}
    syms = sorted(free, key=lambda s: s.name)
    missing = [s.name for s in syms if s.name not in by_name]
    if missing:
        raise ParameterError(f"missing value(s) for parameter(s) {', '.join(missing)}")
    return syms, tuple(_float(by_name[s.name], s.name) for s in syms)


def _float(value, name: str) -> float:
    """The number a parameter value stands for (a string is read by the spec parser, never evaluated);
    ParameterError otherwise."""
    try:
        return float(_sympify(value, where=f"parameter {name}"))
    except LagrangeError:
        raise
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(f"parameter {name} = {shown(value)} is not a number") from None


def mass_point_model(system, params: Mapping) -> MassPointModel:
    """Build the :class:`MassPointModel` of ``system`` with parameter values ``params``.

    Raises
    ------
    NotApplicable
        T is (partly) given directly, a body is neither a particle nor a rigid body, an inertia is not
        physical, or a constraint is rough (its friction depends on the reaction).
    ParameterError
        A parameter value is missing.
    """
    if system.T_given != 0:
        raise NotApplicable("T given directly" + (" for part of the system" if system.bodies else "")
                            + ": no kinematics to represent by mass points")
    if any(c.friction is not None for c in system.constraints):
        raise NotApplicable("rough constraint: its friction depends on the normal reaction (Gauss' principle "
                            "here covers ideal constraints)")
    coords = system.coordinates
    by_name = {(k.name if isinstance(k, sp.Symbol) else str(k)): v for k, v in params.items()}
    values = {s: sp.Float(_float(by_name[s.name], s.name)) for s in _all_symbols(system) if s.name in by_name}
    base, points, signed = _bodies(system, values)
    if not points:
        raise NotApplicable("no massive particle or rigid body")
    E, masses, labels = _selection(points, len(base))
    X = sp.Matrix(base)
    Xd = X.diff(t)
    Xdd = Xd.diff(t)
    qs = [position_symbol(q) for q in coords]
    qds = [velocity_symbol(q) for q in coords]
    Xs, Xds, Xdds = (to_symbols(e, coords) for e in (X, Xd, Xdd))
    zero_dd = {to_symbols(q.diff(t, 2), coords): 0 for q in coords}
    kin = [Xs, Xs.jacobian(qs), Xdds.xreplace(zero_dd), Xds, Xds.xreplace({v: 0 for v in qds})]
    data = _force_data(system, coords, qs, qds)
    syms, pvals = _bind([e for M in kin for e in M] + [e for M in data for e in sp.Matrix([M])], coords, params)
    args = (t, qs, qds, syms)
    kin_f = _lambdify(args, kin, modules="numpy", cse=True)
    data_f = _lambdify(args, data, modules="numpy", cse=True)
    return MassPointModel(masses, labels, len(coords), len(system.constraints),
                          tuple(c.name for c in system.constraints), E, kin_f, data_f, pvals, tuple(signed))


def declared_symbols(system) -> set:
    """Every parameter symbol the mass-point route may need: in the bodies (positions, masses, inertia,
    orientation), V, P, D, the forces and the constraints — a superset of ``system.parameters``, which
    lists only those that survive in the equations of motion (a constant offset in a position does not)."""
    exprs = [system.V, system.P, system.rayleigh, *system.forces.values(),
             *(c.velocity for c in system.constraints), *system.prescribed.values()]
    for b in system.bodies:
        exprs += list(b.position_vectors()) + [getattr(b, "mass", 0)]
        if isinstance(b, RigidBody):
            exprs += [b.inertia, b.com, b.R]
    out = set().union(*(_sympify(e).free_symbols for e in exprs))
    return {s for s in out if s != t and not s.name.startswith("delta_")}


def _all_symbols(system) -> set:
    out = set()
    for b in system.bodies:
        for attr in ("mass", "inertia", "com"):
            if hasattr(b, attr):
                out |= _sympify(getattr(b, attr)).free_symbols
    return out


def _force_data(system, coords, qs, qds) -> list:
    V = to_symbols(system.V, coords)
    P = to_symbols(system.P, coords)
    D = to_symbols(system.rayleigh, coords)
    Fq = [to_symbols(system.forces.get(q, 0), coords) for q in coords]
    Qc = sp.Matrix([-sp.diff(V, s) for s in qs])
    Qnc = sp.Matrix([sp.diff(P, v) - sp.diff(D, v) + F for v, F in zip(qds, Fq)])
    n, m = len(coords), len(system.constraints)
    A, c, b, phi = sp.zeros(m, n), sp.zeros(m, 1), sp.zeros(m, 1), sp.zeros(m, 1)
    for k, spec in enumerate(system.constraints):
        g = to_symbols(spec.velocity, coords)
        row = [sp.diff(g, v) for v in qds]
        A[k, :] = sp.Matrix([row])
        c[k] = -(sum((sp.diff(g, s) * v for s, v in zip(qs, qds)), sp.S.Zero) + sp.diff(g, t))
        b[k] = g.xreplace({v: 0 for v in qds})
        phi[k] = to_symbols(spec.position, coords) if spec.position is not None else sp.nan
    return [Qc, Qnc, V, sp.diff(V, t), A, c, b, phi]
