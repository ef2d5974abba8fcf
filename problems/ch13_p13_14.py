"""Wells, Problem 13.14 — two uniform bars hinged at one end, sliding on a smooth semicircular rod of radius R:
equilibrium angle (transcendental, solved numerically)."""

import numpy as np
import sympy as sp

from lagrange import System, coordinates, parameters, static_equilibrium, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
M1, M2, l1, l2, R, g, J = parameters("M_1 M_2 l_1 l_2 R g J")
V = M1 * g * l1 * sp.sin(theta) + M2 * g * l2 * sp.cos(theta) - 2 * (M1 + M2) * g * R * sp.sin(theta) * sp.cos(theta)
system = System([theta], T=J * theta.diff(t) ** 2 / 2, V=V, name="two hinged bars on a semicircular rod")
NUM = {"M_1": 1.0, "M_2": 2.0, "l_1": 0.5, "l_2": 0.7, "R": 1.0, "g": 9.81, "J": 1.0}


def _book_residual(s):
    """Book's tanθ = [2(M1+M2)R cosθ − M1 l1]/[2(M1+M2)R sinθ − M2 l2] at the engine's numeric equilibrium."""
    th = static_equilibrium(s, [theta], NUM, {theta: 0.8})[theta]
    res = np.tan(th) - (2 * 3.0 * np.cos(th) - 0.5) / (2 * 3.0 * np.sin(th) - 1.4)
    return sp.Float(round(float(res), 9))


PROBLEM = Problem(
    id="p13.14",
    title="Two hinged bars on a smooth semicircular rod: equilibrium angle",
    chapter=13,
    source="Wells, Problem 13.14",
    system=system,
    answers=[
        PotentialEnergy(V),
        Quantity("equilibrium condition −∂V/∂θ (book: M1l1cosθ − M2l2sinθ − 2(M1+M2)R cos2θ = 0)",
                 lambda s: s.derived.forcing[0].subs(s.derived.qd[0], 0),
                 -g * (M1 * l1 * sp.cos(sp.Symbol("theta", real=True)) - M2 * l2 * sp.sin(sp.Symbol("theta", real=True))
                       - 2 * (M1 + M2) * R * sp.cos(2 * sp.Symbol("theta", real=True)))),
        Quantity("book's tanθ relation at the numeric root (M1 = 1, M2 = 2, l1 = 0.5, l2 = 0.7, R = 1)",
                 _book_residual, 0),
    ],
    simulation=Simulation(params={M1: 1, M2: 2, l1: 0.5, l2: 0.7, R: 1, g: 9.81, J: 1},
                          initial={theta: 0.8, theta.diff(t): 0}, t_end=2),
    correction="The book leaves the root to be found graphically; the check applies its tanθ relation to the "
               "engine's root-finder value. J (moment of inertia) only serves the simulation; statics do not use T.",
)
