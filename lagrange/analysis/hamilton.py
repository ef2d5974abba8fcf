r"""Hamilton's equations (Wells ch. 16).

Momenta ``p_r = ∂L/∂q̇_r``; since T is quadratic in the velocities, ``p = M q̇ + B`` (Wells' split 2.55)
and ``q̇ = M⁻¹(p − B)``. The Legendre transform gives

.. math:: H = \sum_r p_r\dot q_r - L = T_2 - T_0 + V \quad (16.8),

equal to the energy only when nothing moves (no t in the transformation equations). Canonical
equations with the non-potential forces ``Q = F_q + ∂P/∂q̇ − ∂D/∂q̇`` (Wells 16.6):

.. math:: \dot q_r = \frac{\partial H}{\partial p_r},\qquad \dot p_r = -\frac{\partial H}{\partial q_r} + Q_r,
          \qquad \frac{dH}{dt} = \sum_r Q_r\dot q_r + \frac{\partial H}{\partial t}\quad (16.11).
"""

from __future__ import annotations

import sympy as sp

from ..conventions import t
from ..errors import AnalysisError
from ..limits import bounded
from ..model.coordinates import coordinate_name, to_functions
from ..records import record
from ..safe_sympify import sympify as _sympify
from ..simplification import simplify

__all__ = ["HamiltonianForm", "hamiltonian"]


@record(frozen=True)
class HamiltonianForm:
    """H and the canonical equations in plain symbols q, p (and t).

    Attributes
    ----------
    q, p : tuples of Symbols (``p_<name>`` for the momenta)
    momenta : tuple — ``p_r = ∂L/∂q̇_r`` in (q, q̇)
    velocities : tuple — ``q̇_r(q, p)``
    H : the Hamiltonian in (q, p, t)
    qdot, pdot : tuples — right-hand sides of the canonical equations
    nonconservative : tuple — ``Q_r`` in (q, p, t)
    """

    coordinates: tuple
    q: tuple
    p: tuple
    momenta: tuple
    velocities: tuple
    H: sp.Expr
    qdot: tuple
    pdot: tuple
    nonconservative: tuple

    def energy_rate(self) -> sp.Expr:
        """``dH/dt`` along the canonical flow, computed from the equations: Σ ∂H/∂q q̇ + ∂H/∂p ṗ + ∂H/∂t."""
        return (sum((sp.diff(self.H, q) * qd for q, qd in zip(self.q, self.qdot)), sp.S.Zero)
                + sum((sp.diff(self.H, p) * pd for p, pd in zip(self.p, self.pdot)), sp.S.Zero)
                + sp.diff(self.H, t))

    def expected_energy_rate(self) -> sp.Expr:
        """Wells (16.11): ``Σ Q_r q̇_r + ∂H/∂t`` — must equal :meth:`energy_rate`."""
        power = sum((Q * qd for Q, qd in zip(self.nonconservative, self.qdot)), sp.S.Zero)
        return power + sp.diff(self.H, t)

    def H_functions(self) -> sp.Expr:
        """H with q as coordinate functions (for printing next to the equations)."""
        return to_functions(self.H, self.coordinates)

    def _repr_latex_(self) -> str:
        from ..display import hamiltonian_latex

        return hamiltonian_latex(self)


@bounded("Hamiltonian")
def hamiltonian(system) -> HamiltonianForm:
    """The Hamiltonian form of an unconstrained system (Wells ch. 16).

    Raises :class:`~lagrange.errors.AnalysisError` for a constrained system (eliminate the constraints
    first with :func:`lagrange.eliminate`)."""
    eqs = system.derived
    if eqs.m:
        raise AnalysisError(f"Hamilton's equations are formed for unconstrained systems; this one has the constraints "
                            f"{', '.join(eqs.constraint_names)}: eliminate them first (lagrange.eliminate)")
    q, qd = list(eqs.q), list(eqs.qd)
    p = [sp.Symbol(f"p_{coordinate_name(c)}", real=True) for c in system.coordinates]
    L = eqs.kinetic - eqs.potential
    momenta = [sp.diff(L, v) for v in qd]
    M = sp.Matrix(eqs.mass_matrix)
    B = sp.Matrix([m.subs({v: 0 for v in qd}) for m in momenta])
    if M.is_diagonal():
        vel = [(pi - bi) / M[i, i] for i, (pi, bi) in enumerate(zip(p, B))]
    else:
        vel = list(M.LUsolve(sp.Matrix(p) - B))  # no symbolic inverse: it explodes beyond 3 coordinates
    vel = [simplify(v) if sp.count_ops(v) < 120 else sp.cancel(v) for v in vel]
    to_p = dict(zip(qd, vel))
    H = sum((pi * vi for pi, vi in zip(p, vel)), sp.S.Zero) - L.subs(to_p)
    H = simplify(H) if sp.count_ops(H) < 250 else sp.cancel(sp.together(H))
    Q = [_sympify(e).subs(to_p) for e in eqs.nonconservative]
    qdot = tuple(sp.diff(H, pi) for pi in p)
    pdot = tuple(-sp.diff(H, qi) + Qi for qi, Qi in zip(q, Q))
    return HamiltonianForm(system.coordinates, tuple(q), tuple(p), tuple(momenta), tuple(vel), H, qdot, pdot,
                           tuple(Q))
