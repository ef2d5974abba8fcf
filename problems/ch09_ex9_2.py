"""Wells, Example 9.2 — physical pendulum (Ex. 8.4(1)) with the reactions at the pivot, by Euler's method.

Pivot O fixed at the inertial origin, X1 horizontal, Y1 up; the body turns by theta about Z (rot_z), its c.m. at
distance l from O along -Y (body axes), so theta is measured from the downward vertical. Body X is then tangent
to the c.m. path and body Y points from the c.m. towards the pivot. I_z is the moment of inertia about the pivot.
Book: M l thetadd = f_x - M g sin(theta), M l thetadot^2 = f_y - M g cos(theta) (f_x, f_y: pivot reaction along
body X, Y), I_z thetadd = -M g l sin(theta).
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation
from lagrange.derive.euler import support_loads
from lagrange.model.rotations import rot_z

th = coordinates("theta")
M, g, l, Ix, Iy, Iz = parameters("M g l I_x I_y I_z")
body = RigidBody(M, (Ix, Iy, Iz), orientation=rot_z(th), com=(0, -l, 0), name="pendulum")
gravity = (0, -M * g, 0)
system = System([th], bodies=[body], V=M * g * body.centre_of_mass[1], name="physical pendulum")


def _pivot_reaction_body(_s):
    F, _tau = support_loads(body, gravity, frame="inertial")
    return list(body.R.T * F)


PROBLEM = Problem(
    id="ex9.2",
    title="Physical pendulum by Euler's method: pivot reactions f_x, f_y and I_z thetadd = -M g l sin(theta)",
    chapter=9,
    source="Wells, Example 9.2 (Ex. 8.4(1))",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(Iz * th.diff(t, 2), -M * g * l * sp.sin(th))], per_equation=True),
        # f_x = M l thetadd + M g sin(theta), f_y = M l thetadot^2 + M g cos(theta), f_z = 0
        Quantity("pivot reaction along body X, Y, Z", _pivot_reaction_body,
                 [M * l * th.diff(t, 2) + M * g * sp.sin(th), M * l * th.diff(t) ** 2 + M * g * sp.cos(th), 0]),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, l: 0.5, Iz: 0.4},
                          initial={th: 1.0, th.diff(t): 0.0}, t_end=5),
    correction="I_z is the moment about the pivot (body origin). The axes are this transcription's reading of "
    "the book's figure (X tangent, Y from the c.m. to the pivot), which the signs of both force equations fix.",
)
