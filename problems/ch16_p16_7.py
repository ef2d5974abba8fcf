"""Wells, Problem 16.7 — pendulum of P4.10 (Fig. 4-13), planar: m1 fixed at r1, m2 sliding on a spring (k, l0)."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th, r = coordinates("theta r")
m1, m2, r1, g, k, l0 = parameters("m_1 m_2 r_1 g k l_0")
ths, rs = sp.Symbol("theta", real=True), sp.Symbol("r", real=True)
pth, pr = sp.Symbol("p_theta", real=True), sp.Symbol("p_r", real=True)

u = (sp.sin(th), -sp.cos(th))  # along the massless rod, theta from the downward vertical
system = System([th, r], bodies=[Particle(m1, (r1 * u[0], r1 * u[1])), Particle(m2, (r * u[0], r * u[1]))],
                V=-(m1 * r1 + m2 * r) * g * sp.cos(th) + k * (r - l0) ** 2 / 2, name="pendulum with sliding mass")

PROBLEM = Problem(
    id="p16.7",
    title="Pendulum with a fixed mass and a spring-held sliding mass: H",
    chapter=16,
    source="Wells, Problem 16.7 (system of Prob. 4.10, Fig. 4-13)",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H,
                 pth**2 / (2 * (m1 * r1**2 + m2 * rs**2)) + pr**2 / (2 * m2) + k * (rs - l0) ** 2 / 2
                 - (m1 * r1 + m2 * rs) * g * sp.cos(ths)),
    ],
    simulation=Simulation(params={m1: 1, m2: 0.5, r1: 1, g: 9.81, k: 30, l0: 1.5},
                          initial={th: 0.4, r: 1.5, th.diff(t): 0, r.diff(t): 0}, t_end=3),
    correction="r is the book's r2 (distance of m2 from the pivot); the spring of free length l0 acts along r2.",
)
