"""Wells, Problem 1.10 — the Sec. 1.9 spring system inside a car with constant acceleration a_x."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation

x1, x2, s = coordinates("x1 x2 s")
m1, m2, k1, k2, A, omega, a_x = parameters("m1 m2 k1 k2 A omega a_x")

car = sp.Rational(1, 2) * a_x * t**2  # position of the car; x1, x2, s are measured in the car
system = System(
    [x1, x2],
    bodies=[Particle(m1, (car + x1,), name="m1"), Particle(m2, (car + x2,), name="m2")],
    V=sp.Rational(1, 2) * k1 * (x1 - s) ** 2 + sp.Rational(1, 2) * k2 * (x2 - x1) ** 2,
    prescribed={s: A * sp.sin(omega * t)},
    name="driven two-mass spring system in an accelerating car",
)

PROBLEM = Problem(
    id="p1.10",
    title="Sec. 1.9 system in a car with constant acceleration a_x",
    chapter=1,
    source="Wells, Problem 1.10",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq(m1 * x1.diff(t, 2) + (k1 + k2) * x1 - k2 * x2, k1 * A * sp.sin(omega * t) - m1 * a_x),
                sp.Eq(m2 * x2.diff(t, 2) + k2 * x2 - k2 * x1, -m2 * a_x),
            ],
            per_equation=True,
        ),
    ],
    units="CGS in the simulation (grams, dyn/cm, cm, rad/s)",
    simulation=Simulation(
        params={m1: 400, m2: 300, A: 5, k1: 60000, k2: 50000, omega: 12, a_x: 200},
        initial={x1: 3.0, x2: 4.0, x1.diff(t): 0.0, x2.diff(t): 0.0},
        t_end=2.0,
    ),
)
