r"""Lagrange's equations the way Wells derives them — pure functions of a :class:`~lagrange.System`.

For each coordinate (Wells 4.9, 5.10, 6.10)

.. math::

    \underbrace{\sum_j M_{rj}\ddot q_j + \sum_j \frac{\partial^2 T}{\partial\dot q_r\partial q_j}\dot q_j
    + \frac{\partial^2 T}{\partial\dot q_r\partial t} - \frac{\partial T}{\partial q_r}}_{
    \frac{d}{dt}\frac{\partial T}{\partial\dot q_r}-\frac{\partial T}{\partial q_r}}
    + \frac{\partial V}{\partial q_r} = F_{q_r} + \frac{\partial P}{\partial\dot q_r}
    - \frac{\partial D}{\partial\dot q_r},
    \qquad M_{rj} = \frac{\partial^2 T}{\partial\dot q_r\,\partial\dot q_j}.

The total time derivative is expanded by the chain rule on plain symbols, so no unevaluated
derivatives reach code generation; nothing is inverted symbolically and nothing is ``simplify``-ed on
this path (see ``reference/numerics.md``: symbolic inversion and simplify blow up beyond 2–3 DOF).
"""

from __future__ import annotations

import sympy as sp
from sympy.simplify.fu import TR2i, TR10i

from .. import limits
from ..budget import fits
from ..conventions import POWER_FUNCTION_SIGN, RAYLEIGH_SIGN, t
from ..model.coordinates import (
    acceleration_symbol,
    position_symbol,
    to_functions,
    to_symbols,
    velocity_symbol,
)
from ..model.inputs import is_input
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero
from ..symengine_bridge import FAILURES, carries, symengine, to_symengine
from .equations import Equations
from .multipliers import constraint_blocks

__all__ = [
    "lagrange_equations",
    "book_form",
    "energy_split",
    "ignorable_coordinates",
    "is_zero",
]


def lagrange_equations(system) -> Equations:
    """Derive ``M q̈ = f`` for ``system``.

    Preconditions (checked by :class:`~lagrange.System` on construction): T, P, D and forces depend on
    coordinates, velocities, t and parameters only; V has no velocities; nothing has accelerations.

    Returns
    -------
    Equations
        Frozen; ``mass_matrix`` is symmetric by construction (only the upper triangle is derived).
    """
    coords = system.coordinates
    q = tuple(position_symbol(c) for c in coords)
    qd = tuple(velocity_symbol(c) for c in coords)
    qdd = tuple(acceleration_symbol(c) for c in coords)
    n = len(q)

    T = _tidy_kinetic(to_symbols(system.T, coords))
    V = to_symbols(system.V, coords)
    P = to_symbols(system.P, coords)
    D = to_symbols(system.rayleigh, coords)
    F = [_tidy_force(to_symbols(system.forces[c], coords)) for c in coords]

    dT_dqd, hessian, convectives = kinetic_derivatives(T, q, qd)
    rows = [[sp.S.Zero] * n for _ in range(n)]  # a list, not sp.zeros: item assignment there costs O(n)
    nonzero: list[list[int]] = [[] for _ in range(n)]  # the structurally nonzero columns of each row of M
    for (i, j), h in sorted(hessian.items()):
        limits.measure(h, what=f"the mass-matrix entry M[{q[i]}, {q[j]}]")
        h = _tidy_force(h)
        if h != 0:
            rows[i][j] = rows[j][i] = h
            nonzero[i].append(j)
            if j != i:
                nonzero[j].append(i)
    M = sp.ImmutableMatrix(rows)
    inertial = []
    forcing = []
    dissipative = []
    potential_gradient = gradient(V, q)
    dP, dD = gradient(P, qd), gradient(D, qd)
    for i in range(n):
        limits.checkpoint()
        convective = convectives[i]
        inertial.append(sp.Add(*(rows[i][j] * qdd[j] for j in sorted(nonzero[i]))) + convective)
        dV = potential_gradient[i]
        diss = POWER_FUNCTION_SIGN * dP[i] + RAYLEIGH_SIGN * dD[i]
        dissipative.append(diss)
        forcing.append(F[i] + diss - convective - dV)
    for i in range(n):
        limits.measure(forcing[i], what=f"the forcing term of {q[i]}")

    nonconservative = tuple(F[i] + dissipative[i] for i in range(n))
    L = T - V
    jacobi = sp.Add(*(v * d for v, d in zip(qd, dT_dqd))) - L
    jacobi_rate = -sp.diff(L, t) + sp.Add(*(v * Q for v, Q in zip(qd, nonconservative)))
    blocks = constraint_blocks(system.constraints, coords, q, qd) if system.constraints else {}
    if blocks:
        B, lam = blocks["reaction_matrix"], blocks["multipliers"]
        # power of the constraint forces q̇ᵀBλ: −λᵀb for moving constraints, plus friction on rough ones
        jacobi_rate += sum((lam[k] * B[j, k] * qd[j] for k in range(B.cols) for j in range(n)), sp.S.Zero)

    internal = set(q) | set(qd) | set(qdd) | {t}
    everything = [T, V, P, D, *F] + [to_symbols(c.velocity, coords) for c in system.constraints]
    everything += [to_symbols(c.position, coords) for c in system.constraints if c.position is not None]
    everything += [to_symbols(sp.Matrix(_flat(c.friction)), coords) for c in system.constraints if c.friction]
    params = set().union(*(e.free_symbols for e in everything)) - internal
    inputs = {s for s in params if is_input(s)}
    params -= inputs
    return Equations(
        coordinates=tuple(coords),
        q=q,
        qd=qd,
        qdd=qdd,
        parameters=tuple(sorted(params, key=lambda s: s.name)),
        mass_matrix=M,
        forcing=sp.ImmutableMatrix(forcing),
        inertial=tuple(inertial),
        potential_gradient=tuple(potential_gradient),
        applied=tuple(F),
        dissipative=tuple(dissipative),
        nonconservative=nonconservative,
        kinetic=T,
        potential=V,
        power_function=P,
        rayleigh=D,
        jacobi=jacobi,
        jacobi_rate=jacobi_rate,
        name=system.name,
        **blocks,
        inputs=tuple(sorted(inputs, key=lambda s: s.name)),
    )


