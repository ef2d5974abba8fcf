"""Wells, Sec. 5.5 — potential energies: pendulum, spring referred to different points, two charges."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PotentialEnergy, Problem, Simulation

theta, x2, r = coordinates("theta x2 r")
m, g, rr, k, s, l0, Q1, Q2 = parameters("m g r k s l0 Q1 Q2")

# (1) Simple pendulum, θ from the downward vertical, bob height measured up from the lowest point.
bob = (rr * sp.sin(theta), -rr * sp.cos(theta))
pendulum = System([theta], bodies=[Particle(m, bob)], V=m * g * (bob[1] + rr), name="simple pendulum")

# (2) Spring of natural length l0 from a wall to the particle; the particle is x2 from a point a distance s
# from the wall, so the stretch is x1 = s - l0 - x2 (s = x1 + x2 + l0).
spring = System([x2], bodies=[Particle(m, (x2,))], V=k * (s - x2 - l0) ** 2 / 2, name="spring, shifted origin")

# (3) Charge Q2 (mass m) moving on a line a distance r from a fixed charge Q1: Coulomb force Q1Q2/r^2, repulsive.
charges = System([r], bodies=[Particle(m, (r,))], forces={r: Q1 * Q2 / r**2}, name="two charges")

PROBLEMS = [
    Problem(
        id="sec5.5-pendulum",
        title="Pendulum: V = mgr(1 - cos θ) = mg(l - r cos θ) = -mgr cos θ up to constants",
        chapter=5,
        source="Wells, Sec. 5.5(1)",
        system=pendulum,
        answers=[
            PotentialEnergy(m * g * rr * (1 - sp.cos(theta))),
            PotentialEnergy(-m * g * rr * sp.cos(theta)),
        ],
        simulation=Simulation(params={m: 1, g: 9.81, rr: 1}, initial={theta: 0.5, theta.diff(t): 0}, t_end=5),
    ),
    Problem(
        id="sec5.5-spring",
        title="Spring referred to a different point: V = k x1^2/2 = -k(s - l0) x2 + k x2^2/2 + const",
        chapter=5,
        source="Wells, Sec. 5.5(2)",
        system=spring,
        answers=[PotentialEnergy(-k * (s - l0) * x2 + k * x2**2 / 2)],
        simulation=Simulation(params={m: 1, k: 4, s: 3, l0: 1}, initial={x2: 1.5, x2.diff(t): 0}, t_end=5),
    ),
    Problem(
        id="sec5.5-charges",
        title="Two point charges: V = +Q1 Q2 / r",
        chapter=5,
        source="Wells, Sec. 5.5(3)",
        system=charges,
        answers=[
            # The repulsive Coulomb force is applied directly; it must equal -dV/dr of the book's V = Q1Q2/r.
            GeneralizedForces({r: -sp.diff(Q1 * Q2 / r, r)}, which="applied"),
        ],
        simulation=Simulation(params={m: 1, Q1: 1, Q2: 1}, initial={r: 1, r.diff(t): 0}, t_end=3),
    ),
]
