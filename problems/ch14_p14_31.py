"""Wells, Problem 14.31 — gyroscope (symmetric, c.m. fixed at O1 of the earth frame of Fig. 14-2), Euler
angles psi, theta, phi (z-x-z) relative to the earth frame: T with the earth's rotation (14.24).
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

psi, theta, phi = coordinates("psi theta phi")
M, Ix, Iz, w, R, Phi = parameters("M I_x I_z omega_e R Phi")
E = EarthFrame(Phi, w, R)
_, Re = E.to_inertial()
gyro = RigidBody(M, (Ix, Ix, Iz), origin=E.point((0, 0, 0)), orientation=Re * EulerAngles(psi, theta, phi).matrix,
                 name="gyroscope")
system = System([psi, theta, phi], bodies=[gyro], name="gyroscope on the rotating earth")

st, ct, ss, cs = sp.sin(theta), sp.cos(theta), sp.sin(psi), sp.cos(psi)
sF, cF = sp.sin(Phi), sp.cos(Phi)
pd, td, fd = psi.diff(t), theta.diff(t), phi.diff(t)
half = sp.Rational(1, 2)
T_book = (half * M * R**2 * w**2 * cF**2
          + half * Ix * (w**2 * cF**2 * ss**2 + w**2 * (sF * st + cF * cs * ct) ** 2 + td**2
                         + (pd + 2 * w * sF) * pd * st**2 + 2 * w * cF * (td * ss + pd * cs * st * ct))
          + half * Iz * ((pd + w * sF) * ct + fd - w * cF * cs * st) ** 2)

PROBLEM = Problem(
    id="p14.31",
    title="Gyroscope with its c.m. fixed on the rotating earth: T",
    chapter=14,
    source="Wells, Problem 14.31",
    system=system,
    answers=[KineticEnergy(T_book)],
    simulation=Simulation(params={M: 1.0, Ix: 1.0, Iz: 2.0, w: 7.29211e-5, R: 6.378e6, Phi: 0.7},
                          initial={psi: 0.0, theta: 1.0, phi: 0.0, pd: 0.1, theta.diff(t): 0.0, fd: 50.0}, t_end=1.0),
    ranges={theta: (0.3, 1.2)},
    units="SI in the simulation",
    correction="Catalog tag PARTIAL (T only, no EOM); the T is checked as a construction test.",
)
