"""Wells, Problem 16.10 — two masses and two springs with viscous drag (Fig. 16-3): H and canonical equations."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x1, x2 = coordinates("x_1 x_2")
m1, m2, k1, k2, b1, b2 = parameters("m_1 m_2 k_1 k_2 b_1 b_2")
x1s, x2s = sp.Symbol("x_1", real=True), sp.Symbol("x_2", real=True)
p1, p2 = sp.Symbol("p_x_1", real=True), sp.Symbol("p_x_2", real=True)

# spring k1 from the wall to m1, spring k2 from m1 to m2; drag b_i on mass i through Wells' (negative) P
system = System([x1, x2], bodies=[Particle(m1, (x1,)), Particle(m2, (x2,))],
                V=k1 * x1**2 / 2 + k2 * (x2 - x1) ** 2 / 2,
                P=-(b1 * x1.diff(t) ** 2 + b2 * x2.diff(t) ** 2) / 2, name="two masses, two springs, drag")

PROBLEM = Problem(
    id="p16.10",
    title="Two masses, two springs, viscous drag: H, P and the canonical equations",
    chapter=16,
    source="Wells, Problem 16.10 (Fig. 16-3)",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H,
                 p1**2 / (2 * m1) + p2**2 / (2 * m2) + k1 * x1s**2 / 2 + k2 * (x2s - x1s) ** 2 / 2),
        Quantity("qdot", lambda s: hamiltonian(s).qdot, [p1 / m1, p2 / m2]),
        Quantity("pdot", lambda s: hamiltonian(s).pdot,
                 [-k1 * x1s + k2 * (x2s - x1s) - b1 * p1 / m1, -k2 * (x2s - x1s) - b2 * p2 / m2]),
        EquationsOfMotion([sp.Eq(m1 * x1.diff(t, 2), -k1 * x1 + k2 * (x2 - x1) - b1 * x1.diff(t)),
                           sp.Eq(m2 * x2.diff(t, 2), -k2 * (x2 - x1) - b2 * x2.diff(t))], per_equation=True),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, k1: 10, k2: 10, b1: 0.2, b2: 0.1},
                          initial={x1: 0.1, x2: 0.3, x1.diff(t): 0, x2.diff(t): 0}, t_end=5),
)