def kinetic_derivatives(T, q, qd) -> tuple[list, dict, list]:
    r"""The derivatives of T that Lagrange's equations need:
    ``(∂T/∂q̇_r, {(r, j): ∂²T/∂q̇_r∂q̇_j for r ≤ j, structural zeros left out}, c_r)`` with the convective terms
    :math:`c_r = \sum_j \frac{\partial^2 T}{\partial\dot q_r\partial q_j}\dot q_j
    + \frac{\partial^2 T}{\partial\dot q_r\partial t} - \frac{\partial T}{\partial q_r}`
    (``d/dt ∂T/∂q̇_r − ∂T/∂q_r`` without its ``M q̈`` part).

    Differentiated by symengine when it is installed (``pip install "lagrange-dynamics[fast]"``), T has at least
    :data:`SYMENGINE_MIN_NODES` nodes and holds only what symengine carries back exactly
    (:func:`lagrange.symengine_bridge.carries`), else by sympy; the two give the same expressions up to the
    order of terms (tests/test_derive.py compares them). Measured with the rest of the
    derivation (benchmarks/results/derivation.md): Greenspan's top 0.74 s → 0.19 s, a 10-link pendulum
    0.78 s → 0.21 s.
    """
    fast = _symengine_derivatives(T, q, qd)
    if fast is not None:
        return fast
    n = len(q)
    dT = gradient(T, qd)
    dT_dq = gradient(T, q)
    hessian, conv = {}, []
    for i in range(n):
        held = dT[i].free_symbols
        for j in range(i, n):
            if qd[j] in held:
                hessian[i, j] = sp.diff(dT[i], qd[j])
        conv.append(sp.Add(*(sp.diff(dT[i], q[j]) * qd[j] for j in range(n) if q[j] in held))
                    + sp.diff(dT[i], t) - dT_dq[i])
    return dT, hessian, conv


