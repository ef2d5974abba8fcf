"""Wells, Problem 10.8 — two disks on a free shaft (torsional stiffness k) (Fig. 10-7(c)): a zero root."""

import sympy as sp

from lagrange import System, coordinates, linearize, normal_modes, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th1, th2 = coordinates("theta1 theta2")
I1, I2, k = parameters("I1 I2 k")
system = System(
    [th1, th2],
    T=sp.Rational(1, 2) * (I1 * th1.diff(t) ** 2 + I2 * th2.diff(t) ** 2),
    V=sp.Rational(1, 2) * k * (th2 - th1) ** 2,
    name="two disks on a free shaft",
)
NUM = {I1: 4000.0, I2: 3000.0, k: 1e5}  # g cm², dyne cm/rad

PROBLEM = Problem(
    id="p10.8",
    title="Two disks on a free shaft: ω1 = 0 (free rotation), ω2 = 7.65 rad/s",
    chapter=10,
    source="Wells, Problem 10.8 (Fig. 10-7(c))",
    system=system,
    answers=[
        Quantity("ω1, ω2", lambda s: [sp.Float(v, 15) for v in normal_modes(linearize(s), NUM).omega],
                 [sp.Integer(0), sp.Float("7.65")], rtol=2e-2,
                 description="ω1 = 0, ω2 = 7.65 rad/s (hand-computed; exact 7.638, rtol 2e-2)"),
    ],
    simulation=Simulation(params=NUM, initial={th1: 0.0, th2: 0.1, th1.diff(t): 1.0, th2.diff(t): 0.0}, t_end=5.0),
    units="CGS",
    correction="Book's 7.65 vs exact [k(I1+I2)/(I1 I2)]^½ = 7.638 (0.2 %, hand arithmetic): rtol 2e-2.",
)
