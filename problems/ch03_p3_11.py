"""Wells, Problem 3.11 — charge Q in a uniform magnetic field B along Z, with an electric field E parallel to B."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

x, y, z = coordinates("x y z")
m, Q, B, E = parameters("m Q B E")

p = Particle(m, (x, y, z), name="charge")
vx, vy, vz = p.velocity
# Wells (4.13): F = Q E + Q v × B with E = (0, 0, E), B = (0, 0, B).
system = System([x, y, z], bodies=[p], forces=[Force(p, (Q * vy * B, -Q * vx * B, Q * E))],
                name="charge in uniform parallel E and B")

PROBLEM = Problem(
    id="p3.11",
    title="Charge in a uniform magnetic field (and parallel electric field): Lorentz-force equations",
    chapter=3,
    source="Wells, Problem 3.11",
    system=system,
    answers=[
        GeneralizedForces({x: Q * B * y.diff(t), y: -Q * B * x.diff(t), z: Q * E}),
        EquationsOfMotion([
            sp.Eq(m * x.diff(t, 2), Q * B * y.diff(t)),
            sp.Eq(m * y.diff(t, 2), -Q * B * x.diff(t)),
            sp.Eq(m * z.diff(t, 2), Q * E),
        ], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, Q: 1, B: 2, E: 0.5},
                          initial={x: 0, y: 0, z: 0, x.diff(t): 1, y.diff(t): 0, z.diff(t): 0.2}, t_end=5),
    correction="Catalogued [PARTIAL]: only the printed equations of motion (Wells 4.13/5.14 form) are checked; the "
               "path descriptions (helix of radius m v_perp/(Q B), increasing pitch with E) are not.",
)
