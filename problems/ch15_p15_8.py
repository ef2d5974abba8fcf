"""Wells, Problem 15.8 — variable capacitor plus wall galvanometer (Fig. 15-14): a plate of mass m on a spring k
(displacement x, gravity m g) forms the capacitor C = A/(s - x) carrying Q1 - Q2; a wall galvanometer coil
(angle theta, suspension k, flux linkage N Phi theta in a radial field) is in the circuit of Q1; batteries E1, E2;
inductances M11, M22. Also the Hamiltonian of this system (Wells, Problem 16.19).

Resistances are not given in the book (the steady values are left open), so this system has no P.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

th, x, Q1, Q2 = coordinates("theta x Q1 Q2")
I, m, M11, M22, N, Phi, k, A, s, g, E1, E2 = parameters("I m M_11 M_22 N Phi k A s g E_1 E_2")
pth, px, pQ1, pQ2 = sp.symbols("p_theta p_x p_Q1 p_Q2", real=True)
half = sp.Rational(1, 2)

T = half * (I * th.diff(t) ** 2 + m * x.diff(t) ** 2 + M11 * Q1.diff(t) ** 2 + M22 * Q2.diff(t) ** 2) \
    + N * Phi * Q1.diff(t) * th
V = -E1 * Q1 + E2 * (Q1 - Q2) + half * (k * x**2 + (Q1 - Q2) ** 2 * (s - x) / A + k * th**2) - m * g * x
system = System([th, x, Q1, Q2], T=T, V=V, name="variable capacitor plus wall galvanometer, Fig. 15-14")


def hamiltonian(sys_, momenta):
    """H = sum p q' - L with q' solved from p = dL/dq' (Legendre transform of the system's L = T - V)."""
    qs = sys_.coordinates
    vel = [sp.Symbol(f"_v{i}") for i in range(len(qs))]
    L = (sys_.T - sys_.V).subs({q.diff(t): v for q, v in zip(qs, vel)})
    sol = sp.solve([sp.diff(L, v) - p for v, p in zip(vel, momenta)], vel, dict=True)[0]
    return sp.expand((sum(p * v for p, v in zip(momenta, vel)) - L).subs(sol))


BOOK_V = -E1 * Q1 + E2 * (Q1 - Q2) + half * (k * x**2 + (Q1 - Q2) ** 2 * (s - x) / A + k * th**2) - m * g * x
BOOK_H = half * (pth**2 / I + px**2 / m + (pQ1 - N * Phi * th) ** 2 / M11 + pQ2**2 / M22) + BOOK_V

PROBLEM = Problem(
    id="p15.8",
    title="Variable capacitor plus wall galvanometer: L and the Hamiltonian",
    chapter=15,
    source="Wells, Problem 15.8 (and Problem 16.19 for H)",
    system=system,
    answers=[
        KineticEnergy(half * (I * th.diff(t) ** 2 + m * x.diff(t) ** 2 + M11 * Q1.diff(t) ** 2
                              + M22 * Q2.diff(t) ** 2) + N * Phi * Q1.diff(t) * th),
        PotentialEnergy(BOOK_V),
        Quantity("H", lambda sy: hamiltonian(sy, [pth, px, pQ1, pQ2]), BOOK_H, description="Hamiltonian (P16.19)"),
    ],
    simulation=Simulation(
        params={I: 1.0, m: 1.0, M11: 1.0, M22: 1.0, N: 1.0, Phi: 0.5, k: 4.0, A: 1.0, s: 1.0, g: 1.0,
                E1: 0.5, E2: 0.2},
        initial={th: 0.0, x: 0.25, Q1: 0.0, Q2: 0.0, th.diff(t): 0.0, x.diff(t): 0.0, Q1.diff(t): 0.0,
                 Q2.diff(t): 0.0},
        t_end=10,
    ),
    correction="The book prints one spring constant k for both the plate spring (k x^2) and the galvanometer "
               "suspension (k theta^2); kept as printed.",
)
