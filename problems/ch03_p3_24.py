"""Wells, Problem 3.24 — particle on table D2 mounted on rotating table D1 (2.46), with θ1' = ω1, θ2' = ω2."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EnergySplit, KineticEnergy, Problem, Simulation

r, alpha = coordinates("r alpha")
m, s, w1, w2 = parameters("m s omega_1 omega_2")

th1, th2 = w1 * t, w2 * t
beta = th1 + th2 + alpha
system = System(
    [r, alpha],
    bodies=[Particle(m, (s * sp.cos(th1) + r * sp.cos(beta), s * sp.sin(th1) + r * sp.sin(beta)), name="particle")],
    name="particle on nested rotating tables",
)

rd, ad = r.diff(t), alpha.diff(t)
ang = w2 * t + alpha
B_r = 2 * s * w1 * sp.sin(ang)
B_a = 2 * r**2 * (w1 + w2) + 2 * s * w1 * r * sp.cos(ang)
C0 = r**2 * (w1 + w2) ** 2 + 2 * s * w1 * (w1 + w2) * r * sp.cos(ang) + s**2 * w1**2
T_book = sp.Rational(1, 2) * m * (rd**2 + r**2 * ad**2 + B_r * rd + B_a * ad + C0)

PROBLEM = Problem(
    id="p3.24",
    title="Particle on nested rotating tables at constant rates: T and its A, B, C split",
    chapter=3,
    source="Wells, Problem 3.24 (with eq. 2.46)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        EnergySplit(A=sp.Matrix([[m / 2, 0], [0, m * r**2 / 2]]), B=[m / 2 * B_r, m / 2 * B_a], C=m / 2 * C0),
    ],
    simulation=Simulation(params={m: 1, s: 1, w1: 1, w2: 0.5},
                          initial={r: 0.5, alpha: 0, r.diff(t): 0, alpha.diff(t): 0}, t_end=2),
)
