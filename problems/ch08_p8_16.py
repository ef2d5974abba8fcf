"""Wells, Problem 8.16 — acceleration of a free particle along the X axis of the disk frame of Fig. 8-5 (θ
constant; frame origin at the distance s along the shaft Z), by the Lagrangian method of Sec. 3.9:
a_x = d/dt(∂T'/∂ẋ) − ∂T'/∂x with T' = ½ v² (the x equation of a unit-mass particle with no forces).
"""

import sympy as sp

from lagrange import EulerAngles, Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

x, y, z, psi, phi = coordinates("x y z psi phi")
th, s_ = parameters("theta s")
psd, phd = psi.diff(t), phi.diff(t)
S, C = sp.sin, sp.cos

pos = EulerAngles(psi, th, phi).matrix * sp.Matrix([x, y, s_ + z])
system = System([x, y, z, psi, phi], bodies=[Particle(1, tuple(pos))], name="free particle in the disk frame (T')")


def a_x(sys_):
    e = sys_.equations()[0]
    return e.lhs - e.rhs


PROBLEM = Problem(
    id="p8.16",
    title="Acceleration a_x of a free particle in the disk frame of Fig. 8-5 (Lagrangian method)",
    chapter=8,
    source="Wells, Problem 8.16",
    system=system,
    answers=[
        Quantity("a_x", a_x,
                 x.diff(t, 2) + ((s_ + z) * psi.diff(t, 2) + 2 * z.diff(t) * psd - (x * C(phi) - y * S(phi)) * psd**2 * S(th))
                 * S(th) * C(phi) - y * (phi.diff(t, 2) + psi.diff(t, 2) * C(th)) - 2 * y.diff(t) * (phd + psd * C(th))
                 - x * (phd + psd * C(th)) ** 2 + (s_ + z) * psd**2 * S(th) * C(th) * S(phi)),
    ],
    ranges={"theta": (0.2, 1.4)},
    correction="Kinematics (unit mass, five coordinates for three positions: singular, no simulation).",
)
