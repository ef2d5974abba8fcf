"""Wells, Example 14.1 — direction of a plumb line (bob at rest at O1 in the earth frame of Fig. 14-2).

The bob (mass m) is held at rest at the origin O1 (x1 = y1 = z1 = 0) by a string. Lagrange's equations of the
free particle in the earth frame give the force needed to keep it there, F_x1 = 0, F_y1 = m omega_e^2 R sPhi cPhi,
F_z1 = -m omega_e^2 R cos^2 Phi. The forces on the bob are the true gravity (F_y1 = m g sin(alpha),
F_z1 = -m g cos(alpha)) and the string tension tau along Z1, so tau = m g' and relations (14.11) follow.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
m, gp, w, R, Phi = parameters("m g_prime omega_e R Phi")
s, c = sp.sin(Phi), sp.cos(Phi)

E = EarthFrame(Phi, w, R)
bob = Particle(m, E.point((x, y, z)), name="bob")
free = System([x, y, z], bodies=[bob], name="bob in the earth frame, no forces")
with_gravity = System([x, y, z], bodies=[bob], forces=[Force(bob, E.gravity_force(m, gp))],
                      name="bob in the earth frame under true gravity")

REST = [{q.diff(t, 2): 0 for q in (x, y, z)}, {q.diff(t): 0 for q in (x, y, z)}, {x: 0, y: 0, z: 0}]


def _needed_at_rest(sys_):
    """d/dt dT/dqdot - dT/dq - (applied F_q) at rest at O1: the force the string must supply."""
    return [sp.simplify((e.lhs - e.rhs).subs(REST[0]).subs(REST[1]).subs(REST[2])) for e in sys_.equations()]


PROBLEM = Problem(
    id="ex14.1",
    title="Plumb line: force to hold a bob at rest at O1; string tension tau = m g' along Z1",
    chapter=14,
    source="Wells, Example 14.1",
    system=with_gravity,
    answers=[
        Quantity("force needed to hold the bob at rest (F_x1, F_y1, F_z1)", lambda _s: _needed_at_rest(free),
                 [0, m * w**2 * R * s * c, -m * w**2 * R * c**2]),
        # With true gravity applied, what is left for the string: (0, 0, tau) with tau = m g'
        Quantity("string force on the bob at rest", _needed_at_rest, [0, 0, m * gp]),
    ],
    correction="The book's answer is the relations (14.11); here they enter through EarthFrame's true gravity "
    "and are confirmed by the string force being along Z1 with tau = m g'.",
)
