"""Wells, Problem 15.7 — capacitor with two movable plates on springs (masses m1, m2, springs k1, k2,
displacements x1, x2 toward each other), C = A/(s - x1 - x2), in a circuit with inductance M, resistance R and
battery E (Fig. 15-13). Also the Hamiltonian of this system (Wells, Problem 16.18)."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

x1, x2, Q = coordinates("x1 x2 Q")
m1, m2, M, k1, k2, E, A, s, R = parameters("m_1 m_2 M k_1 k_2 E A s R")
px1, px2, pQ = sp.symbols("p_x1 p_x2 p_Q", real=True)
half = sp.Rational(1, 2)

T = half * (m1 * x1.diff(t) ** 2 + m2 * x2.diff(t) ** 2 + M * Q.diff(t) ** 2)
V = half * (k1 * x1**2 + k2 * x2**2) - E * Q + half * Q**2 * (s - x1 - x2) / A
system = System([x1, x2, Q], T=T, V=V, P=-half * R * Q.diff(t) ** 2,
                name="capacitor with two spring-mounted plates, Fig. 15-13")


def hamiltonian(sys_, momenta):
    """H = sum p q' - L with q' solved from p = dL/dq' (Legendre transform of the system's L = T - V)."""
    qs = sys_.coordinates
    vel = [sp.Symbol(f"_v{i}") for i in range(len(qs))]
    L = (sys_.T - sys_.V).subs({q.diff(t): v for q, v in zip(qs, vel)})
    sol = sp.solve([sp.diff(L, v) - p for v, p in zip(vel, momenta)], vel, dict=True)[0]
    return sp.simplify((sum(p * v for p, v in zip(momenta, vel)) - L).subs(sol))


BOOK_H = (half * (px1**2 / m1 + px2**2 / m2 + pQ**2 / M) + half * (k1 * x1**2 + k2 * x2**2) - E * Q
          + half * Q**2 * (s - x1 - x2) / A)

PROBLEM = Problem(
    id="p15.7",
    title="Capacitor with two spring-mounted movable plates in an L-R circuit with a battery; Hamiltonian",
    chapter=15,
    source="Wells, Problem 15.7 (and Problem 16.18 for H)",
    system=system,
    answers=[
        KineticEnergy(half * (m1 * x1.diff(t) ** 2 + m2 * x2.diff(t) ** 2 + M * Q.diff(t) ** 2)),
        PotentialEnergy(half * (k1 * x1**2 + k2 * x2**2) - E * Q + half * Q**2 * (s - x1 - x2) / A),
        EquationsOfMotion(
            [
                sp.Eq(m1 * x1.diff(t, 2) + k1 * x1 - Q**2 / (2 * A), 0),
                sp.Eq(m2 * x2.diff(t, 2) + k2 * x2 - Q**2 / (2 * A), 0),
                sp.Eq(M * Q.diff(t, 2) + Q * (s - x1 - x2) / A - E, -R * Q.diff(t)),
            ],
            per_equation=True,
        ),
        Quantity("H", lambda sy: hamiltonian(sy, [px1, px2, pQ]), BOOK_H, description="Hamiltonian (P16.18)"),
    ],
    simulation=Simulation(
        params={m1: 1.0, m2: 2.0, M: 1.0, k1: 4.0, k2: 3.0, E: 0.5, A: 1.0, s: 1.0, R: 0.2},
        initial={x1: 0.0, x2: 0.0, Q: 0.0, x1.diff(t): 0.0, x2.diff(t): 0.0, Q.diff(t): 0.0},
        t_end=20,
    ),
    correction="Wells gives L (and H in P16.18); the equations of motion (with the resistance R through P) were "
               "derived in the catalog and are checked here against Wells' L.",
)
