r"""Ignorable coordinates, the Routhian, steady motion and oscillations about it (Wells ch. 11).

With ignorable coordinates J (absent from L, no generalized force) their momenta ``p_J = ∂L/∂J̇`` are
constant. Solving ``∂L/∂J̇ = p_J`` for J̇ (linear, 11.3) and forming

.. math:: R = L - \sum_i p_i \dot J_i \qquad (11.6)

gives reduced Lagrange equations in the other coordinates (11.9). Steady motion: the non-ignorable
coordinates constant, ``(∂R/∂q)₀ = 0`` (11.10) — possibly several solutions. About it (``q = b + s``)

.. math:: a\ddot s + g\dot s + c\,s = 0,\quad a = (∂^2R/∂q̇∂q̇)_0,\quad
          g_{rl} = (∂^2R/∂q̇_r∂q_l)_0 - (∂^2R/∂q̇_l∂q_r)_0,\quad c = -(∂^2R/∂q∂q)_0,

with antisymmetric gyroscopic ``g`` (Wells writes 11.12 with b = −g and −c). Stability from the roots of
``|aλ² + gλ + c| = 0`` (only even powers of λ when there is no damping).

The Routhian is formed for unconstrained systems only: a constrained system raises
:class:`~lagrange.errors.AnalysisError`. Eliminate holonomic constraints first (:func:`lagrange.eliminate`),
or linearize about the steady motion directly on the constraint manifold, with the reference velocities in
``about`` (:func:`lagrange.analysis.small_oscillations.linearize`, e.g. a rolling disc or a bicycle).
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from ..conventions import t
from ..errors import AnalysisError
from ..limits import bounded
from ..model.coordinates import coordinate_name, position_symbol, to_functions, velocity_symbol
from ..records import record
from ..safe_sympify import sympify as _sympify
from ..simplification import simplify, solve
from .small_oscillations import LinearModel

__all__ = ["Routhian", "routhian", "steady_motion_conditions", "oscillations_about_steady_motion"]


@record(frozen=True)
class Routhian:
    """R in plain symbols of the kept coordinates and the constant momenta ``p_<J>``."""

    system: object
    ignorable: tuple  # coordinate functions J
    kept: tuple  # the other coordinates
    momenta: tuple  # Symbols p_J
    R: sp.Expr
    ignorable_rates: tuple  # J̇ as functions of (q, q̇, p)

    def equations(self) -> list:
        """Reduced Lagrange equations ``d/dt(∂R/∂q̇) − ∂R/∂q = Q`` as expressions (= 0), in symbols with
        q̈ as ``<name>_ddot``."""
        eqs = self.system.derived
        idx = [self.system.coordinates.index(c) for c in self.kept]
        q = [eqs.q[i] for i in idx]
        qd = [eqs.qd[i] for i in idx]
        qdd = [eqs.qdd[i] for i in idx]
        to_rates = {velocity_symbol(c): r for c, r in zip(self.ignorable, self.ignorable_rates)}
        out = []
        for k, i in enumerate(idx):
            dRdv = sp.diff(self.R, qd[k])
            ddt = sum((sp.diff(dRdv, q[j]) * qd[j] + sp.diff(dRdv, qd[j]) * qdd[j] for j in range(len(q))), sp.S.Zero)
            ddt += sp.diff(dRdv, t)
            Q = _sympify(eqs.nonconservative[i]).subs(to_rates)
            out.append(sp.expand(ddt - sp.diff(self.R, q[k]) - Q))
        return out


def _bounded_simplify(e, limit: int = 120):
    """``simplify`` on small expressions only (it can take tens of seconds on a Routhian with several
    ignorable coordinates); larger ones are only put over a common denominator."""
    return simplify(e) if sp.count_ops(e) <= limit else sp.factor_terms(sp.cancel(sp.together(e)))


@bounded("Routhian")
def routhian(system, ignorable=None) -> Routhian:
    """The Routhian for ``ignorable`` coordinates (default: all detected ignorable ones).

    Raises :class:`~lagrange.errors.AnalysisError` for a constrained system (see the module docstring)."""
    eqs = system.derived
    if eqs.m:
        raise AnalysisError(f"the Routhian is formed for unconstrained systems; this one has the constraints "
                            f"{', '.join(eqs.constraint_names)}: eliminate them (lagrange.eliminate) or use "
                            "linearize(system, about={coordinates and velocities of the steady motion}) on the "
                            "constraint manifold")
    if ignorable is None:
        ignorable = tuple(system.ignorable_coordinates())
    ignorable = tuple(ignorable)
    kept = tuple(c for c in system.coordinates if c not in ignorable)
    L = eqs.kinetic - eqs.potential
    Jd = [velocity_symbol(c) for c in ignorable]
    p = [sp.Symbol(f"p_{coordinate_name(c)}", real=True) for c in ignorable]
    sol = solve([sp.diff(L, v) - pi for v, pi in zip(Jd, p)], Jd, dict=True, what="the momenta for the velocities")
    if len(sol) != 1:
        raise ValueError("the ignorable velocities cannot be solved uniquely from their momenta")
    rates = tuple(_bounded_simplify(sol[0][v]) for v in Jd)
    R = L - sum((pi * v for pi, v in zip(p, Jd)), sp.S.Zero)
    R = _bounded_simplify(R.subs(sol[0]))
    return Routhian(system, ignorable, kept, tuple(p), R, rates)


@bounded("steady-motion conditions")
def steady_motion_conditions(r: Routhian) -> list:
    """``(∂R/∂q)₀ = 0`` with the kept velocities zero (Wells 11.10), in coordinate functions; solve them
    (sympy.solve or a root finder) for the steady values — there may be several."""
    rest = {velocity_symbol(c): 0 for c in r.kept}
    return [to_functions(sp.diff(r.R, position_symbol(c)).subs(rest), r.system.coordinates) for c in r.kept]


@bounded("oscillations about a steady motion")
def oscillations_about_steady_motion(r: Routhian, about: Mapping) -> LinearModel:
    """a, gyroscopic g and c of the small oscillations about a steady motion ``about = {q: b}``."""
    q = [position_symbol(c) for c in r.kept]
    qd = [velocity_symbol(c) for c in r.kept]
    at = {position_symbol(c): _sympify(v) for c, v in about.items()}
    at.update({v: 0 for v in qd})
    n = len(q)
    a = sp.Matrix(n, n, lambda i, j: sp.diff(r.R, qd[i], qd[j]).subs(at))
    g = sp.Matrix(n, n, lambda i, j: (sp.diff(r.R, qd[i], q[j]) - sp.diff(r.R, qd[j], q[i])).subs(at))
    c = sp.Matrix(n, n, lambda i, j: -sp.diff(r.R, q[i], q[j]).subs(at))
    simp = lambda M: M.applyfunc(simplify)  # bounded clean-up (lagrange.simplification)  # noqa: E731
    return LinearModel(r.kept, simp(a), simp(g), simp(c), sp.zeros(n, 1), dict(about))
