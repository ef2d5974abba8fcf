"""Wells, Problem 12.4 — free dumbbell (m_1, m_2 joined by a light rod of length l) moving in a vertical plane
(Fig. 4-3): the rod tension, with the rod length as a superfluous coordinate."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

x, y, th, s = coordinates("x y theta s")
m1, m2, l, g = parameters("m_1 m_2 l g")

# m_1 at (x, y), m_2 at (x + s cos(theta), y + s sin(theta)), Y up; the rod length s = l is the constraint.
p2 = (x + s * sp.cos(th), y + s * sp.sin(th))
system = System(
    [x, y, th, s],
    bodies=[Particle(m1, (x, y), name="m1"), Particle(m2, p2, name="m2")],
    V=m1 * g * y + m2 * g * p2[1],
    constraints=[Holonomic(s - l, name="rod")],
    name="free dumbbell with the rod length free",
)

PARAMS = {m1: 1.0, m2: 2.5, l: 0.8, g: 9.81}
INIT = {x: 0.0, y: 0.0, th: 0.3, s: 0.8, x.diff(t): 1.0, y.diff(t): 3.0, th.diff(t): 4.0, s.diff(t): 0.0}

PROBLEM = Problem(
    id="p12.4",
    title="Free dumbbell in a vertical plane: rod tension tau = m1 m2 l thetad^2/(m1 + m2)",
    chapter=12,
    source="Wells, Problem 12.4 (Fig. 4-3)",
    system=system,
    answers=[
        # A rod in tension pulls the masses together: distorting s by +delta s it does work -tau delta s,
        # so the multiplier (generalized force on s) is lambda = -tau.
        ConstraintForce("rod", -m1 * m2 / (m1 + m2) * l * th.diff(t) ** 2, PARAMS, INIT, 2.0,
                        description="tau (lambda = -tau)"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=5),
)
