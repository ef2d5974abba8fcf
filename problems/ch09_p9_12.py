"""Wells, Problem 9.12 — lamina of Ex. 8.5 moving in its plane under gravity along -Y1.

Body origin O at inertial (x, y); body axes turned by theta about Z; c.m. at (x_bar, y_bar) on body axes; I_z about O.
(a) Lagrange form with inertial x, y; (b) Euler form on body axes with a_0x = xdd cth + ydd sth,
a_0y = ydd cth - xdd sth.
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation
from lagrange.model.rotations import rot_z

x, y, th = coordinates("x y theta")
M, g, xb, yb, Ix, Iy, Iz = parameters("M g xbar ybar I_x I_y I_z")
s, c = sp.sin(th), sp.cos(th)
xdd, ydd, thd, thdd = x.diff(t, 2), y.diff(t, 2), th.diff(t), th.diff(t, 2)

lamina = RigidBody(M, (Ix, Iy, Iz), origin=(x, y, 0), orientation=rot_z(th), com=(xb, yb, 0), name="lamina")
system = System([x, y, th], bodies=[lamina], V=M * g * lamina.centre_of_mass[1], name="lamina in its plane")

a0x, a0y = xdd * c + ydd * s, ydd * c - xdd * s

PROBLEM = Problem(
    id="p9.12",
    title="Lamina moving in its plane under gravity: Lagrange form (a) and Euler form on body axes (b)",
    chapter=9,
    source="Wells, Problem 9.12 (lamina of Ex. 8.5)",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq(M * (xdd - thdd * (yb * c + xb * s) + thd**2 * (yb * s - xb * c)), 0),
                sp.Eq(M * (ydd + thdd * (xb * c - yb * s) - thd**2 * (xb * s + yb * c)), -M * g),
                sp.Eq(Iz * thdd + M * ((ydd * xb - xdd * yb) * c - (xdd * xb + ydd * yb) * s), M * g * (yb * s - xb * c)),
            ],
            per_equation=True,
        ),
        EquationsOfMotion(
            [
                sp.Eq(M * a0x - M * (thdd * yb + thd**2 * xb), -M * g * s),
                sp.Eq(M * a0y + M * (thdd * xb - thd**2 * yb), -M * g * c),
                sp.Eq(Iz * thdd + M * (a0y * xb - a0x * yb), M * g * (yb * s - xb * c)),
            ],
        ),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, xb: 0.2, yb: 0.1, Iz: 0.3},
                          initial={x: 0.0, y: 0.0, th: 0.3, x.diff(t): 1.0, y.diff(t): 2.0, thd: 1.0}, t_end=2),
    correction="(a): the book/OCR prints F_x = -M g sth, F_y = -M g cth, the body-axis components of (b); for "
    "the inertial x, y of (a) F_x = 0 and F_y = -M g (catalog, verified).",
)
