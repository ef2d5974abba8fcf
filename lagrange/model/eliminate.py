r"""Eliminating superfluous coordinates with holonomic constraints (Wells 2.21, 4.4: "reduced"
transformation equations).

Given solved forms ``y = Y(q, t)`` of holonomic constraints, the superfluous coordinate y is replaced
everywhere — in the bodies' transformation equations, T, V, P, D and the remaining constraints — and
its generalized force is carried over by virtual work: ``δy = Σ_j ∂Y/∂q_j δq_j`` gives

.. math:: F'_{q_j} = F_{q_j} + F_y\,\frac{\partial Y}{\partial q_j}.

The result is an ordinary :class:`~lagrange.System` with fewer coordinates. Its motion is the motion of
the multiplier formulation (tested); the constraint forces are only available from the latter.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence

import sympy as sp

from ..errors import DeclarationError
from ..safe_sympify import sympify as _sympify
from ..simplification import is_zero, solve
from .constraints import Holonomic, Nonholonomic
from .coordinates import coordinate_name, is_coordinate, position_symbol

__all__ = ["eliminate"]


def _solve_for(system, q) -> sp.Expr:
    """Solve the holonomic constraint(s) containing q for q; exactly one solution is required."""
    for c in system.constraints:
        if c.kind == "holonomic" and c.position.has(q):
            s = sp.Dummy(coordinate_name(q))
            sols = solve(c.position.subs(q, s), s, what=f"{c.name} for {coordinate_name(q)}")
            if len(sols) == 1:
                return sols[0]
            if len(sols) > 1:
                shown = ", ".join(str(x) for x in sols)
                raise DeclarationError(
                    f"{c.name} has {len(sols)} solutions for {coordinate_name(q)} ({shown}); pass the branch "
                    f"you want explicitly: eliminate(system, {{{coordinate_name(q)}: ...}})"
                )
    raise DeclarationError(f"no holonomic constraint can be solved for {coordinate_name(q)}")


def _vanishes(expr, coords) -> bool:
    expr = _sympify(expr)
    if is_zero(expr):  # nonzero expressions are decided numerically, without simplify
        return True
    rng = random.Random(5)
    syms = {f: position_symbol(f) for f in coords}
    e = expr.subs(syms)
    for _ in range(5):
        point = {s: sp.Float(rng.uniform(0.2, 0.9), 30) for s in e.free_symbols}
        v = complex(e.evalf(30, subs=point))
        if abs(v) > 1e-20:
            return False
    return True


def eliminate(system, solutions: Mapping | Sequence):
    """A new System without the superfluous coordinates in ``solutions``.

    Parameters
    ----------
    system : System with holonomic constraints
    solutions : ``{y: Y(q, t)}`` (explicit solved forms — always safe), or a list of coordinates to solve
        for automatically (an error asks for the explicit form when a constraint has several roots)

    Raises
    ------
    DeclarationError
        A coordinate not in the system, a solved form that does not satisfy its constraint, or an
        ambiguous solution.
    """
    from .system import System

    if not isinstance(solutions, Mapping):
        solutions = {q: _solve_for(system, q) for q in solutions}
    problems = []
    for q in solutions:
        if not (is_coordinate(q) and q in system.coordinates):
            problems.append(f"{q} is not a coordinate of the system")
    if problems:
        raise DeclarationError(problems, subject="elimination")
    sub = {q: _sympify(Y) for q, Y in solutions.items()}
    keep = [q for q in system.coordinates if q not in sub]

    def s(e):
        return _sympify(e).subs(sub).doit()

    remaining = []
    for c in system.constraints:
        if c.kind == "holonomic":
            phi = s(c.position)
            if _vanishes(phi, keep):
                continue
            remaining.append(Holonomic(phi, c.name, c.unilateral))
        else:
            remaining.append(Nonholonomic(s(c.velocity), c.name))
    for q in sub:
        used = [c for c in system.constraints if c.kind == "holonomic" and c.position.has(q)]
        if not used:
            problems.append(f"no holonomic constraint involves {coordinate_name(q)}: it is not superfluous")
    if problems:
        raise DeclarationError(problems, subject="elimination")
    forces = {}
    for qj in keep:
        F = s(system.forces[qj])
        for q, Y in sub.items():
            if system.forces[q] != 0:
                sym = sp.Dummy(coordinate_name(qj))
                dY = sp.diff(Y.subs(qj, sym), sym).subs(sym, qj)
                F += s(system.forces[q]) * dY
        forces[qj] = F
    return System(
        keep,
        T=s(system.T_given) if system.T_given != 0 else None,
        V=s(system.V),
        P=s(system.P),
        rayleigh=s(system.rayleigh),
        forces=forces,
        bodies=[b.subs(sub) for b in system.bodies],
        name=(system.name + " (reduced)") if system.name else "",
        constraints=remaining,
        description=system.description,
        symbolic_timeout=system.symbolic_timeout,
        symbolic_budget=system.symbolic_budget,
    )
