"""Wells, Example 9.10(a) — particle relative to a frame carried north along a meridian at the constant rate
Phi1_dot on the rotating earth (X1 east, Y1 north, Z1 up, radius R1).

EarthFrame with the time-dependent latitude Phi1 = Phi0 + Phi1_dot t: the frame's angular velocity is
(-Phi1_dot, omega_e cPhi1, omega_e sPhi1). Lagrange's x1 equation of the free particle, divided by m, is the
acceleration component a_x1 of (9.20) (Wells' 'Lagrangian method for accelerations', Sec. 3.9).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
m, w, R1, Phi0, Phid = parameters("m omega_e R_1 Phi_0 Phi1_dot")
Phi1 = Phi0 + Phid * t
s, c = sp.sin(Phi1), sp.cos(Phi1)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

E = EarthFrame(Phi1, w, R1)
system = System([x, y, z], bodies=[Particle(m, E.point((x, y, z)), name="particle")],
                name="particle in a frame moving north on the rotating earth")


def _a_x1(sys_):
    e = sys_.equations()[0]
    return (e.lhs - e.rhs) / m


a_x1_book = (-2 * R1 * w * Phid * s + x.diff(t, 2) - x * w**2 - 2 * w * Phid * (y * c + z * s)
             + 2 * w * (zd * c - yd * s))

PROBLEM = Problem(
    id="ex9.10",
    title="Particle in a frame moving north along a meridian on the rotating earth: a_x1 (9.20)",
    chapter=9,
    source="Wells, Example 9.10(a), eq. (9.20)",
    system=system,
    answers=[
        Quantity("a_x1 (9.20) = (x1 Lagrange expression)/m", _a_x1, a_x1_book),
        Quantity("frame angular velocity along X1, Y1, Z1",
                 lambda _s: list(E.to_inertial()[1].T * E.angular_velocity()), [-Phid, w * c, w * s]),
    ],
    simulation=Simulation(params={m: 1.0, w: 7.29211e-5, R1: 6.378e8, Phi0: 0.5, Phid: 1e-4},
                          initial={x: 0.0, y: 0.0, z: 0.0, xd: 10.0, yd: 0.0, zd: 0.0}, t_end=5),
    units="cgs in the simulation",
)
