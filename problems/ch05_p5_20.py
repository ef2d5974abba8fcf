"""Wells, Problem 5.20 — two-body Lagrangian in terms of rho1, the distance of m1 from the centre of mass."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Simulation

x, y, z, rho1, theta = coordinates("x y z rho1 theta")
m1, m2, G = parameters("m1 m2 G")
M = m1 + m2
mu = m1 * m2 / M

# Planar relative motion; m1 at distance rho1 from the c.m. (x, y, z), m2 opposite at m1 rho1 / m2.
u = (sp.cos(theta), sp.sin(theta), 0)
body1 = Particle(m1, tuple(c - rho1 * e for c, e in zip((x, y, z), u, strict=True)))
body2 = Particle(m2, tuple(c + m1 / m2 * rho1 * e for c, e in zip((x, y, z), u, strict=True)))
separation = rho1 + m1 / m2 * rho1
T_bodies = sp.fu(sp.expand(sp.cancel(body1.kinetic_energy() + body2.kinetic_energy())))
system = System([x, y, z, rho1, theta], T=T_bodies, V=-G * m1 * m2 / separation, name="two bodies, rho1 form")

PROBLEM = Problem(
    id="p5.20",
    title="Two-body L = (M/2)(xd^2+yd^2+zd^2) + (m1 M/(2 m2))(rho1d^2 + rho1^2 thd^2) + G mu m2 / rho1",
    chapter=5,
    source="Wells, Problem 5.20",
    system=system,
    answers=[
        KineticEnergy(M / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2 + z.diff(t) ** 2)
                      + m1 * M / (2 * m2) * (rho1.diff(t) ** 2 + rho1**2 * theta.diff(t) ** 2)),
        PotentialEnergy(-G * mu * m2 / rho1),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, G: 1},
                          initial={x: 0, y: 0, z: 0, rho1: 0.7, theta: 0, x.diff(t): 0.1, y.diff(t): 0,
                                   z.diff(t): 0, rho1.diff(t): 0, theta.diff(t): 1.0}, t_end=5),
    correction="OCR prints rho1^2 for the first rho1d^2 in (rho1d^2 + rho1^2 thd^2); a kinetic term needs the rate.",
)
