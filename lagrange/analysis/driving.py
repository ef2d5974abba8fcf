r"""Driving forces for a prescribed motion, and statics (Wells ch. 13).

Given the motion ``q(t)`` of every coordinate, the generalized forces that must act besides the
declared ones follow from Lagrange's equations (Wells 13.1):

.. math:: F'_r = \frac{d}{dt}\frac{\partial T}{\partial\dot q_r} - \frac{\partial T}{\partial q_r}
          + \frac{\partial V}{\partial q_r} - F_{q_r} - \frac{\partial P}{\partial\dot q_r}
          - \sum_k A_{kr}\lambda_k .

The last sum is the generalized force of the constraints (Wells ch. 12; absent without constraints): with
constraints the driving force is determined only up to what the constraints carry, so the results keep the
multipliers ``λ_k`` (the symbols of :attr:`Equations.multipliers <lagrange.derive.equations.Equations>`).

Actuator forces ``f_1..f_k`` enter F′ linearly through their virtual work (e.g. Ex. 13.4: ``F'_s = f_1 − f_2``,
``F'_x = f_2``); :func:`actuator_forces` solves for them (and for the λ). Statics: the same equations at rest,
:func:`static_equilibrium` solves them for any unknowns (positions, forces, angles) and the λ, symbolically or
with a root finder when transcendental.

Unknown forces are solved as **real** symbols whatever their declared assumptions: a force declared with
:func:`lagrange.parameters` is positive, and sympy would otherwise drop every solution in which it is zero or
negative. Declare unknowns with :func:`lagrange.unknowns` (real symbols) to say what they are.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import scipy.optimize
import sympy as sp

from ..conventions import t
from ..derive.lagrange import _tidy_force
from ..errors import LagrangeError
from ..limits import bounded
from ..model.coordinates import coordinate_name, is_coordinate, to_functions, to_symbols
from ..safe_sympify import expression as _expression
from ..safe_sympify import lambdify as _lambdify
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, solve

__all__ = ["driving_forces", "actuator_forces", "static_equilibrium"]

def _tidy(e):
    """The derivation path's bounded tidying (:func:`lagrange.derive.lagrange._tidy_force`: the Pythagorean
    cleanup, skipped on large expressions and never accepted when it grows the result), then common factors
    pulled out. No ``simplify``: on Wells Ex. 12.6 (a body with products of inertia on three angles) each
    coordinate's ``simplify`` ran into its time limit and the result came back unsimplified anyway."""
    e = _tidy_force(_sympify(e))
    f = sp.factor_terms(e)
    return f if sp.count_ops(f) <= sp.count_ops(e) else e


def _refuse_rough(eqs, what: str) -> None:
    if eqs.rough_signs:
        raise LagrangeError(f"{what} of a system with rough constraints is not supported: the friction force "
                            "depends on the sign of the sliding velocity and of λ, which a prescribed motion or "
                            "a state at rest does not fix; declare the friction force explicitly instead")


def _real(unknowns: Sequence) -> tuple[list, dict]:
    """Real stand-ins for the unknown symbols with sign (or no real) assumptions, and the map back."""
    stand, back = [], {}
    for u in unknowns:
        signed = any(getattr(u, f"is_{a}") is not None for a in ("positive", "negative", "zero", "integer"))
        if isinstance(u, sp.Symbol) and (signed or not u.is_real):
            d = sp.Dummy(u.name, real=True)
            stand.append(d)
            back[d] = u
        else:
            stand.append(u)
    return stand, back


def _residuals(eqs) -> list:
    """``inertial + ∂V/∂q − Q − Bλ`` per coordinate, in plain symbols (zero along a true motion)."""
    out = []
    for i in range(eqs.n):
        r = eqs.inertial[i] + eqs.potential_gradient[i] - eqs.nonconservative[i]
        r -= sum((eqs.reaction_matrix[i, k] * lam for k, lam in enumerate(eqs.multipliers)), sp.S.Zero)
        out.append(r)
    return out


def _along(expr, eqs, motion: Mapping):
    """``expr`` (plain symbols) along ``motion = {q(t): expression of t}``."""
    sub = {}
    for c, q, qd, qdd in zip(eqs.coordinates, eqs.q, eqs.qd, eqs.qdd):
        sub[qdd] = sp.diff(motion[c], t, 2)
        sub[qd] = sp.diff(motion[c], t)
        sub[q] = motion[c]
    return _sympify(expr).xreplace(sub).doit()


def _check_motion(eqs, motion: Mapping) -> None:
    """Raise naming every constraint the prescribed motion violates."""
    bad = []
    for k, name in enumerate(eqs.constraint_names):
        g = sum((eqs.constraint_matrix[k, j] * eqs.qd[j] for j in range(eqs.n)), sp.S.Zero) + eqs.constraint_bias[k]
        if not is_zero(_along(g, eqs, motion)):
            bad.append(name)
    if bad:
        raise LagrangeError(f"the prescribed motion violates the constraint(s) {', '.join(bad)}: no force can "
                            "produce a motion the constraints forbid")


