r"""Lagrange's equations that follow the system's structure: kinematics per body, assembled numerically.

For a system whose kinetic energy comes wholly from bodies — point masses at ``x_p(q, t)`` and rigid bodies
with centre of mass ``x_b(q, t)``, body-axis angular velocity ``ω_b = W_b q̇ + ω_t,b`` and inertia ``I_b`` about
the centre of mass along the body axes — Lagrange's left side ``d/dt ∂T/∂q̇ − ∂T/∂q`` of
``T = Σ ½ m |ẋ|² + Σ ½ ωᵀ I ω`` is (Kane & Levinson 1985, ch. 6; Featherstone, *Rigid Body Dynamics
Algorithms*, 2008, ch. 6 for the composite form)

.. math::

    M &= \sum_p m_p J_p^{\mathsf T} J_p + \sum_b W_b^{\mathsf T} I_b W_b, \\
    f &= Q - \sum_p m_p J_p^{\mathsf T} a_p
          - \sum_b W_b^{\mathsf T}\,(I_b \alpha_b + \omega_b \times I_b \omega_b),

with ``J_p = ∂x_p/∂q``, ``v_p = J_p q̇ + ∂x_p/∂t``, the velocity-product (and moving-frame) part of the
acceleration ``a_p = Σ_r ∂v_p/∂q_r q̇_r + ∂v_p/∂t``, likewise ``α_b = Σ_r ∂ω_b/∂q_r q̇_r + ∂ω_b/∂t``, and
``Q = −∂V/∂q + F + ∂P/∂q̇ − ∂D/∂q̇`` (:mod:`lagrange.conventions`). The rigid-body term uses Euler's equations
along the body axes, which hold because ``ω_b`` is the angular velocity of an orthogonal ``R(q, t)`` at every
q (``d/dt ∂ω/∂q̇_r − ∂ω/∂q_r = ∂ω/∂q̇_r × ω``); a rigid body's kinetic energy about its origin O (Wells 8.10)
is the same T written about the centre of mass (parallel-axis theorem,
``I_c = J_O − m(|r̄|² E − r̄ r̄ᵀ)``). The equations are identical in value to
:func:`lagrange.derive.lagrange.lagrange_equations`; only J, a, W, α and Q are formed symbolically — no
expanded T, no second derivatives of it — and generated code assembles M and f with small matrix products
(:mod:`lagrange.codegen.structural_source`).

:class:`StructuralEquations` carries the frozen :class:`Structure`; its fields ``mass_matrix``, ``forcing``,
``inertial``, ``kinetic`` and ``jacobi`` are today's expanded equations, derived on first access (cached), so
every analysis sees the same equations as with ``derivation="expanded"``, while compiling and simulating read
only the structure.
"""

from __future__ import annotations

from dataclasses import fields, replace

import sympy as sp

from ..conventions import POWER_FUNCTION_SIGN, RAYLEIGH_SIGN, t
from ..errors import DeclarationError
from ..model.bodies import Particle
from ..model.coordinates import acceleration_symbol, position_symbol, to_symbols, velocity_symbol
from ..model.inputs import is_input
from ..model.rigid_body import RigidBody
from ..records import record
from .derivation_choice import DERIVATIONS, structural_refusal  # noqa: F401 - re-exported (__all__)
from .equations import Equations
from .lagrange import _tidy_force, gradient
from .multipliers import constraint_blocks

__all__ = ["PointMass", "Rotor", "Structure", "StructuralEquations", "structural_equations",
           "structural_refusal", "DERIVATIONS"]


@record(frozen=True)
class PointMass:
    """A particle, or a rigid body's centre of mass: ``mass``, the nonzero entries ``((i, j), ∂x_i/∂q_j)`` of
    J (``i`` the Cartesian component 0–2), ``velocity_bias`` ``∂x/∂t`` and ``acceleration_bias`` ``a`` (3 each),
    in plain symbols."""

    mass: sp.Expr
    jacobian: tuple
    velocity_bias: tuple
    acceleration_bias: tuple
    name: str = ""


@record(frozen=True)
class Rotor:
    """A rigid body's rotation: ``inertia`` (3×3 tensor about the centre of mass, body axes), the nonzero
    entries ``((i, j), ∂ω_i/∂q̇_j)`` of W, ``omega_bias`` ``ω_t`` and ``acceleration_bias`` ``α`` (body axes)."""

    inertia: sp.ImmutableMatrix
    jacobian: tuple
    omega_bias: tuple
    acceleration_bias: tuple
    name: str = ""


