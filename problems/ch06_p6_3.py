"""Wells, Problems 6.3 and 6.18 — two spheres in a viscous liquid, y1 = y + y3, y2 = y - y3 (Fig. 6-11)."""

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

y, y3 = coordinates("y y3")
m1, m2, a1, a2 = parameters("m1 m2 a1 a2")

y1, y2 = y + y3, y - y3
system = System([y, y3], bodies=[Particle(m1, (0, y1)), Particle(m2, (0, y2))],
                P=-a1 * y1.diff(t) ** 2 / 2 - a2 * y2.diff(t) ** 2 / 2, name="two spheres in a viscous liquid")

yd, y3d = y.diff(t), y3.diff(t)
PROBLEM = Problem(
    id="p6.3",
    title="Two spheres in a viscous liquid: F_y, F_y3 and P",
    chapter=6,
    source="Wells, Problem 6.3 (P form: Problem 6.18)",
    system=system,
    answers=[
        GeneralizedForces({y: -a1 * (y3d + yd) + a2 * (y3d - yd), y3: -a1 * (y3d + yd) - a2 * (y3d - yd)}),
        PowerFunction(-a1 * (yd + y3d) ** 2 / 2 - a2 * (yd - y3d) ** 2 / 2),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, a1: 0.5, a2: 0.3}, initial={y: 0, y3: 1, y.diff(t): 1, y3.diff(t): 0},
                          t_end=5),
    correction="The relations y1 = y + y3, y2 = y - y3 are implied by Problem 6.18 (figure not available).",
)
