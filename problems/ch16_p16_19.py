"""Wells, Problem 16.19 — variable capacitor plus wall galvanometer (P15.8, Fig. 15-14): H."""

import sympy as sp

from lagrange import System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th, x, Q1, Q2 = coordinates("theta x Q_1 Q_2")
I, m, M11, M22, E1, E2, N, Phi, k, s, A, g = parameters("I m M_11 M_22 E_1 E_2 N Phi k s A g")
pth, px, pQ1, pQ2 = (sp.Symbol(n, real=True) for n in ("p_theta", "p_x", "p_Q_1", "p_Q_2"))

# L of P15.8 = T - V with T = 1/2(I thd^2 + m xd^2 + M11 Q1d^2 + M22 Q2d^2) + N Phi Q1d theta (coil in a radial field)
T = (I * th.diff(t) ** 2 + m * x.diff(t) ** 2 + M11 * Q1.diff(t) ** 2 + M22 * Q2.diff(t) ** 2) / 2 \
    + N * Phi * Q1.diff(t) * th
V = -E1 * Q1 + E2 * (Q1 - Q2) + (k * x**2 + (Q1 - Q2) ** 2 * (s - x) / A + k * th**2) / 2 - m * g * x
system = System([th, x, Q1, Q2], T=T, V=V, name="variable capacitor and wall galvanometer")

PROBLEM = Problem(
    id="p16.19",
    title="Variable capacitor and wall galvanometer: H = 1/2[p_th^2/I + p_x^2/m + (p_Q1 - N Phi theta)^2/M11 + p_Q2^2/M22] + V",
    chapter=16,
    source="Wells, Problem 16.19 (system of Prob. 15.8)",
    system=system,
    answers=[
        Quantity("H", lambda s_: hamiltonian(s_).H,
                 (pth**2 / I + px**2 / m + (pQ1 - N * Phi * th) ** 2 / M11 + pQ2**2 / M22) / 2 + V),
    ],
    simulation=Simulation(params={I: 1, m: 1, M11: 1, M22: 1, E1: 1, E2: 0.5, N: 1, Phi: 1, k: 10, s: 5, A: 1,
                                  g: 9.81},
                          initial={th: 0, x: 0, Q1: 0, Q2: 0, th.diff(t): 0, x.diff(t): 0, Q1.diff(t): 0,
                                   Q2.diff(t): 0}, t_end=3),
    correction="The book leaves V(x, theta, Q1, Q2) as the potential part of P15.8's L; that V is used on both "
    "sides. The gyroscopic coupling N Phi Q1dot theta is a T2 (linear) term, hence p_Q1 - N Phi theta.",
)
