r"""Two-way interop with :mod:`sympy.physics.mechanics`.

* :func:`from_mechanics` reads a ``LagrangesMethod``, a ``KanesMethod``, a mechanics ``System``
  (sympy ≥ 1.13) or a Lagrangian with its coordinates, and returns a :class:`lagrange.System` whose
  equations agree with sympy's.
* :func:`to_mechanics` (also :meth:`lagrange.System.to_mechanics`) returns a ``LagrangesMethod`` whose
  equations agree with lagrange's.

Time. sympy's ``dynamicsymbols`` are functions of ``Symbol('t')``; lagrange's time is the real
:data:`lagrange.t`. Everything read from sympy has its time replaced by :data:`lagrange.t`
(:func:`lagrange.model.coordinates.normalize_time`), and everything written to sympy the other way round,
so the coordinates keep their names and the equations the same form.

Energies. A Lagrangian is split as ``V = −L(q, q̇ = 0, t)`` and ``T = L + V`` (the velocity-dependent part).
The equations and the Jacobi integral do not depend on the split; ``System.energy()`` is T + V, the true
energy when nothing moves with time.

Kane's models (``KanesMethod``, mechanics ``System``) are converted through their bodies and loads:
``T = Σ body.kinetic_energy(frame)``, ``V = Σ body.potential_energy``, each load gives the generalized
force ``Q_r = F · ∂v_P/∂q̇_r`` (``τ · ∂ω_B/∂q̇_r`` for a torque), after the generalized speeds are
replaced by their expressions in q and q̇ from the kinematic differential equations (the speeds may be any
invertible linear map of q̇, body-frame angular velocity components for instance). Configuration
constraints become :class:`~lagrange.Holonomic` and velocity constraints :class:`~lagrange.Nonholonomic`,
except the velocity constraints that are combinations of the time derivatives of the configuration
constraints (Kane's models list them again to choose the dependent speeds): those are dropped, as they
would be redundant rows. This is only sound when every velocity in the model is the time derivative of a
position in the coordinates, so :func:`from_mechanics` checks it: a model that builds a non-holonomic
constraint into its kinematics (sympy's rolling disc sets the contact point's velocity to zero instead of
declaring the contact coordinates and the rolling constraints) is refused, as are auxiliary speeds. Its
Kane's equations are right, but no Lagrangian T(q, q̇) has them. The kinematic residues of these checks
(and the span test of the velocity constraints) are evaluated at random points in double precision, to
``1e-9`` of the size of their terms: with body-frame speeds they are long trigonometric sums that cancel,
too long to expand or simplify.

Specified quantities. sympy's specifieds (functions of time in the loads that are neither coordinates nor
speeds, e.g. the cart force ``dynamicsymbols('F')`` of ``n_link_pendulum_on_cart``) become lagrange inputs
of the same name (:func:`lagrange.inputs`), whose values are given at simulate time; the other way,
:func:`to_mechanics` turns every input back into a specified ``dynamicsymbols(name)``, so sympy's
``linearize`` finds it and returns its column of B. A load with the time derivative of a specified is
refused (an input has none).

The other way, lagrange's non-potential generalized forces ``F_q + ∂P/∂q̇ − ∂D/∂q̇`` reach
``LagrangesMethod`` as a force ``F_q`` along ``N.x`` at an auxiliary point whose velocity is ``q̇_r N.x``
(partial velocity 1 for q_r, 0 for the others). Rough and unilateral constraints have no counterpart there
and are refused.
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy as sp
from sympy.core.function import AppliedUndef

from ..conventions import t
from ..errors import DeclarationError
from ..model.constraints import Holonomic, Nonholonomic
from ..model.coordinates import SYMPY_TIME, coordinate_name, normalize_time
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, simplify

__all__ = ["from_mechanics", "to_mechanics"]


def _me():
    import sympy.physics.mechanics as me

    return me


# ------------------------------------------------------------------------------------------ from sympy

def from_mechanics(obj, coordinates: Sequence | None = None, *, name: str = "", **system_options):
    """A :class:`lagrange.System` from a :mod:`sympy.physics.mechanics` model.

    Parameters
    ----------
    obj : LagrangesMethod, KanesMethod, sympy.physics.mechanics.System, or a Lagrangian expression
        For a Lagrangian, ``coordinates`` must be given. A ``LagrangesMethod`` brings its Lagrangian,
        coordinates, loads (``forcelist`` with its ``frame``) and holonomic and non-holonomic constraints; Kane's
        models their bodies, loads, kinematic differential equations and constraints (see the module notes).
        Specifieds in the loads become inputs of the same names.
    coordinates : sequence of dynamicsymbols (or lagrange coordinates), only with a Lagrangian
    name : str, optional
    **system_options
        Passed on to :class:`lagrange.System` (``forces``, ``rayleigh``, ``P``, ``constraints``, ``parameters``
        …); only with a Lagrangian.

    Returns
    -------
    System
        In lagrange's time :data:`lagrange.t`; the coordinates keep their names.

    Raises
    ------
    DeclarationError (a ValueError)
        An object of another type, a Kane's model whose kinematics are not holonomic (a velocity that is not
        the time derivative of a position in the coordinates, an angular velocity that does not match the
        orientation), auxiliary speeds, or loads that are not forces at points or torques on frames.
    """
    me = _me()
    if isinstance(obj, me.LagrangesMethod):
        _no_options(obj, coordinates, system_options)
        return _from_lagranges_method(obj, name)
    if isinstance(obj, me.KanesMethod):
        _no_options(obj, coordinates, system_options)
        if len(obj._uaux):
            raise DeclarationError("KanesMethod with auxiliary speeds: they have no place in Lagrange's equations; "
                                   "build the model without u_auxiliary")
        q, u = list(obj.q), list(obj.u)
        qd = [c.diff(SYMPY_TIME) for c in q]
        kdes = list(obj._k_ku * obj.u + obj._k_kqdot * sp.Matrix(qd) + obj._f_k)
        nonhol = list(obj._k_nh * obj.u + obj._f_nh) if len(obj._f_nh) else []
        return _from_kane_model(obj._inertial, q, u, kdes, obj.bodies or (), obj.loads or (), list(obj._f_h),
                                nonhol, name or "from KanesMethod")
    if isinstance(obj, me.System):
        _no_options(obj, coordinates, system_options)
        if len(obj.u_aux):
            raise DeclarationError("mechanics System with auxiliary speeds: build it without u_aux")
        loads = tuple(obj.loads) + tuple(load for act in obj.actuators for load in act.to_loads())
        return _from_kane_model(obj.frame, list(obj.q), list(obj.u), list(obj.kdes), obj.bodies, loads,
                                list(obj.holonomic_constraints), list(obj.nonholonomic_constraints),
                                name or "from mechanics System")
    if isinstance(obj, (sp.Expr, int, float)) and not isinstance(obj, bool):
        if coordinates is None:
            raise DeclarationError("from_mechanics(L) needs the coordinates: from_mechanics(L, [q1, q2])")
        T, V = _split_lagrangian(normalize_time(_sympify(obj)), normalize_time(list(coordinates)))
        return _system(coordinates, T, V, name=name, **system_options)
    raise DeclarationError(f"from_mechanics: cannot read {type(obj).__name__}: give a LagrangesMethod, a KanesMethod, "
                           "a sympy.physics.mechanics.System or a Lagrangian with its coordinates")


def _no_options(obj, coordinates, options) -> None:
    if coordinates is not None or options:
        extra = ["coordinates"] * (coordinates is not None) + sorted(options)
        raise TypeError(f"from_mechanics({type(obj).__name__}) takes no {', '.join(extra)}: the model brings them")


def _system(coordinates, T, V, **options):
    from .. import System  # through the package's lazy table: model.system imports this module (to_mechanics)

    return System(list(coordinates), T=T, V=V, **options)


def _split_lagrangian(L, coords) -> tuple:
    """``(T, V)`` with ``V = −L(q, q̇ = 0, t)`` and ``T = L + V``."""
    rest = L.subs({c.diff(t): 0 for c in coords})
    return sp.expand(L - rest) if rest != 0 else L, -rest


def _from_lagranges_method(lm, name: str):
    q = list(lm.q)
    forces = {}
    if lm.forcelist:
        if lm.inertial is None:
            raise DeclarationError("LagrangesMethod with loads but no frame: its generalized forces need the "
                                   "inertial frame (LagrangesMethod(..., frame=N))")
        qd = [c.diff(SYMPY_TIME) for c in q]
        forces = _specifieds_to_inputs(_generalized_forces(lm.forcelist, lm.inertial, q, qd, {}), q)
    constraints = [Holonomic(e, f"holonomic {k + 1}") for k, e in enumerate(lm._hol_coneqs)]
    n_hol = len(lm._hol_coneqs)
    constraints += [Nonholonomic(e, f"non-holonomic {k + 1}") for k, e in enumerate(lm.coneqs[n_hol:])]
    T, V = _split_lagrangian(normalize_time(lm._L[0]), normalize_time(q))
    return _system(q, T, V, forces=normalize_time(forces) or None, constraints=constraints,
                   name=name or "from LagrangesMethod")


def _load_parts(load):
    me = _me()
    if isinstance(load, (me.Force, me.Torque)):
        return load.location, load.vector
    if isinstance(load, (tuple, list)) and len(load) == 2:
        return load[0], load[1]
    raise DeclarationError(f"load {load!r} is neither a force at a point nor a torque on a frame")


def _generalized_forces(loads, N, q, qd, u_map) -> dict:
    """``{q_r: Σ F·∂v_P/∂q̇_r + Σ τ·∂ω_B/∂q̇_r}`` with speeds replaced by ``u_map``."""
    me = _me()
    out = {c: sp.S.Zero for c in q}
    for load in loads:
        where, vec = _load_parts(load)
        if not isinstance(where, (me.Point, me.ReferenceFrame)):
            raise DeclarationError(f"load {load!r} is applied to {where!r}, neither a Point nor a ReferenceFrame")
        motion = _motion(where, N)
        motion = motion.subs(u_map) if u_map else motion
        vec = vec.subs(u_map) if u_map else vec
        for c, v in zip(q, qd):
            out[c] += sp.expand(vec.dot(motion.diff(v, N, var_in_dcm=False)))
    return out


def _specifieds_to_inputs(forces: dict, known) -> dict:
    """``forces`` with sympy's specifieds (functions of time in the loads that are not coordinates or speeds,
    e.g. ``dynamicsymbols('F')``) replaced by lagrange inputs of the same name (:func:`lagrange.inputs`), whose
    values are given at simulate time. A load with the derivative of a specified is refused: an input has
    none."""
    from ..model.inputs import inputs

    known = set(known)
    found: set = set()
    for e in forces.values():
        for d in _sympify(e).atoms(sp.Derivative):
            if isinstance(d.expr, AppliedUndef) and d.expr not in known:
                raise DeclarationError(f"from_mechanics: a load contains {d}, the derivative of the specified "
                                       f"{d.expr}: a lagrange input has no derivative; make the load a function of "
                                       f"{d.expr} itself, or give {d.expr} as a coordinate")
        found |= {f for f in _sympify(e).atoms(AppliedUndef) if f.args == (SYMPY_TIME,) and f not in known}
    if not found:
        return forces
    to_input = {f: inputs(f.func.__name__) for f in found}
    return {c: _sympify(e).xreplace(to_input) for c, e in forces.items()}


def _motion(where, N):
    """The velocity of a point or the angular velocity of a frame in N; a DeclarationError when undefined."""
    me = _me()
    try:
        return where.vel(N) if isinstance(where, me.Point) else where.ang_vel_in(N)
    except ValueError as exc:
        raise DeclarationError(f"from_mechanics: the motion of {where.name} in {N.name} is not defined "
                               f"({exc})") from None


def _u_map(q, u, kdes) -> dict:
    """The speeds in terms of q and q̇ from the kinematic differential equations (linear in u)."""
    if not u:
        return {}
    if len(kdes) != len(u):
        raise DeclarationError(f"{len(u)} generalized speeds but {len(kdes)} kinematic differential equations")
    A, b = sp.linear_eq_to_matrix(list(kdes), list(u))
    sol = A.LUsolve(b)
    return dict(zip(u, (simplify(s, limit=39) for s in sol)))  # bounded clean-up (lagrange.limits)


def _from_kane_model(N, q, u, kdes, bodies, loads, hol, nonhol, name):
    me = _me()
    qd = [c.diff(SYMPY_TIME) for c in q]
    if not bodies:
        raise DeclarationError(f"{name}: the model has no bodies, so it has no kinetic energy (give them to "
                               "kanes_equations(bodies, loads) or System.add_bodies)")
    u_map = _u_map(q, u, kdes)
    T, V = sp.S.Zero, sp.S.Zero
    for body in bodies:
        T += body.kinetic_energy(N)
        V += _sympify(getattr(body, "potential_energy", 0))
        _check_point(body.masscenter, N, q, qd, u_map, f"the mass centre of {body.name}")
        if isinstance(body, me.RigidBody):
            _check_frame(body.frame, N, q, qd, u_map, f"the frame of {body.name}")
    for load in loads:
        where, _ = _load_parts(load)
        if isinstance(where, me.Point):
            _check_point(where, N, q, qd, u_map, f"the point {where.name} of a load")
        elif isinstance(where, me.ReferenceFrame):
            _check_frame(where, N, q, qd, u_map, f"the frame {where.name} of a torque")
    T = T.subs(u_map) if u_map else T
    forces = _specifieds_to_inputs(_generalized_forces(loads, N, q, qd, u_map), q + list(u))
    constraints = [Holonomic(e, f"configuration {k + 1}") for k, e in enumerate(hol)]
    rows = [sp.expand(e.subs(u_map) if u_map else e) for e in nonhol]
    implied = _implied_by_configuration(rows, hol, q, qd)
    constraints += [Nonholonomic(e, f"velocity {k + 1}") for k, e in enumerate(rows) if not implied[k]]
    return _system(q, normalize_time(T), normalize_time(V), forces=normalize_time(forces), constraints=constraints,
                   name=name)


def _implied_by_configuration(rows, hol, q, qd) -> list[bool]:
    """For each velocity constraint ``a·q̇ + b = 0``: is it a combination of the time derivatives of the
    configuration constraints (``J q̇ + ∂φ/∂t``)? Kane's models list those derivatives again as velocity
    constraints (to choose the dependent speeds); kept, they would be redundant rows. The row ``[a, b]`` must lie
    in the span of ``[J, ∂φ/∂t]`` at random points (ranks to ``_RTOL``)."""
    import numpy as np

    if not hol or not rows:
        return [False] * len(rows)
    qs, vs, plain = _plain(q, qd)
    ts = sp.Dummy("t")

    def flat(e):
        return _sympify(e).xreplace(plain).xreplace({SYMPY_TIME: ts})

    def block(es):
        return [[sp.diff(e, s) for s in vs] + [e.xreplace(dict.fromkeys(vs, 0))] for e in es]

    phis = [flat(e) for e in hol]
    base = [[sp.diff(p, s) for s in qs] + [sp.diff(p, ts)] for p in phis]
    rows_p = block([flat(e) for e in rows])
    everything = sp.Matrix(base + rows_p)
    if everything.atoms(AppliedUndef, sp.Derivative):
        return [False] * len(rows)
    args = sorted(everything.free_symbols - set(vs), key=sp.default_sort_key)
    try:
        f = _lambdify(args, everything, "numpy", cse=True)
    except (TypeError, ValueError, NameError, AttributeError):
        return [False] * len(rows)  # not evaluable: every row is kept (a row is dropped only when shown implied)
    rng = np.random.default_rng(11)
    implied, good = [True] * len(rows), 0
    for _ in range(4 * _POINTS):
        try:
            with np.errstate(all="ignore"):
                m = np.array(f(*rng.uniform(0.2, 1.3, len(args))), dtype=complex)
        except (TypeError, ValueError, NameError, AttributeError, ZeroDivisionError, OverflowError):
            return [False] * len(rows)
        if not np.all(np.isfinite(m)):
            continue
        good += 1
        B = m[:len(base)]
        tol = _RTOL * max(float(np.abs(m).max()), 1e-300) * m.shape[1]
        r0 = np.linalg.matrix_rank(B, tol=tol)
        for k in range(len(rows)):
            if np.linalg.matrix_rank(np.vstack([B, m[len(base) + k]]), tol=tol) > r0:
                implied[k] = False
        if good == _POINTS:
            return implied
    return [False] * len(rows)


def _plain(q, qd):
    """Plain symbols for q and q̇ (derivatives first), and the map."""
    qs = [sp.Dummy(f"q{k}") for k in range(len(q))]
    vs = [sp.Dummy(f"v{k}") for k in range(len(q))]
    return qs, vs, {**dict(zip(qd, vs)), **dict(zip(q, qs))}


def _non_holonomic_refusal(what: str, detail: str) -> DeclarationError:
    return DeclarationError(
        f"from_mechanics: {what} {detail}: the model builds a non-holonomic constraint into its kinematics "
        "(e.g. rolling without slipping with the contact point's velocity set to zero), which no Lagrangian "
        "T(q, q̇) can carry; declare the contact coordinates as coordinates and the rolling conditions as "
        "velocity constraints (lagrange.Nonholonomic), or keep this model in KanesMethod")


def _check_point(P, N, q, qd, u_map, what: str) -> None:
    """The velocity of P in N must be exact: ``v = Σ a_j(q, t) q̇_j + b(q, t)`` with ``∂a_j/∂q_k = ∂a_k/∂q_j``
    and ``∂a_j/∂t = ∂b/∂q_j`` in every inertial component — the time derivative of a position r(q, t). (A point
    whose velocity is set to zero need not be fixed, a contact point is not: positions are not trusted.)"""
    v = _motion(P, N)
    v = v.subs(u_map) if u_map else v
    qs, vs, plain = _plain(q, qd)
    ts = sp.Dummy("t")
    for axis in (N.x, N.y, N.z):
        c = v.dot(axis).xreplace(plain).xreplace({SYMPY_TIME: ts})  # not expanded: body-frame speeds bloat it
        if c.atoms(AppliedUndef):
            raise _non_holonomic_refusal(what, f"has a velocity in {sorted(map(str, c.atoms(AppliedUndef)))}, which "
                                         "are not coordinates or speeds of the model")
        a = [sp.diff(c, s) for s in vs]
        b = c.xreplace(dict.fromkeys(vs, 0))
        if not _vanishes(c - sum(ai * s for ai, s in zip(a, vs)) - b):
            raise _non_holonomic_refusal(what, "has a velocity that is not linear in q̇")
        for j in range(len(q)):
            residues = [sp.diff(a[j], ts) - sp.diff(b, qs[j])]
            residues += [sp.diff(a[j], qs[k]) - sp.diff(a[k], qs[j]) for k in range(j + 1, len(q))]
            if not all(_vanishes(r) for r in residues):
                raise _non_holonomic_refusal(
                    what, f"moves with a velocity along {axis} that is not the time derivative of any position in "
                    f"the coordinates ({', '.join(map(str, q))})")


#: random points, and the relative size (to the sum of its terms' magnitudes) under which a residue is zero
_POINTS, _RTOL = 6, 1e-9


def _vanishes(r) -> bool:
    """Zero, or zero at random points to ``_RTOL`` of the size of its terms. Body-frame speeds make the kinematic
    residues long sums of trigonometric products that cancel, too long to expand or simplify; an expression that
    is not identically zero vanishes at random points with probability zero. When no point can be evaluated
    (a function numpy lacks, a value defined nowhere in the sampled box) the bounded symbolic test decides."""
    if r == 0:
        return True
    verdict = _zero_at_random_points(r)
    return is_zero(r) if verdict is None else verdict


def _zero_at_random_points(r) -> bool | None:
    """True when ``r`` vanishes at ``_POINTS`` random points, False at the first point where it does not, None
    when it cannot be evaluated at enough points."""
    import numpy as np

    # functions of time and their derivatives take independent values at one instant
    stand_in = {a: sp.Dummy() for a in r.atoms(sp.Derivative, AppliedUndef)}
    r = r.xreplace(stand_in)
    args = sorted(r.free_symbols, key=sp.default_sort_key)
    rng = np.random.default_rng(7)
    good = 0
    try:
        f = _lambdify(args, list(sp.Add.make_args(r)), "numpy", cse=True)
        for _ in range(4 * _POINTS):
            with np.errstate(all="ignore"):
                terms = np.array(f(*rng.uniform(0.2, 1.3, len(args))), dtype=complex)
            value, scale = terms.sum(), np.abs(terms).sum()
            if not (np.isfinite(value) and np.isfinite(scale)):
                continue
            if abs(value) > _RTOL * max(abs(scale), 1e-300):
                return False
            good += 1
            if good == _POINTS:
                return True
    except (TypeError, ValueError, NameError, AttributeError, ZeroDivisionError, OverflowError):
        return None
    return None


def _check_frame(B, N, q, qd, u_map, what: str) -> None:
    """The angular velocity of B in N must be the one its orientation gives (``Ṙ Rᵀ``)."""
    w = _motion(B, N)
    w = w.subs(u_map) if u_map else w
    try:
        true = B._w_diff_dcm(N)
    except (ValueError, AttributeError, TypeError):
        raise _non_holonomic_refusal(what, "has no orientation relative to the inertial frame") from None
    for axis in (N.x, N.y, N.z):
        if not _vanishes((w - true).dot(axis)):
            raise _non_holonomic_refusal(what, f"turns with an angular velocity along {axis} that differs from the "
                                         "time derivative of its orientation")


# -------------------------------------------------------------------------------------------- to sympy

def to_mechanics(system):
    """A formed ``sympy.physics.mechanics.LagrangesMethod`` with the equations of ``system``.

    ``L = T − V`` in sympy's time ``dynamicsymbols._t``; the non-potential generalized forces
    ``F_q + ∂P/∂q̇ − ∂D/∂q̇`` enter as forces along ``N.x`` at auxiliary points moving with ``q̇_r N.x``
    (see the module notes); holonomic constraints ``φ = 0`` go to ``hol_coneqs`` and non-holonomic ones
    ``A q̇ + b = 0`` to ``nonhol_coneqs``. ``form_lagranges_equations()`` has been called, so
    ``mass_matrix_full``, ``forcing_full`` and ``rhs()`` are ready. The coordinates are
    ``dynamicsymbols`` with the names of the system's coordinates, and each input (:func:`lagrange.inputs`) is
    the specified ``dynamicsymbols(name)``, so ``linearize(..., A_and_B=True)`` gives its column of B.

    Raises
    ------
    DeclarationError (a ValueError)
        Rough (friction) or unilateral constraints: LagrangesMethod has neither.
    """
    me = _me()
    rough = [c.name for c in system.constraints if c.friction is not None]
    one_sided = [c.name for c in system.constraints if c.unilateral]
    if rough or one_sided:
        parts = ([f"rough constraints ({', '.join(rough)})"] if rough else []) + (
            [f"unilateral constraints ({', '.join(one_sided)})"] if one_sided else [])
        raise DeclarationError(f"to_mechanics: {' and '.join(parts)} have no counterpart in LagrangesMethod")
    ts = me.dynamicsymbols._t
    # each coordinate becomes sympy's dynamicsymbols(name) (no assumptions), time becomes dynamicsymbols._t
    back = {t: ts, **{c: sp.Function(coordinate_name(c))(ts) for c in system.coordinates},
            **{u: sp.Function(u.name)(ts) for u in system.inputs}}  # inputs become sympy's specifieds

    def s(e):
        return _sympify(e).xreplace(back)

    q = [s(c) for c in system.coordinates]
    N = me.ReferenceFrame("N")
    forcelist = []
    for c, Q in system.generalized_forces().items():
        if Q != 0:
            P = me.Point(f"P_{coordinate_name(c)}")
            P.set_vel(N, s(c.diff(t)) * N.x)
            forcelist.append((P, s(Q) * N.x))
    hol = [s(c.position) for c in system.constraints if c.kind == "holonomic"]
    nonhol = [s(c.velocity) for c in system.constraints if c.kind != "holonomic"]
    lm = me.LagrangesMethod(s(system.T - system.V), q, forcelist=forcelist or None, frame=N,
                            hol_coneqs=hol or None, nonhol_coneqs=nonhol or None)
    lm.form_lagranges_equations()
    return lm
