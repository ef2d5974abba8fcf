"""Wells, Example 6.17 — rod (length r) pivoted at p1 carrying a bar magnet (half-length l) at p2 over a grill."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

th1, th2 = coordinates("theta1 theta2")
I1, I2, C, r, l, alpha = parameters("I1 I2 C r l alpha")

# Poles at (r sin th1 +- l sin th2, r cos th1 +- l cos th2) (Y downward); grill wires at angle alpha,
# each pole feels -C times its velocity component normal to the wires: P = -(C/2) sum v_n^2 (Sec. 6.12).
n = (sp.sin(alpha), -sp.cos(alpha))
P = 0
for sgn in (1, -1):
    pole = (r * sp.sin(th1) + sgn * l * sp.sin(th2), r * sp.cos(th1) + sgn * l * sp.cos(th2))
    v_n = pole[0].diff(t) * n[0] + pole[1].diff(t) * n[1]
    P += -C * v_n**2 / 2
system = System([th1, th2], T=I1 * th1.diff(t) ** 2 / 2 + I2 * th2.diff(t) ** 2 / 2, P=P,
                name="rod and bar magnet over a grill")

PROBLEM = Problem(
    id="ex6.17",
    title="Rod and bar magnet over a grill: P = -C[r^2 th1d^2 sin^2(th1+a) + l^2 th2d^2 sin^2(th2+a)]",
    chapter=6,
    source="Wells, Example 6.17",
    system=system,
    answers=[PowerFunction(-C * (r**2 * th1.diff(t) ** 2 * sp.sin(th1 + alpha) ** 2
                                 + l**2 * th2.diff(t) ** 2 * sp.sin(th2 + alpha) ** 2))],
    simulation=Simulation(params={I1: 1, I2: 0.2, C: 0.5, r: 1, l: 0.3, alpha: 0.4},
                          initial={th1: 0.2, th2: 0.5, th1.diff(t): 1, th2.diff(t): -1}, t_end=5),
    correction="Y is taken downward (catalog: verified so). T = I1 th1d^2/2 + I2 th2d^2/2 is assumed for "
    "simulation (I1 includes the magnet carried at p2); no gravity.",
)
