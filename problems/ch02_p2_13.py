"""Wells, Problem 2.13 — rod of mass M, length l, with its ends on the X and Y axes."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
M, l = parameters("M l")

# Ends at (l cosθ, 0) and (0, l sinθ): centre of mass at (l/2)(cosθ, sinθ); θ is the rod angle to X.
# Centre-of-mass theorem (2.47): T = ½ M v_c² + ½ (M l²/12) θ̇².
system = System(
    [theta],
    bodies=[Particle(M, (l / 2 * sp.cos(theta), l / 2 * sp.sin(theta)), name="rod centre")],
    T=sp.Rational(1, 2) * (M * l**2 / 12) * theta.diff(t) ** 2,
    name="rod sliding on two axes",
)

def _dof(s):
    # degrees of freedom = rank of the mass matrix at a generic point (exact rationals, 30-digit evaluation)
    pt = {q: sp.Rational(3 + i, 7 + 2 * i) for i, q in enumerate(s.coordinates)}
    pt.update({p: sp.Rational(11 + i, 9) for i, p in enumerate(s.parameters)})
    M = s.mass_matrix.subs(pt).evalf(30)
    return M.rank(iszerofunc=lambda v: abs(v) < 1e-20)


PROBLEM = Problem(
    id="p2.13",
    title="Rod with its ends on the X and Y axes: 1 DOF, T = M l^2 θ'^2 / 6",
    chapter=2,
    source="Wells, Problem 2.13",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 6) * M * l**2 * theta.diff(t) ** 2),
        Quantity("degrees of freedom (rank of the mass matrix)", _dof, 1),
    ],
    simulation=Simulation(params={M: 1, l: 1}, initial={theta: 0.5, theta.diff(t): 1.0}, t_end=2.0),
)
