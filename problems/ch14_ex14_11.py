"""Wells, Example 14.11 (Fig. 14-8) — bearing forces on a balanced rotor spinning about a horizontal axis along Y1
(north), caused by the earth's rotation.

Rotor: RigidBody with its c.m. at O1 of the earth frame (Fig. 14-2), principal moments I_x, I_y, I_z about its
c.m.; body Z along Y1 (north) and the spin angle phi between the body axes and the X1Z1 plane:
body X = (-cos(phi), 0, sin(phi)), body Y = (sin(phi), 0, cos(phi)) in (east, north, up) components, so that
omega_x = omega_e sPhi sin(phi), omega_y = omega_e sPhi cos(phi), omega_z = omega_e cPhi + phidot (book).
Bearing 1 at z = +l1, bearing 2 at z = -l2 on the axis (the sign pattern of the book's (7), (8)); motor torque
tau_m about Z. True gravity from EarthFrame.
"""

import sympy as sp

from lagrange import Force, RigidBody, System, Torque, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation
from lagrange.derive.euler import euler_equations, support_loads
from lagrange.model.frames import EarthFrame

phi = coordinates("phi")
M, Ix, Iy, Iz, gp, w, R, Phi, l1, l2, tau_m = parameters("M I_x I_y I_z g_prime omega_e R Phi l_1 l_2 tau_m")
sF, cF = sp.sin(Phi), sp.cos(Phi)
s, c = sp.sin(phi), sp.cos(phi)
pd = phi.diff(t)

E = EarthFrame(Phi, w, R)
local = sp.Matrix([[-c, s, 0], [0, 0, 1], [s, c, 0]])  # columns: body X, Y, Z in earth-frame components
rotor = RigidBody(M, (Ix, Iy, Iz), origin=E.point((0, 0, 0)), orientation=E.to_inertial()[1] * local, name="rotor")
gravity = E.gravity_force(M, gp)
system = System([phi], bodies=[rotor], forces=[Force(rotor.centre_of_mass, gravity), Torque(rotor, (0, 0, tau_m))],
                name="balanced rotor on the rotating earth")


def _omega(_s):
    return list(rotor.angular_velocity)


def _support_force_body(_s):
    F, _tau = support_loads(rotor, gravity, frame="inertial")
    return list(rotor.R.T * F)


def _f1x(_s):
    """Bearing 1 (z = +l1) and 2 (z = -l2) carry the support force and the support torque about the c.m.:
    f1x + f2x = F_x, tau_y = f1x l1 - f2x l2  =>  f1x = (tau_y + F_x l2)/(l1 + l2)."""
    F, tau = support_loads(rotor, gravity, frame="inertial")  # both along the inertial axes
    Fb, taub = rotor.R.T * F, rotor.R.T * tau  # along the body axes, as the book's (10)
    return (taub[1] + Fb[0] * l2) / (l1 + l2)


euler_book = [
    Ix * w * pd * sF * c + (Iz - Iy) * w * sF * c * (w * cF + pd),            # (7) = f2y l2 - f1y l1 = tau_x
    -(Iy * w * pd * sF * s + (Iz - Ix) * w * sF * s * (w * cF + pd)),         # (8) printed as -tau_y
    Iz * phi.diff(t, 2) + (Iy - Ix) * w**2 * sF**2 * s * c,                   # (9) = tau_m
]

PROBLEM = Problem(
    id="ex14.11",
    title="Balanced rotor on a north-south horizontal axis: bearing forces due to the earth's rotation",
    chapter=14,
    source="Wells, Example 14.11, Fig. 14-8",
    system=system,
    answers=[
        Quantity("angular velocity (omega_x, omega_y, omega_z)", _omega, [w * sF * s, w * sF * c, w * cF + pd]),
        Quantity("bearing force sum on body axes (f1x+f2x, f1y+f2y, f_z)", _support_force_body,
                 [M * gp * s, M * gp * c, 0]),
        Quantity("Euler's equations (7), (8), (9)", lambda _s: list(euler_equations(rotor)), euler_book),
        EquationsOfMotion([sp.Eq(euler_book[2], tau_m)], per_equation=True),
        Quantity("bearing force f1x (10)", _f1x,
                 s / (l1 + l2) * (M * gp * l2 + w * pd * (Ix - Iz - Iy) * sF + w**2 * (Ix - Iz) * sF * cF)),
    ],
    simulation=Simulation(
        params={M: 1.0, Ix: 1.0, Iy: 1.2, Iz: 2.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854, tau_m: 0.0},
        initial={phi: 0.0, pd: 100.0},
        t_end=1,
    ),
    units="cgs in the simulation",
    correction="The book writes (8) with both sides negated relative to (9.10b): I_y omega_e phidot sPhi sin(phi) + "
    "(I_z - I_x)(...) = f2x l2 - f1x l1, i.e. -tau_y; it is compared as -(Euler y). The bearing positions "
    "(1 at +l1, 2 at -l2 along Z) are read off (7), (8). (11) (I_x = I_y, omega_e^2 dropped) is not compared.",
)
