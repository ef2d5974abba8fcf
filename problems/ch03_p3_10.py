"""Wells, Problem 3.10 — the Kepler problem: mass m attracted by M with −GmM/r²."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, GeneralizedForces, Problem, Simulation

r, theta = coordinates("r theta")
m, G, M = parameters("m G M")

system = System(
    [r, theta],
    bodies=[Particle(m, (r * sp.cos(theta), r * sp.sin(theta)), name="planet")],
    forces=-G * m * M / r**2 * delta(r),
    name="Kepler problem",
)

PROBLEM = Problem(
    id="p3.10",
    title="Kepler problem: radial equation and conserved p_theta = m r^2 theta'",
    chapter=3,
    source="Wells, Problem 3.10",
    system=system,
    answers=[
        GeneralizedForces({r: -G * m * M / r**2, theta: 0}),
        EquationsOfMotion(
            [
                sp.Eq(m * (r.diff(t, 2) - r * theta.diff(t) ** 2), -G * m * M / r**2),
                sp.Eq(sp.diff(m * r**2 * theta.diff(t), t), 0),
            ],
            per_equation=True,
        ),
        ConservedMomenta({theta: m * r**2 * theta.diff(t)}),
    ],
    simulation=Simulation(params={m: 1, G: 1, M: 1}, initial={r: 1.0, theta: 0, r.diff(t): 0, theta.diff(t): 1.2},
                          t_end=10),
)
