"""Dry-friction ``sign(u)`` switches in derived equations: finding them, regularizing them, freezing them.

Symbolic transformations of :class:`~lagrange.derive.equations.Equations` that code generation applies on
request of the friction driver (:mod:`lagrange.integrate.switching`, which documents the treatment):

* :func:`switching_functions` — the distinct arguments ``u`` of ``sign(u)`` in the forcing;
* :func:`regularized_equations` — ``sign(u) → u/sqrt(u² + ε²)`` (``friction="regularize"``);
* :func:`switched_equations` — ``sign(u_k) → σ_k``, new parameters frozen within a segment.
"""

from __future__ import annotations

import dataclasses
import weakref

import sympy as sp

from ..budget import _postorder
from ..derive.equations import Equations

__all__ = ["switching_functions", "regularized_equations", "switched_equations"]

_SWITCHES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def switching_functions(eqs: Equations) -> list:
    """Distinct arguments ``u`` of ``sign(u)`` in the forcing (sorted for determinism); found once per
    Equations (a tree walk of the forcing costs about 0.1 ms, which repeated short runs would pay each time)."""
    if eqs not in _SWITCHES:
        # structural equations: the switches are in Q (the kinematics hold none), read without expanding M, f
        # each distinct subexpression once (the forcing shares most of its tree: 10-link pendulum, atoms() 8 ms)
        forcing = eqs.structure.generalized_force if eqs.is_structural else eqs.forcing
        found = {n.args[0] for n in _postorder(sp.Tuple(*forcing)) if isinstance(n, sp.sign)}
        _SWITCHES[eqs] = tuple(sorted(found, key=sp.default_sort_key))
    return list(_SWITCHES[eqs])


def _replace_in(eqs: Equations, mapping: dict, new_params: tuple = ()) -> Equations:
    if eqs.is_structural:  # the same replacement in Q and the force fields, structure kept
        return eqs.with_replaced_forces(mapping, tuple(new_params))

    def sub(e):
        return e.xreplace(mapping)

    return dataclasses.replace(
        eqs,
        forcing=sp.ImmutableMatrix([sub(e) for e in eqs.forcing]),
        dissipative=tuple(sub(e) for e in eqs.dissipative),
        nonconservative=tuple(sub(e) for e in eqs.nonconservative),
        applied=tuple(sub(e) for e in eqs.applied),
        jacobi_rate=sub(eqs.jacobi_rate),
        parameters=eqs.parameters + tuple(new_params),
    )


def regularized_equations(eqs: Equations, epsilon: float) -> Equations:
    """``sign(u) → u/sqrt(u² + ε²)`` everywhere in the forces."""
    eps = sp.Float(epsilon)
    mapping = {}
    forcing = eqs.structure.generalized_force if eqs.is_structural else eqs.forcing
    for e in list(forcing) + list(eqs.nonconservative) + [eqs.jacobi_rate]:
        for a in e.atoms(sp.sign):
            u = a.args[0]
            mapping[a] = u / sp.sqrt(u**2 + eps**2)
    return _replace_in(eqs, mapping)


def switched_equations(eqs: Equations, switches: list) -> tuple[Equations, tuple]:
    """Replace ``sign(u_k)`` by parameters ``sigma_k`` (appended to the parameters)."""
    sigmas = tuple(sp.Symbol(f"_sigma{k}", real=True) for k in range(len(switches)))
    mapping = {sp.sign(u): s for u, s in zip(switches, sigmas)}
    new = _replace_in(eqs, mapping, sigmas)
    # parameters must stay in the order compile expects: user parameters sorted, then the sigmas
    return new, sigmas
