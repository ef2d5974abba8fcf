"""Wells, Example 3.3 — particle on a smooth table pulled through a hole by a spring (free length at the hole)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import (
    ConservedMomenta,
    EquationsOfMotion,
    GeneralizedForces,
    KineticEnergy,
    Problem,
    Simulation,
)

r, theta = coordinates("r theta")
x, y = coordinates("x y")
m, k = parameters("m k")

# Polar coordinates: δW = −k r δr.
polar = System(
    [r, theta],
    bodies=[Particle(m, (r * sp.cos(theta), r * sp.sin(theta)), name="particle")],
    forces=-k * r * delta(r),
    name="particle on a table, spring through a hole (polar)",
)

# Rectangular coordinates: the same δW = −k r δr with r = sqrt(x² + y²).
rho = sp.sqrt(x**2 + y**2)
rect = System(
    [x, y],
    bodies=[Particle(m, (x, y), name="particle")],
    forces=-k * rho * delta(rho),
    name="particle on a table, spring through a hole (rectangular)",
)

PROBLEMS = [
    Problem(
        id="ex3.3",
        title="Particle on a table held by a spring through a hole: polar equations, p_theta constant",
        chapter=3,
        source="Wells, Example 3.3",
        system=polar,
        answers=[
            KineticEnergy(m / 2 * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2)),
            GeneralizedForces({r: -k * r, theta: 0}),
            EquationsOfMotion(
                [
                    sp.Eq(m * r.diff(t, 2) - m * r * theta.diff(t) ** 2, -k * r),
                    sp.Eq(sp.diff(m * r**2 * theta.diff(t), t), 0),
                ],
                per_equation=True,
            ),
            ConservedMomenta({theta: m * r**2 * theta.diff(t)}),
        ],
        simulation=Simulation(params={m: 1, k: 4}, initial={r: 1.0, theta: 0, r.diff(t): 0, theta.diff(t): 1.0},
                              t_end=10),
    ),
    Problem(
        id="ex3.3-rectangular",
        title="Particle on a table held by a spring through a hole: rectangular form (isotropic oscillator)",
        chapter=3,
        source="Wells, Example 3.3",
        system=rect,
        answers=[
            GeneralizedForces({x: -k * x, y: -k * y}),
            EquationsOfMotion([sp.Eq(m * x.diff(t, 2), -k * x), sp.Eq(m * y.diff(t, 2), -k * y)], per_equation=True),
        ],
        simulation=Simulation(params={m: 1, k: 4}, initial={x: 1.0, y: 0, x.diff(t): 0, y.diff(t): 1.0}, t_end=10),
    ),
]