def gradient(e, variables) -> list:
    """``[∂e/∂v for v in variables]``, the same expressions as ``sympy.diff``, in time linear in the number of
    variables when each summand of ``e`` holds a few of them (a chain, uncoupled oscillators), where
    differentiating the whole of ``e`` once per variable is quadratic: a sum is differentiated summand by
    summand, each by the variables it holds only (the others give zero), and a constant factor of a sum
    (``k*(a**2 + b**2)/2``) is kept outside, as sympy's sum and product rules do."""
    index = {v: i for i, v in enumerate(variables)}
    parts = _sparse_gradient(_sympify(e), variables, index)
    return [parts.get(i, sp.S.Zero) for i in range(len(variables))]


def _sparse_gradient(e, variables, index) -> dict:
    """``{i: ∂e/∂variables[i]}`` for the derivatives that are not structurally zero."""
    if e.is_Add:
        collected: dict = {}
        for term in e.args:
            for i, d in _sparse_gradient(term, variables, index).items():
                collected.setdefault(i, []).append(d)
        return {i: sp.Add(*ds) for i, ds in collected.items()}
    if e.is_Mul:
        sums = [f for f in e.args if f.is_Add]
        if len(sums) == 1:
            rest = sp.Mul(*[f for f in e.args if f is not sums[0]])
            if not any(s in index for s in rest.free_symbols):
                return {i: rest * d for i, d in _sparse_gradient(sums[0], variables, index).items()}
    return {index[s]: sp.diff(e, s) for s in e.free_symbols if s in index}


#: kinetic energies smaller than this (expression nodes) are differentiated by sympy even when symengine is
#: installed: importing symengine (20–40 ms, once per process) costs more than it saves there. Measured
#: (fresh processes, import included): double pendulum (T of 45 nodes) 20 ms by sympy, 31 ms with symengine;
#: 3-link pendulum (79 nodes) 44 against 39 ms; 4-link (121) 102 against 48 ms; 5-link (171) 163 against
#: 68 ms. Decided by size alone, so a model's derived form never depends on what a process imported before.
SYMENGINE_MIN_NODES = 75


def _symengine_derivatives(T, q, qd):
    """:func:`kinetic_derivatives` by symengine, or None: T below :data:`SYMENGINE_MIN_NODES`, symengine
    not installed, T holds something it does not carry back unchanged
    (:func:`lagrange.symengine_bridge.carries`), or symengine failed."""
    if sum(1 for _ in sp.preorder_traversal(T)) < SYMENGINE_MIN_NODES:
        return None
    se = symengine()
    symbols = set(q) | set(qd) | {t}
    if se is None or not carries([T], symbols):
        return None
    n = len(q)
    try:
        Ts, *qs, ts = to_symengine([T, *q, *qd, t], T.free_symbols | symbols)
        qs, qds = qs[:n], qs[n:]
        dT = [Ts.diff(v) for v in qds]
        # derivatives by symbols a ∂T/∂q̇ does not hold are zero: skipped (linear in n for sparse M)
        where_qd, where_q = {v: j for j, v in enumerate(qds)}, {v: j for j, v in enumerate(qs)}
        held = [d.free_symbols for d in dT]
        # symbols convert back to the originals (to_symengine), so sympify alone restores the results
        hessian = {(i, j): sp.sympify(dT[i].diff(qds[j])) for i in range(n)
                   for j in sorted(where_qd[v] for v in held[i] if v in where_qd) if j >= i}
        conv = [sp.sympify(sum((dT[i].diff(qs[j]) * qds[j]
                                for j in sorted(where_q[v] for v in held[i] if v in where_q)),
                               se.Integer(0)) + dT[i].diff(ts) - Ts.diff(qs[i])) for i in range(n)]
        return [sp.sympify(e) for e in dT], hessian, conv
    except FAILURES:
        return None


_TIDY_LIMIT = 400
_KINETIC_LIMIT = 600
_TRIGSIMP_LIMIT = 60


