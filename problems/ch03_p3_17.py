"""Wells, Problem 3.17 — pendulum whose string passes through a hole in a board oscillating vertically, s = A sin ωt."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

theta = coordinates("theta")
m, g, l, A, w = parameters("m g l A omega")

# Hole at height −s (s downward, inferred from the signs), string length below the hole r = l − s.
s = A * sp.sin(w * t)
rr = l - s
Y = -s - rr * sp.cos(theta)
system = System(
    [theta],
    bodies=[Particle(m, (rr * sp.sin(theta), Y), name="bob")],
    forces=-m * g * delta(Y),
    name="pendulum through an oscillating hole",
)

c = sp.cos(w * t)
T_book = sp.Rational(1, 2) * m * (
    2 * A**2 * w**2 * c**2 + (l - A * sp.sin(w * t)) ** 2 * theta.diff(t) ** 2
    - 2 * A**2 * w**2 * c**2 * sp.cos(theta)
    - 2 * (l - A * sp.sin(w * t)) * A * w * theta.diff(t) * c * sp.sin(theta)
)

PROBLEM = Problem(
    id="p3.17",
    title="Pendulum through a hole in a vertically oscillating board: T, F_theta and equation of motion",
    chapter=3,
    source="Wells, Problem 3.17",
    system=system,
    answers=[
        KineticEnergy(T_book),
        GeneralizedForces({theta: -m * g * (l - A * sp.sin(w * t)) * sp.sin(theta)}),
        # Derived in the catalog from the book's T and F_theta (divided by m(l − A sin ωt)).
        EquationsOfMotion([
            sp.Eq((l - A * sp.sin(w * t)) * theta.diff(t, 2) - 2 * A * w * c * theta.diff(t)
                  + (g + A * w**2 * sp.sin(w * t)) * sp.sin(theta), 0)
        ]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, l: 1, A: 0.1, w: 5}, initial={theta: 0.3, theta.diff(t): 0},
                          t_end=5),
    ranges={"A": (0.1, 0.5)},
    correction="s taken downward (inferred from the signs of the printed T). The equation of motion is derived in "
               "the catalog from the book's T and F_theta; the book prints T and F_theta only.",
)
