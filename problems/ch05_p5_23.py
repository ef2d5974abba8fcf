"""Wells, Problem 5.23 — planar two-body Lagrangian (c.m. at rest) in r and in r2 (distance of m2 from the c.m.)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Simulation

r, r2, theta = coordinates("r r2 theta")
m1, m2, G = parameters("m1 m2 G")
M = m1 + m2
mu = m1 * m2 / M
u = (sp.cos(theta), sp.sin(theta))

# c.m. at rest at the origin; m1 and m2 on opposite sides, m1 d1 = m2 d2.
sys_r = System([r, theta], bodies=[Particle(m1, tuple(-m2 / M * r * e for e in u)),
                                   Particle(m2, tuple(m1 / M * r * e for e in u))],
               V=-G * m1 * m2 / r, name="two bodies, relative distance r")
sys_r2 = System([r2, theta], bodies=[Particle(m1, tuple(-m2 / m1 * r2 * e for e in u)),
                                     Particle(m2, tuple(r2 * e for e in u))],
                V=-G * m1 * m2 / (r2 + m2 / m1 * r2), name="two bodies, r2 from the c.m.")

sim = {m1: 1, m2: 2, G: 1}
PROBLEMS = [
    Problem(
        id="p5.23",
        title="Two-body planar L = (mu/2)(rd^2 + r^2 thd^2) + G m1 m2 / r",
        chapter=5,
        source="Wells, Problem 5.23",
        system=sys_r,
        answers=[KineticEnergy(mu / 2 * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2)),
                 PotentialEnergy(-G * m1 * m2 / r)],
        simulation=Simulation(params=sim, initial={r: 1, theta: 0, r.diff(t): 0, theta.diff(t): 1.2}, t_end=5),
        correction="OCR prints G m1 m2 / r^2 for the potential term; the Newtonian potential is G m1 m2 / r.",
    ),
    Problem(
        id="p5.23-r2",
        title="Two-body planar L in r2: (m2^2/(2 mu))(r2d^2 + r2^2 thd^2) + G m1^2 m2 / (M r2)",
        chapter=5,
        source="Wells, Problem 5.23",
        system=sys_r2,
        answers=[KineticEnergy(m2**2 / (2 * mu) * (r2.diff(t) ** 2 + r2**2 * theta.diff(t) ** 2)),
                 PotentialEnergy(-G * m1**2 * m2 / (M * r2))],
        simulation=Simulation(params=sim, initial={r2: 0.4, theta: 0, r2.diff(t): 0, theta.diff(t): 1.2}, t_end=5),
        correction="OCR prints m2^2/mu and r1^2 in the kinetic term; corrected (catalog, re-derived) to "
        "m2^2/(2 mu) (r2d^2 + r2^2 thd^2). The potential term is as printed.",
    ),
]
