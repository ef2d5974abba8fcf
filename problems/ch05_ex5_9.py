"""Wells, Example 5.9 — pendulum whose string is pulled up through a hole at constant speed v: V(theta, t)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, PotentialEnergy, Problem, Simulation

theta = coordinates("theta")
m, g, r0, v = parameters("m g r0 v")
r = r0 - v * t  # prescribed string length

bob = (r * sp.sin(theta), -r * sp.cos(theta))
system = System([theta], bodies=[Particle(m, bob)], V=m * g * bob[1], name="pendulum with shortening string")

PROBLEM = Problem(
    id="ex5.9",
    title="String pulled through a hole (r = r0 - v t): V = -m g (r0 - v t) cos(theta), time-dependent",
    chapter=5,
    source="Wells, Example 5.9",
    system=system,
    answers=[
        PotentialEnergy(-m * g * (r0 - v * t) * sp.cos(theta)),
        GeneralizedForces({theta: -m * g * (r0 - v * t) * sp.sin(theta)}, which="total"),
        # Not per equation: the book's form is the derived one divided by m r (a function of t).
        EquationsOfMotion([sp.Eq((r0 - v * t) * theta.diff(t, 2) - 2 * v * theta.diff(t) + g * sp.sin(theta), 0)]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, r0: 2, v: 0.3}, initial={theta: 0.3, theta.diff(t): 0}, t_end=5),
    ranges={"v": (0.1, 1.0)},
    correction="The equation of motion is DERIVED in the catalog (the book gives V and F_theta); singular at t = r0/v.",
)
