"""Wells, Example 3.2 — bead on a smooth parabolic wire y = b x², Y vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x = coordinates("x")
m, g, b = parameters("m g b")

# Gravity by virtual work: δW = −m g δy with y = b x² (Wells' way), so F_x = −2 m g b x.
system = System(
    [x],
    bodies=[Particle(m, (x, b * x**2), name="bead")],
    forces=-m * g * delta(b * x**2),
    name="bead on a parabolic wire",
)

PROBLEM = Problem(
    id="ex3.2",
    title="Bead on a smooth parabolic wire y = b x^2 (gravity by virtual work)",
    chapter=3,
    source="Wells, Example 3.2",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * x.diff(t) ** 2 * (1 + 4 * b**2 * x**2)),
        GeneralizedForces({x: -2 * m * g * b * x}),
        EquationsOfMotion(
            [sp.Eq(m * x.diff(t, 2) * (1 + 4 * b**2 * x**2) + 4 * m * x.diff(t) ** 2 * x * b**2, -2 * m * g * b * x)],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, b: 0.5}, initial={x: 1.0, x.diff(t): 0.0}, t_end=10),
)