@record(frozen=True)
class Structure:
    """What generated code needs to assemble ``M q̈ = f``: the point masses, the rotors and
    ``generalized_force`` ``Q`` (n expressions). T in the compact per-body form (not expanded) follows from them
    (:meth:`kinetic_parts`)."""

    points: tuple
    rotors: tuple
    generalized_force: tuple

    def kinetic_parts(self, qd) -> tuple:
        """``(T, T₂, T₀)`` in the compact per-body form: ``T = Σ ½ m |J q̇ + ∂x/∂t|² + Σ ½ ωᵀIω``, ``T₂`` its part
        quadratic in the velocities, ``T₀`` its part free of them."""
        return _kinetic_parts(self.points, self.rotors, qd)

    def has_time(self) -> bool:
        """Whether t appears explicitly in the kinematics (a moving frame, a prescribed motion)."""
        return any(t in e.free_symbols for e in self.expressions()[len(self.generalized_force):])

    def expressions(self) -> list:
        """Every expression of the structure (for free symbols and explicit time)."""
        out = list(self.generalized_force)
        for p in self.points:
            out += [p.mass, *(e for _, e in p.jacobian), *p.velocity_bias, *p.acceleration_bias]
        for r in self.rotors:
            out += [*r.inertia, *(e for _, e in r.jacobian), *r.omega_bias, *r.acceleration_bias]
        return [sp.sympify(e) for e in out]


def _positions(xs: list, q, qd) -> list:
    """``(J row, ∂x/∂t, a)`` of each position expression ``x(q, t)`` (plain symbols): ``J = ∂x/∂q`` (list of n),
    ``a = Σ_r ∂v/∂q_r q̇_r + ∂v/∂t`` with ``v = J q̇ + ∂x/∂t``."""
    return _kinematics(xs, q, qd, velocity=False)


def _rates(ws: list, q, qd) -> list:
    """``(W row, ω_t, α)`` of each expression ``ω(q, q̇, t)`` linear in q̇: ``W = ∂ω/∂q̇``, ``ω_t = ω|_{q̇=0}``,
    ``α = Σ_r ∂ω/∂q_r q̇_r + ∂ω/∂t``."""
    return _kinematics(ws, q, qd, velocity=True)


def _kinematics(exprs: list, q, qd, velocity: bool) -> list:
    """The derivatives of :func:`_positions` / :func:`_rates`: by symengine when installed and it carries the
    expressions exactly (:func:`lagrange.symengine_bridge.carries`; the results convert back by ``sympify``),
    else by sympy (:func:`lagrange.derive.lagrange.gradient`, sparse)."""
    exprs = [sp.sympify(e) for e in exprs]
    fast = _symengine_kinematics(exprs, q, qd, velocity)
    if fast is not None:
        return fast
    out = []
    zero = {v: 0 for v in qd}
    for e in exprs:
        row = gradient(e, qd if velocity else q)
        if velocity:
            bias = e.xreplace(zero) if t in e.free_symbols else sp.S.Zero
            v = e
        else:
            bias = sp.diff(e, t) if t in e.free_symbols else sp.S.Zero
            v = sp.Add(*(d * qd[j] for j, d in enumerate(row) if d != 0)) + bias
        dv = gradient(v, q)
        rate = sp.Add(*(d * qd[r] for r, d in enumerate(dv) if d != 0))
        if t in v.free_symbols:
            rate += sp.diff(v, t)
        out.append((row, bias, rate))
    return out


def _symengine_kinematics(exprs, q, qd, velocity: bool):
    from ..symengine_bridge import FAILURES, carries, symengine, to_symengine

    se = symengine()
    symbols = set(q) | set(qd) | {t}
    if se is None or not exprs or not carries(exprs, symbols):
        return None
    n = len(q)
    free = set().union(*(e.free_symbols for e in exprs)) | symbols
    try:
        conv = to_symengine([*exprs, *q, *qd, t], free)
        es, qs, qds, ts = conv[:len(exprs)], conv[len(exprs):len(exprs) + n], conv[len(exprs) + n:-1], conv[-1]
        zero = {v: se.Integer(0) for v in qds}
        out = []
        for e in es:
            held = e.free_symbols
            wrt = qds if velocity else qs
            row = [e.diff(v) if v in held else se.Integer(0) for v in wrt]
            if velocity:
                bias = e.xreplace(zero) if ts in held else se.Integer(0)
                v = e
            else:
                bias = e.diff(ts) if ts in held else se.Integer(0)
                v = sum((d * qds[j] for j, d in enumerate(row) if d != 0), se.Integer(0)) + bias
            vheld = v.free_symbols
            rate = sum((v.diff(qs[r]) * qds[r] for r in range(n) if qs[r] in vheld), se.Integer(0))
            if ts in vheld:
                rate += v.diff(ts)
            out.append(([sp.sympify(d) for d in row], sp.sympify(bias), sp.sympify(rate)))
        return out
    except FAILURES:
        return None


