"""Wells, Problem 16.18 — capacitor with two movable plates on springs (P15.7, Fig. 15-13): H."""

import sympy as sp

from lagrange import System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x1, x2, Q = coordinates("x_1 x_2 Q")
m1, m2, M, k1, k2, E, s, A = parameters("m_1 m_2 M k_1 k_2 E s A")
p1, p2, pQ = (sp.Symbol(n, real=True) for n in ("p_x_1", "p_x_2", "p_Q"))

# L = 1/2(m1 x1d^2 + m2 x2d^2 + M Qd^2) - 1/2(k1 x1^2 + k2 x2^2) + EQ - 1/2 Q^2 (s - x1 - x2)/A  (P15.7)
V = (k1 * x1**2 + k2 * x2**2) / 2 - E * Q + Q**2 * (s - x1 - x2) / (2 * A)
system = System([x1, x2, Q], T=(m1 * x1.diff(t) ** 2 + m2 * x2.diff(t) ** 2 + M * Q.diff(t) ** 2) / 2, V=V,
                name="capacitor with spring-mounted plates")

PROBLEM = Problem(
    id="p16.18",
    title="Capacitor with two movable plates: H = 1/2(p1^2/m1 + p2^2/m2 + pQ^2/M) + V",
    chapter=16,
    source="Wells, Problem 16.18 (system of Prob. 15.7)",
    system=system,
    answers=[
        # book's H; V is written with the coordinate functions (compared in plain symbols)
        Quantity("H", lambda s_: hamiltonian(s_).H,
                 (p1**2 / m1 + p2**2 / m2 + pQ**2 / M) / 2 + (k1 * x1**2 + k2 * x2**2) / 2 - E * Q
                 + Q**2 * (s - x1 - x2) / (2 * A)),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, M: 1, k1: 10, k2: 10, E: 1, s: 5, A: 1},
                          initial={x1: 0, x2: 0, Q: 0, x1.diff(t): 0, x2.diff(t): 0, Q.diff(t): 0}, t_end=3),
    correction="No resistance: the problem asks for H only (the circuit resistance of P15.7 would enter as F_Q).",
)