def _pythagoras(expr):
    """Cheap Pythagorean cleanup: expand, then try sin² → 1 − cos² and cos² → 1 − sin²; keep the
    shortest of the three. Collapses the sin²(ωt) + cos²(ωt) left by rotating frames at polynomial cost."""
    e = sp.expand(expr)
    if not any(isinstance(x.base, (sp.sin, sp.cos)) and x.exp.is_Integer and x.exp >= 2 for x in e.atoms(sp.Pow)):
        return e  # no sin² or cos²: both rewrites below would return e itself
    candidates = [e]
    for f, other in ((sp.sin, sp.cos), (sp.cos, sp.sin)):

        def is_power(x, f=f):
            return x.is_Pow and isinstance(x.base, f) and x.exp.is_Integer and x.exp >= 2

        def rewrite(x, f=f, other=other):
            u = x.base.args[0]
            return (1 - other(u) ** 2) ** (x.exp // 2) * f(u) ** (x.exp % 2)

        candidates.append(sp.expand(e.replace(is_power, rewrite)))
    return min(candidates, key=sp.count_ops)


_EXPAND_LIMIT = 400


def _expanded_terms(expr) -> int:
    """An upper bound on the number of terms of ``expand(expr)`` at the top level, without expanding: sums
    add, products multiply, integer powers of sums raise (functions count as one term)."""
    if expr.is_Add:
        return sum(_expanded_terms(a) for a in expr.args)
    if expr.is_Mul:
        out = 1
        for a in expr.args:
            out *= _expanded_terms(a)
        return out
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0:
        return _expanded_terms(expr.base) ** int(expr.exp)
    return 1


def _tidy_kinetic(T):
    """Compact a textbook-sized T (sin² + cos² = 1) so that M and f stay small and readable.

    Bounded: a T above ``_KINETIC_LIMIT`` operations is left as it is (no simplify on big systems). Small
    results get two of Fu's rules — TR10i (``sin a sin b + cos a cos b → cos(a − b)``, the relative angles of
    linked bodies) and TR2i (``cos/sin → 1/tan``) — instead of ``trigsimp``: on the 62 distinct kinetic
    energies of the book's problems that reach this step they give exactly ``trigsimp``'s result, in a
    fourteenth of the time (0.3 s against 4.5 s in all; 34 ms of a double pendulum's first result).
    """
    if sp.count_ops(T) > _KINETIC_LIMIT or not fits(T):
        return T
    return limits.tidy(_compact_kinetic, T, what="clean-up of T")


def _compact_kinetic(T):
    """:func:`_tidy_kinetic`'s work, run under a share of the derivation's time (:func:`lagrange.limits.tidy`)."""
    e = _pythagoras(T)
    if e.has(sp.sin, sp.cos) and sp.count_ops(e) <= _TRIGSIMP_LIMIT:
        e2 = sp.expand(TR2i(TR10i(e)))
        e = e2 if sp.count_ops(e2) < sp.count_ops(e) else e
    # expanded sums of squares cost more operations than the compact squares they came from; accept
    # that (derivatives of the expanded form are simpler), but never a blow-up
    return e if sp.count_ops(e) <= 3 * sp.count_ops(T) + 10 else T


def _tidy_force(F):
    """The same Pythagorean cleanup for a generalized force or a mass-matrix entry (e.g. a force vector
    rotating with t), accepted unless it grows the expression. Skipped when expanding would give more than
    :data:`_EXPAND_LIMIT` terms (:func:`_expanded_terms`): the result would be rejected as longer anyway, and
    expanding a bicycle's mass matrix that way took half of its derivation."""
    # the cheap bound first: count_ops of a bicycle's mass-matrix entries costs more than the bound
    if F == 0 or _expanded_terms(F) > _EXPAND_LIMIT or sp.count_ops(F) > _KINETIC_LIMIT or not fits(F):
        return F
    e = limits.tidy(_pythagoras, F, what="clean-up of a force or mass-matrix entry")
    return e if sp.count_ops(e) <= sp.count_ops(F) else F


def _tidy(expr, collect_in=()):
    """Light, bounded tidying for display: collect in velocities, factor common terms."""
    if expr == 0 or sp.count_ops(expr) > _TIDY_LIMIT or not fits(expr):
        return expr
    e = sp.expand(expr)
    held = e.free_symbols
    collect_in = [v for v in collect_in if v in held]  # the velocities present: linear in n, not quadratic
    if collect_in:
        e = sp.collect(e, collect_in)
    return sp.factor_terms(e)


def book_form(eqs: Equations) -> list[sp.Eq]:
    r"""Wells' printed form per coordinate, in the coordinate functions.

    Left: ``Σ_j M_rj q̈_j + (rest of d/dt ∂T/∂q̇ − ∂T/∂q) + ∂V/∂q``; right: ``F_q + ∂P/∂q̇ − ∂D/∂q̇``
    plus ``Σ_k λ_k ∂g_k/∂q̇_r`` with constraints, followed by the m constraint equations.
    """
    out = []
    n = eqs.n
    nonzero = _nonzero_columns(eqs.mass_matrix)
    for i in range(n):
        acc = sp.Add(*(_tidy(eqs.mass_matrix[i, j]) * eqs.qdd[j] for j in nonzero[i]))
        rest = eqs.inertial[i] - sp.Add(*(eqs.mass_matrix[i, j] * eqs.qdd[j] for j in nonzero[i]))
        lhs = acc + _tidy(rest + eqs.potential_gradient[i], eqs.qd)
        rhs = _tidy(eqs.nonconservative[i], eqs.qd)
        rhs += sum((_tidy(eqs.reaction_matrix[i, k]) * lam for k, lam in enumerate(eqs.multipliers)), sp.S.Zero)
        rhs = rhs.xreplace(_display_signs(eqs))
        out.append(sp.Eq(to_functions(lhs, eqs.coordinates), to_functions(rhs, eqs.coordinates)))
    return out + constraint_equations(eqs)


def _nonzero_columns(M) -> list[list[int]]:
    """The structurally nonzero columns of each row of ``M`` (one pass over its entries)."""
    rows: list[list[int]] = [[] for _ in range(M.rows)]
    for (i, j), _ in sorted(M.todok().items()):
        rows[i].append(j)
    return rows


def _display_signs(eqs: Equations) -> dict:
    """σ_k of rough constraints shown as sign(λ_k)·sign(v_s,k) — the friction opposes sliding with
    magnitude μ|N|."""
    pairs = zip(eqs.rough_signs, eqs.sliding_velocities)
    planar = {k for k, _ in eqs.planar_friction}  # friction over a surface: σ = sign(λ), the direction is v/|v|
    return {sig: sp.sign(eqs.multipliers[k]) * (1 if k in planar else sp.sign(v)) for sig, (k, v) in pairs}


def _flat(friction) -> list:
    """(μ, v_s or (v_1, v_2, …), normal) as one flat list."""
    mu, vs, normal = friction
    return [mu, *(vs if isinstance(vs, tuple) else (vs,)), normal]


def constraint_equations(eqs: Equations) -> list[sp.Eq]:
    """The constraints as printed by Wells: ``φ(q, t) = 0`` (holonomic) or ``Σ a q̇ + a_t = 0``."""
    out = []
    qd = sp.Matrix(eqs.qd)
    for k in range(eqs.m):
        phi = eqs.constraint_positions[k]
        g = phi if phi is not None else (eqs.constraint_matrix[k, :] * qd)[0, 0] + eqs.constraint_bias[k]
        out.append(sp.Eq(to_functions(g, eqs.coordinates), 0))
    return out


def energy_split(system) -> tuple:
    """Wells (2.54)–(2.56): ``T = Σ_kl A_kl q̇_k q̇_l + Σ_k B_k q̇_k + C`` with A containing the 1/2."""
    eqs = system.derived
    T = eqs.kinetic
    zero = {v: 0 for v in eqs.qd}
    A = sp.Matrix(eqs.mass_matrix) / 2
    B = sp.Matrix([sp.diff(T, v).subs(zero) for v in eqs.qd])
    C = T.subs(zero)
    c = eqs.coordinates
    return to_functions(A, c), to_functions(B, c), to_functions(C, c)


def ignorable_coordinates(system) -> dict:
    """``{q: p_q}`` for coordinates absent from L with no generalized force (Wells 3.3, 5.15) and no
    constraint force (no constraint involves q̇, so the column of A — of B for rough constraints — is zero).

    ``p_q = ∂L/∂q̇`` is then a constant of the motion.
    """
    eqs = system.derived
    L = eqs.kinetic - eqs.potential
    dL_dq = gradient(L, eqs.q)  # linear in the number of coordinates for local terms
    out = {}
    for i, c in enumerate(eqs.coordinates):
        constrained = any(not is_zero(eqs.reaction_matrix[i, k]) for k in range(eqs.m))
        if not constrained and is_zero(dL_dq[i]) and is_zero(eqs.nonconservative[i]):
            out[c] = to_functions(sp.diff(L, eqs.qd[i]), eqs.coordinates)
    return out
