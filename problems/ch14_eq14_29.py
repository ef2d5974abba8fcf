"""Wells, eq. (14.29) (= Problem 14.29) — velocity of the c.m. of a top with its tip at O1 of the earth frame
(Fig. 14-2), components along X1 (east), Y1 (north), Z1 (up), relative to inertial space.

Top: RigidBody with origin at the tip O1, Euler angles (z-x-z) relative to the earth frame, c.m. at z = r on the
symmetry axis, i.e. at r (s(theta) s(psi), -s(theta) c(psi), c(theta)) in the earth frame.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

psi, theta, phi = coordinates("psi theta phi")
M, Ix, Iz, r, w, R, Phi = parameters("M I_x I_z r omega_e R Phi")
E = EarthFrame(Phi, w, R)
_, Re = E.to_inertial()
top = RigidBody(M, (Ix, Ix, Iz), origin=E.point((0, 0, 0)), orientation=Re * EulerAngles(psi, theta, phi).matrix,
                com=(0, 0, r), name="top")
system = System([psi, theta, phi], bodies=[top], name="top on the rotating earth")

st, ct, sp_, cp = sp.sin(theta), sp.cos(theta), sp.sin(psi), sp.cos(psi)
sF, cF = sp.sin(Phi), sp.cos(Phi)
td, pd = theta.diff(t), psi.diff(t)
v_book = [
    R * w * cF + r * td * ct * sp_ + r * pd * st * cp + w * r * ct * cF + w * r * st * cp * sF,
    r * pd * st * sp_ - r * td * ct * cp + w * r * st * sp_ * sF,
    -r * td * st - w * r * st * sp_ * cF,
]

PROBLEM = Problem(
    id="eq14.29",
    title="Velocity of the c.m. of a top with its tip at O1 on the rotating earth (14.29)",
    chapter=14,
    source="Wells, eq. (14.29), Problem 14.29",
    system=system,
    answers=[Quantity("c.m. velocity along X1, Y1, Z1", lambda _s: list(Re.T * top.centre_of_mass.diff(t)), v_book)],
    ranges={theta: (0.3, 1.2)},
)