def _point(mass, kin, name: str) -> PointMass:
    """The :class:`PointMass` of the three components' ``(J row, ∂x/∂t, a)``."""
    jac = tuple(((i, j), e) for i, (row, _, _) in enumerate(kin) for j, e in enumerate(row) if e != 0)
    return PointMass(sp.sympify(mass), jac, tuple(k[1] for k in kin), tuple(k[2] for k in kin), name)


def _rotor(body: RigidBody, coords, kin) -> Rotor:
    m = sp.sympify(body.mass)
    com = body.com
    J = sp.Matrix(body.inertia)
    if any(c != 0 for c in com):  # parallel-axis theorem: the tensor about the centre of mass
        J = J - m * ((com.T * com)[0, 0] * sp.eye(3) - com * com.T)
    jac = tuple(((i, j), e) for i, (row, _, _) in enumerate(kin) for j, e in enumerate(row) if e != 0)
    inertia = sp.ImmutableMatrix(to_symbols(J, coords))
    return Rotor(inertia, jac, tuple(k[1] for k in kin), tuple(k[2] for k in kin), body.name)


def _kinetic_parts(points, rotors, qd) -> tuple:
    """(T, T₂, T₀) in the compact per-body form."""
    T2, T1, T0 = [], [], []
    for p in points:
        Jv = [sp.S.Zero] * 3
        for (i, j), e in p.jacobian:
            Jv[i] += e * qd[j]
        T2.append(p.mass * sp.Add(*(a**2 for a in Jv)) / 2)
        T1.append(p.mass * sp.Add(*(a * b for a, b in zip(Jv, p.velocity_bias))))
        T0.append(p.mass * sp.Add(*(b**2 for b in p.velocity_bias)) / 2)
    for r in rotors:
        Wv = [sp.S.Zero] * 3
        for (i, j), e in r.jacobian:
            Wv[i] += e * qd[j]
        Wv, wt, I = sp.Matrix(Wv), sp.Matrix(r.omega_bias), sp.Matrix(r.inertia)
        T2.append((Wv.T * I * Wv)[0, 0] / 2)
        T1.append((Wv.T * I * wt)[0, 0])
        T0.append((wt.T * I * wt)[0, 0] / 2)
    T2, T1, T0 = sp.Add(*T2), sp.Add(*T1), sp.Add(*T0)
    return T2 + T1 + T0, T2, T0


