"""Wells, Problem 2.23 — bar B pivoted at its centre with a pendulum hanging from each end."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

alpha, theta1, theta2 = coordinates("alpha theta1 theta2")
m1, m2, r1, r2, l, I = parameters("m1 m2 r1 r2 l I")
half = sp.Rational(1, 2)

# Bar ends at ∓l(cosα, sinα) (inferred); pendulum angles θ1, θ2 from the downward vertical.
E1 = (-l * sp.cos(alpha), -l * sp.sin(alpha))
E2 = (l * sp.cos(alpha), l * sp.sin(alpha))
system = System(
    [alpha, theta1, theta2],
    T=half * I * alpha.diff(t) ** 2,  # the bar: rotation about a fixed axis (2.38)
    bodies=[
        Particle(m1, (E1[0] + r1 * sp.sin(theta1), E1[1] - r1 * sp.cos(theta1)), name="m1"),
        Particle(m2, (E2[0] + r2 * sp.sin(theta2), E2[1] - r2 * sp.cos(theta2)), name="m2"),
    ],
    name="bar with two pendulums",
)

def _dof(s):
    # degrees of freedom = rank of the mass matrix at a generic point (exact rationals, 30-digit evaluation)
    pt = {q: sp.Rational(3 + i, 7 + 2 * i) for i, q in enumerate(s.coordinates)}
    pt.update({p: sp.Rational(11 + i, 9) for i, p in enumerate(s.parameters)})
    M = s.mass_matrix.subs(pt).evalf(30)
    return M.rank(iszerofunc=lambda v: abs(v) < 1e-20)


ad, t1d, t2d = alpha.diff(t), theta1.diff(t), theta2.diff(t)
PROBLEM = Problem(
    id="p2.23",
    title="Pivoted bar with pendulums at its ends: 3 DOF and T",
    chapter=2,
    source="Wells, Problem 2.23 (answer key)",
    system=system,
    answers=[
        KineticEnergy(
            half * m1 * (l**2 * ad**2 + r1**2 * t1d**2 - 2 * r1 * l * ad * t1d * sp.sin(theta1 - alpha))
            + half * m2 * (l**2 * ad**2 + r2**2 * t2d**2 + 2 * r2 * l * ad * t2d * sp.sin(theta2 - alpha))
            + half * I * ad**2
        ),
        Quantity("degrees of freedom (rank of the mass matrix)", _dof, 3),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 1.5, r1: 1, r2: 0.8, l: 0.5, I: 0.3},
        initial={alpha: 0.1, theta1: 0.2, theta2: -0.1, ad: 0, t1d: 0.5, t2d: 0},
        t_end=2.0,
    ),
    correction="The key prints 2r1 l α̇θ̇2 sin(θ2−α) in the m2 term; it must be r2 (the m2 pendulum has length "
    "r2; re-derived in the catalog, sym ✓). Geometry (bar ends at ∓l(cosα, sinα), angles from the downward "
    "vertical) inferred to match the printed signs.",
)
