"""Wells, Problem 16.3 — bead on the conical spiral x = a z cos bz, y = -a z sin bz (P3.5), z vertical."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

z = coordinates("z")
m, g, a, b = parameters("m g a b")
zs, pz = sp.Symbol("z", real=True), sp.Symbol("p_z", real=True)

system = System([z], bodies=[Particle(m, (a * z * sp.cos(b * z), -a * z * sp.sin(b * z), z))], V=m * g * z,
                name="bead on a conical spiral")

PROBLEM = Problem(
    id="p16.3",
    title="Bead on a conical spiral: H = p_z^2 / (2m[1 + a^2(1 + b^2 z^2)]) + mgz",
    chapter=16,
    source="Wells, Problem 16.3 (system of Prob. 3.5)",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H, pz**2 / (2 * m * (1 + a**2 * (1 + b**2 * zs**2))) + m * g * zs),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, a: 0.5, b: 2}, initial={z: 2, z.diff(t): 0}, t_end=2),
    correction="Spiral handedness (y = -a z sin bz, as in P14.22) does not affect T or H.",
)