@bounded("driving forces")
def driving_forces(system, motion: Mapping) -> dict:
    r"""``{q: F'_q(t)}`` needed to produce ``motion = {q: q(t)}`` (every coordinate), Wells (13.1).

    With constraints the motion must satisfy them (checked) and each F′ contains the multipliers λ_k: the
    constraint forces ``Σ_k A_kr λ_k`` are subtracted, so ``F'`` plus the constraint forces drive the motion
    for any λ (the constraints carry whatever part of the load lies along their normals).

    Raises
    ------
    LagrangeError
        A coordinate's motion is missing, the motion violates a constraint, or a constraint is rough.
    """
    motion = {q: _sympify(v, where=f"motion of {coordinate_name(q) if is_coordinate(q) else q}")
              for q, v in motion.items()}
    missing = [coordinate_name(q) for q in system.coordinates if q not in motion]
    if missing:
        raise LagrangeError(f"the prescribed motion must give every coordinate; missing {', '.join(missing)}")
    eqs = system.derived
    _refuse_rough(eqs, "driving_forces")
    _check_motion(eqs, motion)
    return {q: _tidy(_along(r, eqs, motion)) for q, r in zip(system.coordinates, _residuals(eqs))}


@bounded("actuator forces")
def actuator_forces(system, virtual_work, unknowns: Sequence, motion: Mapping | None = None) -> dict:
    """Solve for actuator forces ``unknowns`` whose virtual work ``virtual_work`` (written with
    :func:`~lagrange.delta`) produces the system's motion — the prescribed ``motion`` if given, else the
    equations in terms of q, q̇, q̈.

    The unknowns are solved as real symbols (a positive declaration does not exclude a negative force). With
    constraints the multipliers λ_k are solved for too; an actuator force that still depends on a λ (the
    constraints could carry that load instead) is not determined and raises.

    Raises
    ------
    LagrangeError
        The virtual work is malformed, the forces have no solution or are not determined uniquely, the
        motion violates a constraint, or a constraint is rough.
    """
    from ..model.forces import generalized_forces

    problems: list = []
    Fp = generalized_forces(virtual_work, system.coordinates, problems)
    if problems:
        raise LagrangeError("; ".join(problems))
    eqs = system.derived
    _refuse_rough(eqs, "actuator_forces")
    if motion is not None:
        need = driving_forces(system, motion)
    else:
        need = {q: to_functions(r, eqs.coordinates) for q, r in zip(system.coordinates, _residuals(eqs))}
    stand, back = _real(unknowns)
    fwd = {u: d for d, u in back.items()}
    lam = list(eqs.multipliers)
    eqns = [sp.Eq(_sympify(Fp.get(q, 0)).xreplace(fwd), _sympify(need[q]).xreplace(fwd))
            for q in system.coordinates]
    sol = solve(eqns, stand + lam, dict=True, what="the driving-force equations")
    names = ", ".join(map(str, unknowns))
    if not sol:
        raise LagrangeError(f"the actuator forces {names} have no solution: their virtual work cannot produce "
                            "this motion (an unactuated coordinate's equation is not satisfied)")
    undetermined = [str(u) for u, d in zip(unknowns, stand)
                    if d not in sol[0] or _sympify(sol[0][d]).free_symbols & (set(stand) | set(lam))]
    if len(sol) != 1 or undetermined:
        raise LagrangeError(f"the actuator forces {names} are not determined uniquely ({len(sol)} solution(s)"
                            + (f"; free: {', '.join(undetermined)}" if undetermined else "") + ")")
    return {u: _tidy(sol[0][d].xreplace(back)) for u, d in zip(unknowns, stand)}