def structural_equations(system) -> StructuralEquations:
    """The structural derivation of ``system`` (see the module docstring).

    Preconditions: the kinetic energy comes wholly from Particle and RigidBody bodies (no ``T`` argument),
    no Quaternion orientation, no integrals in the kinematics (:func:`structural_refusal`); the
    :class:`~lagrange.System` checks them when ``derivation="structural"`` is asked for.

    Raises
    ------
    DeclarationError
        A precondition does not hold (the reason is named).
    """
    bodies = getattr(system, "_kinematic_bodies", system.bodies)
    why = structural_refusal(getattr(system, "T_given", 0), bodies)
    if why is not None:
        raise DeclarationError(f"derivation='structural' is not available: {why}; use derivation='expanded'")
    coords = system.coordinates
    q = tuple(position_symbol(c) for c in coords)
    qd = tuple(velocity_symbol(c) for c in coords)
    qdd = tuple(acceleration_symbol(c) for c in coords)
    n = len(q)
    positions = [to_symbols(b.position if isinstance(b, Particle) else b.centre_of_mass, coords) for b in bodies]
    spinning = [b for b in bodies if isinstance(b, RigidBody)]
    pkin = _positions([e for x in positions for e in x], q, qd)
    rkin = _rates([e for b in spinning for e in to_symbols(b.angular_velocity, coords)], q, qd)
    points = [_point(b.mass, pkin[3 * k:3 * k + 3], b.name) for k, b in enumerate(bodies)]
    rotors = [_rotor(b, coords, rkin[3 * k:3 * k + 3]) for k, b in enumerate(spinning)]
    V = to_symbols(system.V, coords)
    P = to_symbols(system.P, coords)
    D = to_symbols(system.rayleigh, coords)
    F = [to_symbols(system.forces[c], coords) for c in coords]
    dV, dP, dD = gradient(V, q), gradient(P, qd), gradient(D, qd)
    dissipative = [POWER_FUNCTION_SIGN * dP[i] + RAYLEIGH_SIGN * dD[i] for i in range(n)]
    nonconservative = tuple(F[i] + dissipative[i] for i in range(n))
    Q = tuple(nonconservative[i] - dV[i] for i in range(n))
    structure = Structure(tuple(points), tuple(rotors), Q)

    blocks = constraint_blocks(system.constraints, coords, q, qd) if system.constraints else {}
    # ∂T/∂t of the compact T: the bounded Pythagorean tidy-up of the expanded derivation, so that a T whose
    # explicit t cancels (a uniformly rotating frame) gives 0 here too where it fits
    T = structure.kinetic_parts(qd)[0] if structure.has_time() else sp.S.Zero  # else ∂T/∂t = 0: T not formed
    dT_dt = _tidy_force(sp.diff(T, t)) if t in T.free_symbols else sp.S.Zero
    jacobi_rate = -dT_dt + sp.diff(V, t) + sp.Add(*(v * Qn for v, Qn in zip(qd, nonconservative)))
    if blocks:
        B, lam = blocks["reaction_matrix"], blocks["multipliers"]
        jacobi_rate += sum((lam[k] * B[j, k] * qd[j] for k in range(B.cols) for j in range(n)), sp.S.Zero)

    internal = set(q) | set(qd) | set(qdd) | {t}
    everything = [*structure.expressions(), V, P, D, *F]
    everything += [to_symbols(c.velocity, coords) for c in system.constraints]
    everything += [to_symbols(c.position, coords) for c in system.constraints if c.position is not None]
    for c in system.constraints:
        if c.friction:
            mu, vs, normal = c.friction
            everything += [to_symbols(sp.sympify(e), coords) for e in (mu, *(vs if isinstance(vs, tuple) else (vs,)),
                                                                       normal)]
    params = set().union(*(sp.sympify(e).free_symbols for e in everything)) - internal
    inputs = {s for s in params if is_input(s)}
    params -= inputs
    cheap = dict(
        coordinates=tuple(coords), q=q, qd=qd, qdd=qdd,
        parameters=tuple(sorted(params, key=lambda s: s.name)),
        potential_gradient=tuple(dV), applied=tuple(F), dissipative=tuple(dissipative),
        nonconservative=nonconservative, potential=V, power_function=P, rayleigh=D, jacobi_rate=jacobi_rate,
        name=system.name, **blocks, inputs=tuple(sorted(inputs, key=lambda s: s.name)),
    )
    return StructuralEquations._create(structure, system, cheap)


def _replaced(eqs: Equations, mapping: dict, new_params: tuple) -> Equations:
    """``eqs`` with ``mapping`` applied to its force fields and ``new_params`` appended (as
    :func:`lagrange.codegen.switches.switched_equations` does to expanded equations)."""

    def sub(e):
        return e.xreplace(mapping)

    return replace(eqs, forcing=sp.ImmutableMatrix([sub(e) for e in eqs.forcing]),
                   dissipative=tuple(sub(e) for e in eqs.dissipative),
                   nonconservative=tuple(sub(e) for e in eqs.nonconservative),
                   applied=tuple(sub(e) for e in eqs.applied), jacobi_rate=sub(eqs.jacobi_rate),
                   parameters=eqs.parameters + tuple(new_params))


#: fields of :class:`Equations` a :class:`StructuralEquations` derives only on first access (by the expanded
#: derivation): everything else is in the structure or cheap
LAZY_FIELDS = frozenset({"mass_matrix", "forcing", "inertial", "kinetic", "jacobi"})


