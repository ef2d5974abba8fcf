"""Wells, Problem 14.28 — body with its c.m. at O on the support B of Fig. 8-12, attached to the rotating earth:
angular velocity components along the body axes (14.24) with theta fixed by the support (no thetadot terms).

Body orientation relative to the earth frame of Fig. 14-2: Euler angles psi, theta (a constant set by the
support), phi, z-x-z. Axes through the c.m. with products of inertia (Wells' positive products).
"""

import sympy as sp

from lagrange import Inertia, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity
from lagrange.model.frames import EarthFrame
from lagrange.model.rotations import rot_x, rot_z

psi, phi = coordinates("psi phi")
M, Ix, Iy, Iz, Ixy, Ixz, Iyz, th, w, R, Phi = parameters("M I_x I_y I_z I_xy I_xz I_yz theta omega_e R Phi")
E = EarthFrame(Phi, w, R)
_, Re = E.to_inertial()
body = RigidBody(M, Inertia(Ix, Iy, Iz, I_xy=Ixy, I_xz=Ixz, I_yz=Iyz), origin=E.point((0, 0, 0)),
                 orientation=Re * rot_z(psi) * rot_x(th) * rot_z(phi), name="body")
system = System([psi, phi], bodies=[body], name="body on the support B of Fig. 8-12 on the earth")

st, ct, ss, cs, sf, cf = sp.sin(th), sp.cos(th), sp.sin(psi), sp.cos(psi), sp.sin(phi), sp.cos(phi)
sF, cF = sp.sin(Phi), sp.cos(Phi)
pd, fd = psi.diff(t), phi.diff(t)
wx = pd * st * sf + w * (cf * ss + sf * cs * ct) * cF + w * st * sf * sF
wy = pd * st * cf + w * (cf * cs * ct - sf * ss) * cF + w * st * cf * sF
wz = fd + pd * ct - w * st * cs * cF + w * ct * sF
half = sp.Rational(1, 2)

PROBLEM = Problem(
    id="p14.28",
    title="Body with its c.m. on the support of Fig. 8-12 on the rotating earth: omega (14.24) and T",
    chapter=14,
    source="Wells, Problem 14.28",
    system=system,
    answers=[
        Quantity("(omega_x, omega_y, omega_z)", lambda _s: list(body.angular_velocity), [wx, wy, wz]),
        KineticEnergy(half * M * w**2 * R**2 * cF**2
                      + half * (Ix * wx**2 + Iy * wy**2 + Iz * wz**2 - 2 * Ixy * wx * wy - 2 * Ixz * wx * wz
                                - 2 * Iyz * wy * wz)),
    ],
    correction="The catalog marks this case PARTIAL (no EOM; theta is not free on the support, so no thetadot "
    "terms). The printed constant term is 1/2 M omega_e^2 R^2; the c.m. at O1 moves at R omega_e cos(Phi), so the "
    "constant is 1/2 M omega_e^2 R^2 cos^2(Phi) (as in P14.31 and 14.27) — used here (a constant does not affect "
    "the motion).",
)
