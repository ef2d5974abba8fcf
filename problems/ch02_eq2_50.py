"""Wells, eqs. (2.49), (2.50) — oblique axes Q1, Q2 whose origin moves with constant acceleration."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EnergySplit, KineticEnergy, Problem, Simulation

q1, q2 = coordinates("q1 q2")
m, alpha, beta, x0, y0, v_x, v_y, a_x, a_y = parameters("m alpha beta x0 y0 v_x v_y a_x a_y")
half = sp.Rational(1, 2)

X = x0 + v_x * t + half * a_x * t**2 + q1 * sp.cos(alpha) + q2 * sp.cos(beta)
Y = y0 + v_y * t + half * a_y * t**2 + q1 * sp.sin(alpha) + q2 * sp.sin(beta)
system = System([q1, q2], bodies=[Particle(m, (X, Y))], name="particle in accelerating oblique axes")

q1d, q2d = q1.diff(t), q2.diff(t)
ux, uy = v_x + a_x * t, v_y + a_y * t
B1 = m * (ux * sp.cos(alpha) + uy * sp.sin(alpha))
B2 = m * (ux * sp.cos(beta) + uy * sp.sin(beta))
C = half * m * (2 * (v_x * a_x + v_y * a_y) * t + (a_x**2 + a_y**2) * t**2 + v_x**2 + v_y**2)
PROBLEM = Problem(
    id="eq2.50",
    title="Oblique axes with an accelerating origin: T and its A, B, C split",
    chapter=2,
    source="Wells, Sec. 2.10, eqs. (2.49), (2.50), (2.55)",
    system=system,
    answers=[
        KineticEnergy(half * m * (
            q1d**2 + q2d**2 + 2 * q1d * q2d * sp.cos(beta - alpha)
            + 2 * (ux * sp.cos(alpha) + uy * sp.sin(alpha)) * q1d
            + 2 * (ux * sp.cos(beta) + uy * sp.sin(beta)) * q2d
            + 2 * (v_x * a_x + v_y * a_y) * t + (a_x**2 + a_y**2) * t**2 + v_x**2 + v_y**2
        )),
        EnergySplit(
            A=sp.Matrix([[half * m, half * m * sp.cos(beta - alpha)], [half * m * sp.cos(beta - alpha), half * m]]),
            B=[B1, B2],
            C=C,
        ),
    ],
    simulation=Simulation(
        params={m: 1, alpha: 0.2, beta: 1.3, v_x: 1, v_y: 0.5, a_x: 1, a_y: 2},
        initial={q1: 0, q2: 0, q1.diff(t): 0.5, q2.diff(t): 0.1},
        t_end=1.0,
    ),
    correction="A, B, C are read off the book's T (2.50) with Wells' convention that A contains the 1/2 and the "
    "double sum runs over all k, l.",
)