class StructuralEquations(Equations):
    """:class:`~lagrange.derive.equations.Equations` with a frozen :attr:`structure` (see the module docstring).

    ``mass_matrix``, ``forcing``, ``inertial``, ``kinetic`` and ``jacobi`` are today's expanded equations, derived
    on first access (:meth:`expanded`) and cached, so they are exactly those of ``derivation="expanded"``; the
    other fields are set on construction. Equality, hashing and pickling use the structure and the cheap
    fields, never the expansion. ``dataclasses.replace`` of a structural equations object gives a plain
    :class:`Equations` (expanded) with the change: the structure would no longer describe it.

    Code generation (``backend="python"``/``"numba"``) assembles M and f from the structure
    (:mod:`lagrange.codegen.structural_source`). Backends that need the whole right-hand side as one
    expression — ``method="taylor"`` (its tape), heyoka, the C interpreter, the reference backend, the
    vectorized ``rhs_many`` kernel — read the expanded fields.
    """

    def __new__(cls, *args, **kwargs):
        if args or kwargs:  # dataclasses.replace / direct construction: a plain (expanded) Equations
            return Equations(*args, **kwargs)
        return object.__new__(cls)

    @classmethod
    def _create(cls, structure: Structure, system, cheap: dict) -> StructuralEquations:
        obj = object.__new__(cls)
        defaults = {f.name: f.default for f in fields(Equations) if f.name not in LAZY_FIELDS}
        for name, value in {**defaults, **cheap}.items():
            object.__setattr__(obj, name, value)
        object.__setattr__(obj, "structure", structure)
        object.__setattr__(obj, "_system", system)
        return obj

    def __getattr__(self, name):
        if name in LAZY_FIELDS:
            value = getattr(self.expanded(), name)
            object.__setattr__(self, name, value)
            return value
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    def expanded(self) -> Equations:
        """Today's equations of the same system (:func:`lagrange.derive.lagrange.lagrange_equations`), derived
        once (with the replacements of :meth:`with_replaced_forces` applied)."""
        e = self.__dict__.get("_expanded")
        if e is None:
            replaced = self.__dict__.get("_replaced")
            if replaced is not None:
                parent, mapping, new_params = replaced
                e = _replaced(parent.expanded(), mapping, new_params)
            else:  # derived once per System (System.expanded), loaded from the on-disk cache on a re-run
                e = self._system._expanded_equations
            object.__setattr__(self, "_expanded", e)
        return e

    def with_replaced_forces(self, mapping: dict, new_params: tuple = ()) -> StructuralEquations:
        """These equations with ``mapping`` (``xreplace``) applied to Q and the force fields (``applied``,
        ``dissipative``, ``nonconservative``, ``jacobi_rate``) and ``new_params`` appended to the parameters —
        the friction driver's regularized or frozen ``sign`` terms, which live in Q only."""

        def sub(e):
            return sp.sympify(e).xreplace(mapping)

        s = self.structure
        structure = Structure(s.points, s.rotors, tuple(sub(e) for e in s.generalized_force))
        cheap = {f.name: getattr(self, f.name) for f in fields(Equations) if f.name not in LAZY_FIELDS}
        cheap.update(applied=tuple(sub(e) for e in self.applied), dissipative=tuple(sub(e) for e in self.dissipative),
                     nonconservative=tuple(sub(e) for e in self.nonconservative), jacobi_rate=sub(self.jacobi_rate),
                     parameters=self.parameters + tuple(new_params))
        out = StructuralEquations._create(structure, self._system, cheap)
        object.__setattr__(out, "_replaced", (self, mapping, tuple(new_params)))
        return out

    def _identity(self) -> tuple:
        """What equality, hashing and the cache fingerprint compare: the cheap fields and the structure."""
        s = self.structure
        points = tuple((p.mass, p.jacobian, p.velocity_bias, p.acceleration_bias) for p in s.points)
        rotors = tuple((r.inertia, r.jacobian, r.omega_bias, r.acceleration_bias) for r in s.rotors)
        return tuple((f.name, getattr(self, f.name)) for f in fields(Equations) if f.name not in LAZY_FIELDS) + (
            ("structure", (points, rotors, s.generalized_force)),)  # T follows from these: not printed again

    def __hash__(self) -> int:
        h = self.__dict__.get("_hash")
        if h is None:
            h = hash(self._identity())
            object.__setattr__(self, "_hash", h)
        return h

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if other.__class__ is not self.__class__:
            return NotImplemented
        return self._identity() == other._identity()

    def __getstate__(self) -> dict:
        skip = {"_hash", "_expanded", "_energy_parts", *LAZY_FIELDS}
        return {k: v for k, v in self.__dict__.items() if k not in skip}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)

    @property
    def is_structural(self) -> bool:
        return True

    @property
    def is_autonomous(self) -> bool:
        """True when t appears nowhere in the structure (kinematics, Q) nor in the constraint blocks."""
        exprs = self.structure.expressions() + list(self.constraint_bias) + list(self.constraint_rhs)
        return not any(t in e.free_symbols for e in exprs) and t not in self.constraint_matrix.free_symbols

    def energy_parts(self) -> tuple:
        """``(T, h, T₂, T₀)`` from the structure: T in the compact per-body form, ``h = T₂ − T₀ + V``."""
        parts = self.__dict__.get("_energy_parts")
        if parts is None:
            T, T2, T0 = self.structure.kinetic_parts(self.qd)
            parts = (T, T2 - T0 + self.potential, T2, T0)
            object.__setattr__(self, "_energy_parts", parts)
        return parts
