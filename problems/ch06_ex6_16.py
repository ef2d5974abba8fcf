"""Wells, Example 6.16 — extended pole face (length l1) moving over a grill of wires parallel to X."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x1, y1, theta = coordinates("x1 y1 theta")
M, a, l1 = parameters("M a l1")
s = sp.Symbol("s", real=True)  # distance along the pole face from (x1, y1)

# Drag per unit length a times the velocity normal to the wires (the Y component) only.
Ye = y1 + s * sp.sin(theta)
P = -a / 2 * sp.integrate(sp.expand(Ye.diff(t) ** 2), (s, 0, l1))
cm = (x1 + l1 / 2 * sp.cos(theta), y1 + l1 / 2 * sp.sin(theta))
system = System([x1, y1, theta], T=M * l1**2 / 12 * theta.diff(t) ** 2 / 2, bodies=[Particle(M, cm)], P=P,
                name="pole face over a grill")

y1d, thd = y1.diff(t), theta.diff(t)
PROBLEM = Problem(
    id="ex6.16",
    title="Pole face over a grill (wires along X): F_y1, F_theta and P",
    chapter=6,
    source="Wells, Example 6.16",
    system=system,
    answers=[
        GeneralizedForces({x1: 0, y1: -a * (y1d * l1 + l1**2 * thd * sp.cos(theta) / 2),
                           theta: -a * (y1d * l1**2 * sp.cos(theta) / 2 + l1**3 * thd * sp.cos(theta) ** 2 / 3)}),
        PowerFunction(-a / 2 * (y1d**2 * l1 + y1d * l1**2 * thd * sp.cos(theta) + l1**3 * thd**2 * sp.cos(theta) ** 2 / 3)),
    ],
    simulation=Simulation(params={M: 1, a: 0.5, l1: 1},
                          initial={x1: 0, y1: 0, theta: 0.2, x1.diff(t): 1, y1.diff(t): 0.5, theta.diff(t): 1}, t_end=5),
    correction="The pole's T (uniform rod of mass M) is assumed for simulation; the book's answer is the drag.",
)
