"""Wells, Example 4.10 — charged dumbbell (−Q1 on m1, +Q2 on m2) in uniform E (along X) and B (along Z), planar."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, Q1, Q2, E, B = parameters("m1 m2 l1 l2 Q1 Q2 E B")

p1 = Particle(m1, (x - l1 * sp.cos(theta), y - l1 * sp.sin(theta)), name="m1 (charge -Q1)")
p2 = Particle(m2, (x + l2 * sp.cos(theta), y + l2 * sp.sin(theta)), name="m2 (charge +Q2)")


def lorentz(p, Q):
    """Wells (4.13) with E = (E, 0, 0), B = (0, 0, B): F = Q(E + v × B), v the particle's inertial velocity."""
    vx, vy, _ = p.velocity
    return Force(p, (Q * E + Q * vy * B, -Q * vx * B, 0))


system = System([x, y, theta], bodies=[p1, p2], forces=[lorentz(p1, -Q1), lorentz(p2, Q2)],
                name="charged dumbbell in E and B")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="ex4.10",
    title="Charged dumbbell in crossed uniform E and B: velocity-dependent generalized forces",
    chapter=4,
    source="Wells, Example 4.10",
    system=system,
    answers=[
        GeneralizedForces({
            x: (Q2 - Q1) * E + B * (Q2 - Q1) * yd + B * (Q2 * l2 + Q1 * l1) * thd * sp.cos(theta),
            y: B * (Q1 - Q2) * xd + B * (Q1 * l1 + Q2 * l2) * thd * sp.sin(theta),
            theta: -(Q1 * l1 + Q2 * l2) * (E * sp.sin(theta) + B * (xd * sp.cos(theta) + yd * sp.sin(theta))),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, l1: 0.5, l2: 0.5, Q1: 1, Q2: 1, E: 1, B: 2},
                          initial={x: 0, y: 0, theta: 0.2, xd: 0, yd: 0, thd: 0}, t_end=3),
)
