"""Wells, Example 5.10 — particle on a smooth plane tied by a spring whose end is driven as s = A sin(wt) along X."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PotentialEnergy, Problem, Simulation

x, y = coordinates("x y")
m, k, l0, A, w = parameters("m k l0 A omega")

end = (A * sp.sin(w * t), 0)
length = sp.sqrt((x - end[0]) ** 2 + (y - end[1]) ** 2)
system = System([x, y], bodies=[Particle(m, (x, y))], V=k * (length - l0) ** 2 / 2, name="spring with driven end")

d = sp.sqrt((x - A * sp.sin(w * t)) ** 2 + y**2)
PROBLEM = Problem(
    id="ex5.10",
    title="Spring end driven along X: V = k{[(x - A sin wt)^2 + y^2]^(1/2) - l0}^2 / 2",
    chapter=5,
    source="Wells, Example 5.10",
    system=system,
    answers=[
        PotentialEnergy(k * (d - l0) ** 2 / 2),
        GeneralizedForces({x: -k * (d - l0) * (x - A * sp.sin(w * t)) / d, y: -k * (d - l0) * y / d}, which="total"),
    ],
    simulation=Simulation(params={m: 1, k: 10, l0: 1, A: 0.2, w: 2},
                          initial={x: 1.2, y: 0.3, x.diff(t): 0, y.diff(t): 0.5}, t_end=5),
    correction="The book writes F_y 'similar'; it is taken as the y-analogue -k(d - l0) y / d.",
)
