"""Wells, Problem 4.15 — dumbbell attracted to the origin, f_i = c m_i / r_i²; coordinates (x, y, θ) of the CM."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
m1, m2, l1, l2, c = parameters("m1 m2 l1 l2 c")

P1 = (x - l1 * sp.cos(theta), y - l1 * sp.sin(theta))
P2 = (x + l2 * sp.cos(theta), y + l2 * sp.sin(theta))
r1 = sp.sqrt(P1[0] ** 2 + P1[1] ** 2)
r2 = sp.sqrt(P2[0] ** 2 + P2[1] ** 2)
# Central attractions: δW = −(c m1/r1²) δr1 − (c m2/r2²) δr2.
system = System(
    [x, y, theta],
    bodies=[Particle(m1, P1, name="m1"), Particle(m2, P2, name="m2")],
    forces=-c * m1 / r1**2 * delta(r1) - c * m2 / r2**2 * delta(r2),
    name="dumbbell in a central inverse-square field",
)

s, co = sp.sin(theta), sp.cos(theta)
PROBLEM = Problem(
    id="p4.15",
    title="Dumbbell attracted to the origin by inverse-square forces: generalized forces",
    chapter=4,
    source="Wells, Problem 4.15",
    system=system,
    answers=[
        GeneralizedForces({
            x: -c * (m1 / r1**3 * (x - l1 * co) + m2 / r2**3 * (x + l2 * co)),
            y: -c * (m1 / r1**3 * (y - l1 * s) + m2 / r2**3 * (y + l2 * s)),
            theta: -c * (m1 / r1**3 * (x * l1 * s - y * l1 * co) + m2 / r2**3 * (y * l2 * co - x * l2 * s)),
        }),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, l1: 0.1, l2: 0.1, c: 1},
                          initial={x: 1, y: 0, theta: 0.3, x.diff(t): 0, y.diff(t): 1, theta.diff(t): 0}, t_end=3),
    correction="The second part (coordinates r1, alpha, theta) has no printed answer and is not included.",
)
