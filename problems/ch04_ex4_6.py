"""Wells, Example 4.6 — planar double pendulum with inextensible strings."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

theta, phi = coordinates("theta phi")
m1, m2, r1, r2, g = parameters("m1 m2 r1 r2 g")

# Y downward; both angles from the downward vertical.
X1, Y1 = r1 * sp.sin(theta), r1 * sp.cos(theta)
X2, Y2 = X1 + r2 * sp.sin(phi), Y1 + r2 * sp.cos(phi)
system = System(
    [theta, phi],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    forces=m1 * g * delta(Y1) + m2 * g * delta(Y2),
    name="double pendulum",
)

thd, phd = theta.diff(t), phi.diff(t)
Fth = -(m1 + m2) * g * r1 * sp.sin(theta)
Fph = -m2 * g * r2 * sp.sin(phi)
PROBLEM = Problem(
    id="ex4.6",
    title="Double pendulum: T, generalized forces, equations of motion",
    chapter=4,
    source="Wells, Example 4.6",
    system=system,
    answers=[
        KineticEnergy(m1 / 2 * r1**2 * thd**2
                      + m2 / 2 * (r1**2 * thd**2 + r2**2 * phd**2 + 2 * r1 * r2 * thd * phd * sp.cos(phi - theta))),
        GeneralizedForces({theta: Fth, phi: Fph}),
        EquationsOfMotion([
            sp.Eq((m1 + m2) * r1**2 * theta.diff(t, 2) + m2 * r1 * r2 * phi.diff(t, 2) * sp.cos(phi - theta)
                  - m2 * r1 * r2 * phd**2 * sp.sin(phi - theta), Fth),
            sp.Eq(m2 * r2**2 * phi.diff(t, 2) + m2 * r1 * r2 * theta.diff(t, 2) * sp.cos(phi - theta)
                  + m2 * r1 * r2 * thd**2 * sp.sin(phi - theta), Fph),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, r1: 1, r2: 1, g: 9.81},
                          initial={theta: 0.5, phi: -0.3, thd: 0, phd: 0}, t_end=5),
)
