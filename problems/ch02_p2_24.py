"""Wells, Problem 2.24 — framework accelerating upward at a, sliding mass m1 with a pendulum m2 below it."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EnergySplit, KineticEnergy, Problem, Simulation

y, theta = coordinates("y theta")
m1, m2, r, a, v0 = parameters("m1 m2 r a v0")
half = sp.Rational(1, 2)

h = v0 * t + half * a * t**2  # height of the framework (velocity v0 at t = 0)
# m1 slides vertically, y measured downward from the framework; m2 hangs on a rod r below m1 (inferred).
system = System(
    [y, theta],
    bodies=[
        Particle(m1, (0, h - y), name="m1"),
        Particle(m2, (r * sp.sin(theta), h - y - r * sp.cos(theta)), name="m2"),
    ],
    name="pendulum on a slider in an accelerating framework",
)

yd, thd = y.diff(t), theta.diff(t)
u = v0 + a * t
PROBLEM = Problem(
    id="p2.24",
    title="Framework accelerating upward: T and its A, B, C split (2.55)",
    chapter=2,
    source="Wells, Problem 2.24",
    system=system,
    answers=[
        KineticEnergy(half * (m2 * r**2 * thd**2 + (m1 + m2) * yd**2 - 2 * m2 * r * thd * yd * sp.sin(theta)
                              + 2 * m2 * r * thd * u * sp.sin(theta) - 2 * (m1 + m2) * yd * u
                              + (m1 + m2) * u**2)),
        EnergySplit(
            A=sp.Matrix([[half * (m1 + m2), -half * m2 * r * sp.sin(theta)],
                         [-half * m2 * r * sp.sin(theta), half * m2 * r**2]]),
            B=[-(m1 + m2) * u, m2 * r * u * sp.sin(theta)],
            C=half * (m1 + m2) * u**2,
        ),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 0.5, r: 1, a: 2, v0: 0.5},
        initial={y: 0, theta: 0.3, yd: 0, thd: 0},
        t_end=2.0,
    ),
    correction="Geometry inferred (figure not available). A, B, C are read off the book's T (A contains the 1/2 "
    "and the double sum runs over all k, l). No applied forces are given; the simulation is force-free.",
)
