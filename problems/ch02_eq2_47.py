"""Wells, eq. (2.47) — the centre-of-mass theorem: T = ½M v̄² + Σ ½ mᵢ ρ̇ᵢ², the kinetic energy of the total
mass at the centre of mass plus that of the motion relative to it.

Instance: three particles in space, coordinates the centre of mass (X, Y, Z) and the positions ρ1, ρ2 of m1, m2
relative to it; ρ3 = −(m1 ρ1 + m2 ρ2)/m3 follows from the definition of the centre of mass.
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

X, Y, Z = coordinates("X Y Z")
r1 = sp.Matrix(coordinates("u1 v1 w1"))
r2 = sp.Matrix(coordinates("u2 v2 w2"))
m1, m2, m3, k = parameters("m1 m2 m3 k")

C = sp.Matrix([X, Y, Z])
r3 = -(m1 * r1 + m2 * r2) / m3
masses = [(m1, r1), (m2, r2), (m3, r3)]
# an interaction depending on the separations only (springs between the particles), so there is motion to simulate
V = k / 2 * ((r1 - r2).dot(r1 - r2) + (r2 - r3).dot(r2 - r3) + (r3 - r1).dot(r3 - r1))
system = System([X, Y, Z, *r1, *r2], bodies=[Particle(m, tuple(C + r), name=f"m{i + 1}")
                                             for i, (m, r) in enumerate(masses)], V=V,
                name="three particles in centre-of-mass and relative coordinates")

M = m1 + m2 + m3
dot = sp.Matrix([X, Y, Z]).diff(t)
T_book = M * dot.dot(dot) / 2 + sum(m * r.diff(t).dot(r.diff(t)) / 2 for m, r in masses)

PROBLEM = Problem(
    id="eq2.47",
    title="Centre-of-mass theorem: T = ½ M v̄² + Σ ½ mᵢ ρ̇ᵢ²",
    chapter=2,
    source="Wells, eq. (2.47)",
    system=system,
    answers=[KineticEnergy(T_book)],
    simulation=Simulation(params={m1: 1, m2: 2, m3: 1.5, k: 3},
                          initial={X: 0, Y: 0, Z: 0, **{q: 0.1 * (i + 1) for i, q in enumerate([*r1, *r2])},
                                   **{q.diff(t): v for q, v in zip([X, Y, Z, *r1, *r2],
                                                                   [1, 0.5, 0, 0, 0.3, 0, -0.2, 0, 0.1])}},
                          t_end=2.0),
    correction="Wells states the theorem for any particle set; it is checked on three particles in space with "
    "springs between them (the springs only give the simulation something to do).",
)
