"""Wells, Example 4.11 — string through rings: m1 on a fixed cone, m2 between planes oscillating about a vertical axis."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Simulation

q1, q2, q3 = coordinates("q1 q2 q3")
m1, m2, th1, h, c, l, A, w, g = parameters("m1 m2 theta_1 h c l A omega g")

# r1 = q1, r2 = c − q1 (string through the rings); the planes P turn by α = A sin ωt.
al = A * sp.sin(w * t)
Z1 = h - q1 * sp.cos(th1)
Z2 = h - (c - q1) * sp.cos(q3)
rho2 = l + (c - q1) * sp.sin(q3)
system = System(
    [q1, q2, q3],
    bodies=[
        Particle(m1, (q1 * sp.cos(q2) * sp.sin(th1), q1 * sp.sin(q2) * sp.sin(th1), Z1), name="m1"),
        Particle(m2, (rho2 * sp.cos(al), rho2 * sp.sin(al), Z2), name="m2"),
    ],
    forces=-m1 * g * delta(Z1) - m2 * g * delta(Z2),
    name="cone and oscillating planes",
)

PROBLEM = Problem(
    id="ex4.11",
    title="String through rings: cone and oscillating planes — kinetic energy",
    chapter=4,
    source="Wells, Example 4.11",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m1 * (q1.diff(t) ** 2 + q1**2 * q2.diff(t) ** 2 * sp.sin(th1) ** 2)
                      + sp.Rational(1, 2) * m2 * (q1.diff(t) ** 2 + (c - q1) ** 2 * q3.diff(t) ** 2
                                                   + rho2**2 * A**2 * w**2 * sp.cos(w * t) ** 2)),
        # Gravity forces: derived in the catalog (the book stops at T).
        GeneralizedForces({q1: m1 * g * sp.cos(th1) - m2 * g * sp.cos(q3), q2: 0,
                           q3: -m2 * g * (c - q1) * sp.sin(q3)}),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, th1: 0.5, c: 2, l: 0.5, A: 0.3, w: 2, g: 9.81},
                          initial={q1: 1, q2: 0, q3: 0.2, q1.diff(t): 0, q2.diff(t): 1, q3.diff(t): 0}, t_end=1),
    ranges={"theta_1": (0.2, 1.2), "c": (2.0, 3.0)},
    correction="The book gives T only; the gravity forces are derived in the catalog.",
)
