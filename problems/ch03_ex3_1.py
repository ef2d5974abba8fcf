"""Wells, Example 3.1 — projectile in rectangular coordinates, Z vertical."""

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x, y, z = coordinates("x y z")
m, g = parameters("m g")

# Gravity by virtual work: δW = −m g δz.
system = System([x, y, z], bodies=[Particle(m, (x, y, z), name="projectile")], forces=-m * g * delta(z),
                name="projectile")

PROBLEM = Problem(
    id="ex3.1",
    title="Projectile: m x'' = 0, m y'' = 0, m z'' = -m g",
    chapter=3,
    source="Wells, Example 3.1",
    system=system,
    answers=[
        KineticEnergy(m / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2 + z.diff(t) ** 2)),
        GeneralizedForces({x: 0, y: 0, z: -m * g}),
        EquationsOfMotion([m * x.diff(t, 2), m * y.diff(t, 2), m * z.diff(t, 2) + m * g], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81}, initial={x: 0, y: 0, z: 0, x.diff(t): 3.0, y.diff(t): 1.0,
                                                           z.diff(t): 10.0}, t_end=2.0),
)
