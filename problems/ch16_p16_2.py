"""Wells, Problem 16.2 — mass on a smooth horizontal plane tied to the origin by a spring (Ex. 3.3): H."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r, th = coordinates("r theta")
m, k = parameters("m k")
rs, pr, pth = sp.Symbol("r", real=True), sp.Symbol("p_r", real=True), sp.Symbol("p_theta", real=True)

system = System([r, th], bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)))], V=k * r**2 / 2,
                name="mass on a plane with a spring to the origin")

PROBLEM = Problem(
    id="p16.2",
    title="Mass on a horizontal plane with a spring to the origin: H = (p_r^2 + p_theta^2/r^2)/2m + kr^2/2",
    chapter=16,
    source="Wells, Problem 16.2 (system of Ex. 3.3)",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H, (pr**2 + pth**2 / rs**2) / (2 * m) + k * rs**2 / 2),
        Quantity("p_theta conserved (pdot_theta = 0)", lambda s: hamiltonian(s).pdot[1], 0),
    ],
    simulation=Simulation(params={m: 1, k: 4}, initial={r: 1, th: 0, r.diff(t): 0, th.diff(t): 1}, t_end=5),
    correction="The spring has zero free length (V = kr^2/2), as the printed H implies.",
)
