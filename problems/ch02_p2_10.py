"""Wells, Problem 2.10(a) — bead on a wire fixed to table D2, both tables driven (θ1 = ω1 t, θ2 = ω2 t)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r, theta1, theta2 = coordinates("r theta1 theta2")
m, s, alpha0, omega1, omega2 = parameters("m s alpha0 omega1 omega2")

# Geometry of Fig. 2-21 / (2.31) with the wire along a straight line of D2 at the fixed angle alpha0
# (inferred: the figure is not available); the bead's distance r along the wire is the only coordinate.
beta = theta1 + theta2 + alpha0
system = System(
    [r],
    bodies=[Particle(m, (s * sp.cos(theta1) + r * sp.cos(beta), s * sp.sin(theta1) + r * sp.sin(beta)))],
    prescribed={theta1: omega1 * t, theta2: omega2 * t},
    name="bead on a wire on driven tables",
)

def _dof(s):
    # degrees of freedom = rank of the mass matrix at a generic point (exact rationals, 30-digit evaluation)
    pt = {q: sp.Rational(3 + i, 7 + 2 * i) for i, q in enumerate(s.coordinates)}
    pt.update({p: sp.Rational(11 + i, 9) for i, p in enumerate(s.parameters)})
    pt[t] = sp.Rational(2, 7)
    M = s.mass_matrix.subs(pt).evalf(30)
    return M.rank(iszerofunc=lambda v: abs(v) < 1e-20)


PROBLEM = Problem(
    id="p2.10",
    title="Bead on a wire carried by two driven tables: one degree of freedom",
    chapter=2,
    source="Wells, Problem 2.10(a)",
    system=system,
    answers=[Quantity("degrees of freedom (rank of the mass matrix)", _dof, 1)],
    simulation=Simulation(
        params={m: 1, s: 1.0, alpha0: 0.3, omega1: 1.0, omega2: 0.5},
        initial={r: 0.2, r.diff(t): 0.0},
        t_end=1.0,
    ),
    correction="Wire shape inferred (straight, at a fixed angle on D2); the DOF count does not depend on it. "
    "Part (b) (board hinged to a rigid body on springs, 7 DOF) needs rigid bodies and is not included.",
)
