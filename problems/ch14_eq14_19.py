"""Wells, Sec. 14.6, eqs. (14.19)-(14.20) (and Problem 14.25) — the polar-parallel frame of Fig. 14-3.

Origin O1 on the earth's surface at latitude Phi; Z1 parallel to the polar axis, X1 perpendicular to it (outward,
in O1's meridian plane), Y1 east. The frame turns with the earth at omega_e about the polar axis, at distance
R cos(Phi) from it. Gravity is the same true g as in Fig. 14-2 (EarthFrame.gravity_force at the same meridian):
F_x1 = -m g cos(Phi - alpha) = -m g' cPhi - m omega_e^2 R cPhi, F_y1 = 0, F_z1 = -m g sin(Phi - alpha) = -m g' sPhi.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame, Frame
from lagrange.model.rotations import rot_z

x, y, z = coordinates("x1 y1 z1")
m, gp, w, R, Phi = parameters("m g_prime omega_e R Phi")
sF, cF = sp.sin(Phi), sp.cos(Phi)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

spin = rot_z(w * t)
polar = Frame(origin=spin * sp.Matrix([R * cF, 0, R * sF]), rotation=spin, name="polar-parallel")
E = EarthFrame(Phi, w, R)  # only for the true gravity vector
p = Particle(m, polar.point((x, y, z)), name="particle")
system = System([x, y, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))],
                name="particle in the polar-parallel frame")

T_book = sp.Rational(1, 2) * m * (xd**2 + yd**2 + zd**2 + (x**2 + y**2) * w**2 + 2 * w * (x * yd - y * xd)
                                  + 2 * R * w * (x * w + yd) * cF)
T_book += sp.Rational(1, 2) * m * R**2 * w**2 * cF**2  # constant dropped in the book (see correction)

PROBLEM = Problem(
    id="eq14.19",
    title="Particle in the polar-parallel frame (Fig. 14-3): T (14.19), gravity forces, EOM (14.20)",
    chapter=14,
    source="Wells, Sec. 14.6, eqs. (14.19), (14.20); Problem 14.25",
    system=system,
    answers=[
        KineticEnergy(T_book),
        GeneralizedForces({x: -m * gp * cF - m * w**2 * R * cF, y: 0, z: -m * gp * sF}),
        EquationsOfMotion(
            [
                sp.Eq(m * (x.diff(t, 2) - x * w**2 - 2 * yd * w - R * w**2 * cF), -m * gp * cF - m * w**2 * R * cF),
                sp.Eq(m * (y.diff(t, 2) - y * w**2 + 2 * w * xd), 0),
                sp.Eq(m * z.diff(t, 2), -m * gp * sF),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={x: 0.0, y: 0.0, z: 0.0, xd: 1000.0, yd: 2000.0, zd: 3000.0},
        t_end=5,
    ),
    units="cgs in the simulation",
    correction="T (14.19) omits the constant 1/2 m R^2 omega_e^2 cos^2 Phi; it is added to the book's T here "
    "(a constant does not change the equations).",
)
