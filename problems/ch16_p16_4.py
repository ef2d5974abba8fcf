"""Wells, Problem 16.4 — two masses of Fig. 2-8 in the coordinates (y1, y3): H."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

y1, y3 = coordinates("y_1 y_3")
m1, m2, g, k, l0 = parameters("m_1 m_2 g k l_0")
y1s, y3s = sp.Symbol("y_1", real=True), sp.Symbol("y_3", real=True)
p1, p3 = sp.Symbol("p_y_1", real=True), sp.Symbol("p_y_3", real=True)

# m1 at height y1; m2 hangs below it at y2 = y1 - y3 on the spring of length y3 (Y up)
system = System([y1, y3], bodies=[Particle(m1, (0, y1)), Particle(m2, (0, y1 - y3))],
                V=m1 * g * y1 + m2 * g * (y1 - y3) + k * (y3 - l0) ** 2 / 2, name="two masses, Fig. 2-8")

PROBLEM = Problem(
    id="p16.4",
    title="Two masses of Fig. 2-8 in (y1, y3): H",
    chapter=16,
    source="Wells, Problem 16.4",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H,
                 (p1 + p3) ** 2 / (2 * m1) + p3**2 / (2 * m2) + m1 * g * y1s + m2 * g * (y1s - y3s)
                 + k * (y3s - l0) ** 2 / 2),
    ],
    simulation=Simulation(params={m1: 1, m2: 0.5, g: 9.81, k: 20, l0: 1},
                          initial={y1: 0, y3: 1.2, y1.diff(t): 0, y3.diff(t): 0}, t_end=2),
    correction="T = 1/2 m1 y1dot^2 + 1/2 m2 (y1dot - y3dot)^2 and V (y up, y2 = y1 - y3) are the ones implied by "
    "the printed H (catalog check); Fig. 2-8 itself is not in the catalog.",
)
