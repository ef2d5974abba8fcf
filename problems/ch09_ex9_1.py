"""Wells, Example 9.1 (Fig. 2-21) — particle on disk D2, which is carried at radius s on disk D1 turning by
theta1; D2 turns by theta2 relative to the arm, beta = theta1 + theta2; (x2, y2) on D2's axes.

Lagrange's x2 and y2 expressions divided by m are the acceleration components a_x, a_y along D2's axes (Wells'
Lagrangian method for accelerations, Sec. 3.9); the origin O of D2 has a_0x, a_0y (body axes).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity
from lagrange.model.rotations import rot_z

th1, th2, x2, y2 = coordinates("theta1 theta2 x2 y2")
m, s = parameters("m s")
beta = th1 + th2
O = rot_z(th1) * sp.Matrix([s, 0, 0])
pos = O + rot_z(beta) * sp.Matrix([x2, y2, 0])
system = System([th1, th2, x2, y2], bodies=[Particle(m, pos, name="particle")], name="particle on a disk on a disk")

t1d, t1dd = th1.diff(t), th1.diff(t, 2)
bd, bdd = beta.diff(t), beta.diff(t, 2)
x2d, y2d = x2.diff(t), y2.diff(t)
s2, c2 = sp.sin(th2), sp.cos(th2)
a0x = -s * t1d**2 * c2 + s * t1dd * s2
a0y = s * t1d**2 * s2 + s * t1dd * c2
ax = a0x + x2.diff(t, 2) - x2 * bd**2 - y2 * bdd - 2 * y2d * bd
ay = a0y + y2.diff(t, 2) - y2 * bd**2 + x2 * bdd + 2 * x2d * bd
T_book = sp.Rational(1, 2) * m * (s**2 * t1d**2 + (x2d - y2 * bd) ** 2 + (y2d + x2 * bd) ** 2
                                  + 2 * s * t1d * (x2d - y2 * bd) * s2 + 2 * s * t1d * (y2d + x2 * bd) * c2)


def _acc(i):
    return lambda sys_: (sys_.equations()[i].lhs - sys_.equations()[i].rhs) / m


PROBLEM = Problem(
    id="ex9.1",
    title="Particle on a disk carried by a disk: a_0, a_x, a_y along D2's axes and T",
    chapter=9,
    source="Wells, Example 9.1 (Fig. 2-21)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        Quantity("(a_0x, a_0y) of D2's centre along D2's axes",
                 lambda _s: list((rot_z(beta).T * O.diff(t, 2))[:2]), [a0x, a0y]),
        Quantity("a_x = (x2 Lagrange expression)/m", _acc(2), ax),
        Quantity("a_y = (y2 Lagrange expression)/m", _acc(3), ay),
    ],
    correction="The OCR prints s thetadot1^2 in the first term of T; it is s^2 thetadot1^2 (dimensions; catalog).",
)
