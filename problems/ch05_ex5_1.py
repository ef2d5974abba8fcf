"""Wells, Example 5.1 — pendulum bob on a rubber band (elastic pendulum), L = T - V."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Simulation

r, theta = coordinates("r theta")
m, g, k, r0 = parameters("m g k r0")

# θ from the downward vertical; X horizontal, Y up.
bob = (r * sp.sin(theta), -r * sp.cos(theta))
system = System([r, theta], bodies=[Particle(m, bob)], V=k * (r - r0) ** 2 / 2 + m * g * bob[1],
                name="elastic pendulum")

PROBLEM = Problem(
    id="ex5.1",
    title="Elastic pendulum (bob on a rubber band)",
    chapter=5,
    source="Wells, Example 5.1",
    system=system,
    answers=[
        KineticEnergy(m * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2) / 2),
        PotentialEnergy(k * (r - r0) ** 2 / 2 - m * g * r * sp.cos(theta)),
        EquationsOfMotion(
            [
                sp.Eq(m * r.diff(t, 2) - m * r * theta.diff(t) ** 2 + k * (r - r0) - m * g * sp.cos(theta), 0),
                sp.Eq(m * r**2 * theta.diff(t, 2) + 2 * m * r * r.diff(t) * theta.diff(t)
                      + m * g * r * sp.sin(theta), 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1},
                          initial={r: 1.2, theta: 0.6, r.diff(t): 0, theta.diff(t): 0}, t_end=10),
)