def _rest_conditions(system, unk_syms: list) -> tuple[list, list]:
    """The equilibrium conditions at rest (``q̇ = q̈ = 0``) and the multipliers to solve for.

    ``f + Bλ = 0`` per coordinate, then per constraint ``φ_k = 0`` (holonomic, when it involves an unknown)
    and ``b_k = 0`` (a constraint that moves cannot hold the system at rest)."""
    eqs = system.derived
    _refuse_rough(eqs, "static_equilibrium")
    rest = {v: 0 for v in eqs.qd}
    conds = []
    for i in range(eqs.n):
        f = _sympify(eqs.forcing[i])
        dry = [s for s in f.atoms(sp.sign) if s.free_symbols & set(eqs.qd)]
        c = f.subs(rest)
        if dry or c.has(sp.nan, sp.zoo):
            raise LagrangeError(
                f"static_equilibrium of a system with dry friction ({coordinate_name(eqs.coordinates[i])} "
                "equation): static friction can take any value up to its limit at rest, which these "
                "conditions do not model; remove the friction terms to get the frictionless equilibria")
        c += sum((eqs.reaction_matrix[i, k] * lam for k, lam in enumerate(eqs.multipliers)), sp.S.Zero)
        conds.append(c)
    unknown_set = set(unk_syms)
    for k, name in enumerate(eqs.constraint_names):
        phi = eqs.constraint_positions[k]
        if phi is not None and _sympify(phi).free_symbols & unknown_set:
            conds.append(_sympify(phi))
        b = _sympify(eqs.constraint_bias[k])
        if b.free_symbols & unknown_set:
            conds.append(b)
        elif not is_zero(b):
            raise LagrangeError(f"constraint {name} moves (its velocity form has the term {b} without q̇): the "
                                "system cannot be at rest; use relative coordinates in which it is fixed")
    return conds, list(eqs.multipliers)


@bounded("static equilibrium")
def static_equilibrium(system, unknowns: Sequence, params: Mapping | None = None, guess: Mapping | None = None):
    """Solve the equilibrium conditions (all velocities and accelerations zero) for ``unknowns``.

    ``unknowns`` are coordinates or symbols (an applied force, a length). Symbolic without ``params``: a list
    of solutions ``{unknown: value}``; with ``params`` numeric values are substituted and
    ``scipy.optimize.root`` (``least_squares`` when there are more conditions than unknowns) is used from
    ``guess``, giving one ``{unknown: float}``.

    Unknown symbols are solved as real whatever their declared assumptions (see the module docstring). With
    constraints the conditions are ``f + Aᵀλ = 0`` plus the holonomic constraints that involve an unknown, and
    the solutions also give the multipliers λ_k (keys: the symbols ``system.derived.multipliers``). With
    explicit t the conditions are those at time t (relative equilibrium in moving coordinates).

    Raises
    ------
    LagrangeError
        Dry friction (static friction is indeterminate), rough or moving constraints, or (numeric) no root
        found or fewer conditions than unknowns.
    """
    coords = system.coordinates
    unk_plain = [to_symbols(u, coords) for u in unknowns]
    stand, back = _real(unk_plain)
    fwd = {u: d for d, u in back.items()}
    conds, lam = _rest_conditions(system, unk_plain)
    conds = [c.xreplace(fwd) for c in conds]
    if params is None:
        sols = solve(conds, stand + lam, dict=True, what="the equilibrium conditions")
        out = []
        for s in sols:
            one = {u: to_functions(s[d].xreplace(back), coords) for u, d in zip(unknowns, stand) if d in s}
            one.update({m: to_functions(s[m].xreplace(back), coords) for m in lam if m in s})
            out.append(one)
        return out
    return _numeric_equilibrium(system, unknowns, stand, lam, conds, params, guess)


def _numeric_equilibrium(system, unknowns, stand, lam, conds, params, guess):
    by_name = {getattr(k, "name", str(k)): _expression(v, where=f"parameter {getattr(k, 'name', k)}")
               for k, v in params.items()}
    variables = stand + lam
    sub = {s: by_name[s.name] for c in conds for s in c.free_symbols
           if s.name in by_name and s not in variables}
    conds = [c.xreplace(sub) for c in conds]
    left = sorted({str(s) for c in conds for s in c.free_symbols if s not in variables and s != t})
    if left:
        raise LagrangeError(f"static_equilibrium needs values for {', '.join(left)}")
    if any(c.has(t) for c in conds):
        raise LagrangeError("the equilibrium conditions depend on t: solve them symbolically (no params) or "
                            "give t a value in the expressions")
    if len(conds) < len(variables):
        raise LagrangeError(f"{len(conds)} equilibrium condition(s) for {len(variables)} unknown(s) (with the "
                            "multipliers): the equilibrium is not determined")
    f = _lambdify([variables], conds, "numpy")
    g = dict(guess or {})
    x0 = np.array([float(g.get(u, 0.0)) for u in unknowns] + [0.0] * len(lam))

    def F(x):
        return np.asarray(f(x), dtype=float)

    if len(conds) == len(variables):
        res = scipy.optimize.root(F, x0, tol=1e-12)
    else:
        res = scipy.optimize.least_squares(F, x0, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    scale = max(1.0, float(np.max(np.abs(F(x0)))))
    if not float(np.max(np.abs(F(res.x)))) <= 1e-9 * scale:
        raise LagrangeError(f"static equilibrium not found from {dict(zip(map(str, unknowns), x0))}: {res.message}")
    out = dict(zip(unknowns, (float(v) for v in res.x[: len(unknowns)])))
    out.update(zip(lam, (float(v) for v in res.x[len(unknowns):])))
    return out
