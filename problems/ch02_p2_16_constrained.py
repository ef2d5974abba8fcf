"""Wells, Problem 2.16 with the rod as a constraint — two particles on a light rod of length l, in a plane.

Cartesian multiplier form: (x1, y1, x2, y2) with ``Holonomic((x2 − x1)² + (y2 − y1)² − l²)``. A for m1 is
−2(x2 − x1, y2 − y1), so the rod force on m1 is −2 λ l e12 (e12 the unit vector from m1 to m2): a rod in
tension τ (pulling the particles together) has λ = −τ/(2 l). For the free dumbbell (no applied forces) the
tension is the centripetal force of the relative motion, τ = μ |v2 − v1|²/l with μ = m1 m2/(m1 + m2)
(derived; the book asks only for DOF = 3 and T).

Polar multiplier form, the book's (r, θ, φ) plus the superfluous rod length ρ: m1 at polar (r, θ),
m2 = m1 + ρ (cos φ, sin φ), constraint ρ − l = 0. A = (0, 0, 0, 1): λ = 𝓕_ρ, the rod's force on m2 along
+e(φ), i.e. λ = −τ = −μ l φ̇². Eliminating ρ = l gives the book's T (OCR-corrected, catalog).
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, Problem, Quantity, Simulation

x1, y1, x2, y2 = coordinates("x1 y1 x2 y2")
r, th, ph, rho = coordinates("r theta phi rho")
m1, m2, l = parameters("m1 m2 l")
mu = m1 * m2 / (m1 + m2)

system = System(
    [x1, y1, x2, y2],
    bodies=[Particle(m1, (x1, y1), name="m1"), Particle(m2, (x2, y2), name="m2")],
    constraints=[Holonomic((x2 - x1) ** 2 + (y2 - y1) ** 2 - l**2, name="rod")],
    name="two particles on a light rod (Cartesian, multipliers)",
)

p1 = (r * sp.cos(th), r * sp.sin(th))
system_polar = System(
    [r, th, ph, rho],
    bodies=[Particle(m1, p1, name="m1"),
            Particle(m2, (p1[0] + rho * sp.cos(ph), p1[1] + rho * sp.sin(ph)), name="m2")],
    constraints=[Holonomic(rho - l, name="rod")],
    name="two particles on a light rod (r, theta, phi, rho; multipliers)",
)
reduced = eliminate(system_polar, {rho: l})

PARAMS = {m1: 1.0, m2: 2.0, l: 1.0}
# on the rod: equal speeds along it (x1_dot = x2_dot), the state the run projected 0.3 and 0.1 to before
INITIAL = {x1: 0.0, y1: 0.0, x2: 1.0, y2: 0.0, x1.diff(t): 0.2, y1.diff(t): -0.4, x2.diff(t): 0.2, y2.diff(t): 0.8}
vrel2 = (x2.diff(t) - x1.diff(t)) ** 2 + (y2.diff(t) - y1.diff(t)) ** 2
INITIAL_P = {r: 1.0, th: 0.3, ph: 1.0, rho: 1.0, r.diff(t): 0.2, th.diff(t): 0.5, ph.diff(t): 1.2, rho.diff(t): 0.0}

T_book = (sp.Rational(1, 2) * (m1 + m2) * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2)
          + sp.Rational(1, 2) * m2 * (l**2 * ph.diff(t) ** 2 - 2 * l * r.diff(t) * ph.diff(t) * sp.sin(ph - th)
                                      + 2 * l * r * th.diff(t) * ph.diff(t) * sp.cos(ph - th)))


def dof(s):
    return sp.Integer(len(s.coordinates) - len(s.derived.constraint_names))


PROBLEMS = [
    Problem(
        id="p2.16-multipliers",
        title="Two particles on a light rod: (x2-x1)^2 + (y2-y1)^2 = l^2 as a multiplier; DOF = 3; rod tension",
        chapter=2,
        source="Wells, Problem 2.16 (answer key)",
        system=system,
        answers=[
            Quantity("degrees of freedom (4 coordinates - 1 constraint)", dof, sp.Integer(3)),
            ConstraintForce("rod", -mu * vrel2 / (2 * l**2), PARAMS, INITIAL, t_end=3),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=5),
        correction="The book gives DOF and T only; the rod tension τ = μ|v2 − v1|²/l is derived (free dumbbell).",
    ),
    Problem(
        id="p2.16-multipliers-polar",
        title="Two particles on a light rod in (r, theta, phi, rho) with rho = l as a multiplier; rod tension",
        chapter=2,
        source="Wells, Problem 2.16 (answer key)",
        system=system_polar,
        answers=[
            Quantity("degrees of freedom (4 coordinates - 1 constraint)", dof, sp.Integer(3)),
            ConstraintForce("rod", -mu * l * ph.diff(t) ** 2, PARAMS, INITIAL_P, t_end=3),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL_P, t_end=3),
        correction="The rod force λ = −μ l φ̇² is derived (the book gives DOF and T only).",
    ),
    Problem(
        id="p2.16-multipliers-reduced",
        title="Two particles on a light rod: rho = l eliminated gives the book's T in (r, theta, phi)",
        chapter=2,
        source="Wells, Problem 2.16 (answer key)",
        system=reduced,
        answers=[KineticEnergy(T_book)],
        simulation=Simulation(params=PARAMS, initial={r: 1.0, th: 0.3, ph: 1.0, r.diff(t): 0.2,
                                                       th.diff(t): 0.5, ph.diff(t): 1.2}, t_end=3),
        correction="The key prints '(ẋ² + ẏ²)' and '2 l r φ̇ sin'; the corrected T is the catalog's (sym ✓).",
    ),
]
