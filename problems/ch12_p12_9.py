"""Wells, Problem 12.9 — tension of the upper string of the double pendulum (as Example 12.2), r_1 freed."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

th, ph, r1 = coordinates("theta phi r_1")
m1, m2, l1, r2, g = parameters("m_1 m_2 l_1 r_2 g")

# theta, phi from the downward vertical, Y up; only the upper string length r_1 is superfluous.
p1 = (r1 * sp.sin(th), -r1 * sp.cos(th))
p2 = (p1[0] + r2 * sp.sin(ph), p1[1] - r2 * sp.cos(ph))
system = System(
    [th, ph, r1],
    bodies=[Particle(m1, p1, name="m1"), Particle(m2, p2, name="m2")],
    V=m1 * g * p1[1] + m2 * g * p2[1],
    constraints=[Holonomic(r1 - l1, name="string1")],
    name="double pendulum with the upper string length free",
)

PARAMS = {m1: 1.2, m2: 0.5, l1: 0.9, r2: 0.7, g: 9.81}
INIT = {th: -0.4, ph: 0.8, r1: 0.9, th.diff(t): 1.0, ph.diff(t): -0.6, r1.diff(t): 0.0}

# Book: f = m2 r2 [phidd sin(phi - theta) + phid^2 cos(phi - theta)] + (m1 + m2)(r1 thd^2 + g cos(theta)).
# The string pulls m1 toward the pivot: the multiplier (generalized force on r_1) is lambda = -f.
f = (m2 * r2 * (ph.diff(t, 2) * sp.sin(ph - th) + ph.diff(t) ** 2 * sp.cos(ph - th))
     + (m1 + m2) * (r1 * th.diff(t) ** 2 + g * sp.cos(th)))

PROBLEM = Problem(
    id="p12.9",
    title="Double pendulum: tension f of the upper string (r_1 superfluous)",
    chapter=12,
    source="Wells, Problem 12.9",
    system=system,
    answers=[ConstraintForce("string1", -f, PARAMS, INIT, 2.0, description="f (lambda = -f)")],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=10),
    correction="OCR misplaces the closing bracket; the form used groups m2 r2[phidd sin(phi-theta) + phid^2 "
               "cos(phi-theta)] + (m1+m2)(r1 thd^2 + g cos theta), as in Example 12.2 (dimensions: all forces).",
)
