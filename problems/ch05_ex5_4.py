"""Wells, Example 5.4 — double pendulum (Fig. 2-10): V and the generalized forces from it; spring-rod extension."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PotentialEnergy, Problem, Simulation

theta, phi, r1, r2 = coordinates("theta phi r1 r2")
m1, m2, g, R1, R2, k1, k2, r10, r20 = parameters("m1 m2 g R1 R2 k1 k2 r10 r20")


def _bobs(a, b):
    p1 = (a * sp.sin(theta), -a * sp.cos(theta))
    p2 = (p1[0] + b * sp.sin(phi), p1[1] - b * sp.cos(phi))
    return p1, p2


# Rigid rods of lengths R1, R2 (the book's r1, r2); Y up, angles from the downward vertical.
p1, p2 = _bobs(R1, R2)
rigid = System([theta, phi], bodies=[Particle(m1, p1), Particle(m2, p2)], V=m1 * g * p1[1] + m2 * g * p2[1],
               name="double pendulum")

# Extension: rods replaced by springs, r1 and r2 become coordinates.
q1, q2 = _bobs(r1, r2)
springy = System([r1, theta, r2, phi], bodies=[Particle(m1, q1), Particle(m2, q2)],
                 V=m1 * g * q1[1] + m2 * g * q2[1] + k1 * (r1 - r10) ** 2 / 2 + k2 * (r2 - r20) ** 2 / 2,
                 name="double spring pendulum")

PROBLEMS = [
    Problem(
        id="ex5.4",
        title="Double pendulum: V = -m1 g r1 cos(theta) - m2 g (r1 cos(theta) + r2 cos(phi)), F from -dV/dq",
        chapter=5,
        source="Wells, Example 5.4",
        system=rigid,
        answers=[
            PotentialEnergy(-m1 * g * R1 * sp.cos(theta) - m2 * g * (R1 * sp.cos(theta) + R2 * sp.cos(phi))),
            GeneralizedForces({theta: -(m1 + m2) * g * R1 * sp.sin(theta), phi: -m2 * g * R2 * sp.sin(phi)},
                              which="total"),
        ],
        simulation=Simulation(params={m1: 1, m2: 1, g: 9.81, R1: 1, R2: 1},
                              initial={theta: 0.5, phi: -0.3, theta.diff(t): 0, phi.diff(t): 0}, t_end=10),
    ),
    Problem(
        id="ex5.4-springs",
        title="Double pendulum with elastic rods: V += k1(r1-r10)^2/2 + k2(r2-r20)^2/2",
        chapter=5,
        source="Wells, Example 5.4 (extension with springs)",
        system=springy,
        answers=[
            GeneralizedForces({
                r1: (m1 + m2) * g * sp.cos(theta) - k1 * (r1 - r10),
                r2: m2 * g * sp.cos(phi) - k2 * (r2 - r20),
                theta: -(m1 + m2) * g * r1 * sp.sin(theta),
                phi: -m2 * g * r2 * sp.sin(phi),
            }, which="total"),
        ],
        simulation=Simulation(params={m1: 1, m2: 1, g: 9.81, k1: 100, k2: 80, r10: 1, r20: 1},
                              initial={r1: 1.1, theta: 0.5, r2: 1.0, phi: -0.3, r1.diff(t): 0, theta.diff(t): 0,
                                       r2.diff(t): 0, phi.diff(t): 0}, t_end=5),
        correction="F_r1 and F_r2 are DERIVED in the catalog (the book states the V extension only); "
        "F_theta and F_phi are the book's, with r1, r2 now variable.",
    ),
]
