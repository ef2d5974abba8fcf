"""Wells, Sec. 5.6 — generalized force from V: pendulum V = -mgr cos θ gives F_θ = -mgr sin θ."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

theta = coordinates("theta")
m, g, r = parameters("m g r")

system = System([theta], bodies=[Particle(m, (r * sp.sin(theta), -r * sp.cos(theta)))],
                V=-m * g * r * sp.cos(theta), name="simple pendulum")

PROBLEM = Problem(
    id="sec5.6",
    title="F_theta = -dV/dtheta = -mgr sin(theta) for the pendulum",
    chapter=5,
    source="Wells, Sec. 5.6, eq. (5.7)",
    system=system,
    answers=[GeneralizedForces({theta: -m * g * r * sp.sin(theta)}, which="total")],
    simulation=Simulation(params={m: 1, g: 9.81, r: 1}, initial={theta: 1.0, theta.diff(t): 0}, t_end=5),
)
