"""Wells, Example 14.9 — thin rod (mass M, moment of inertia I about its c.m. normal to the plane) moving in the
X1Y1 plane of the polar-parallel frame (Fig. 14-3).

Rod: RigidBody with its c.m. at (x1, y1, 0) of the frame, turned by theta about Z1 relative to the frame, which
itself turns at omega_e about the polar axis. True gravity from EarthFrame (same meridian).
"""

import sympy as sp

from lagrange import Force, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame, Frame
from lagrange.model.rotations import rot_z

x, y, th = coordinates("x1 y1 theta")
M, I, gp, w, R, Phi = parameters("M I g_prime omega_e R Phi")
cF = sp.cos(Phi)
xd, yd, thd = x.diff(t), y.diff(t), th.diff(t)

spin = rot_z(w * t)
polar = Frame(origin=spin * sp.Matrix([R * cF, 0, R * sp.sin(Phi)]), rotation=spin, name="polar-parallel")
E = EarthFrame(Phi, w, R)  # true gravity vector only
rod = RigidBody(M, (0, I, I), origin=polar.point((x, y, 0)), orientation=spin * rot_z(th), name="rod")
system = System([x, y, th], bodies=[rod], forces=[Force(rod.centre_of_mass, E.gravity_force(M, gp))],
                name="thin rod in the polar-parallel frame")

T_book = (sp.Rational(1, 2) * M * ((xd**2 + yd**2) + w**2 * (x**2 + y**2) + 2 * w * (x * yd - y * xd)
                                   + 2 * w * R * (x * w + yd) * cF)
          + sp.Rational(1, 2) * I * (thd + w) ** 2)
T_book += sp.Rational(1, 2) * M * R**2 * w**2 * cF**2  # constant not printed (see correction)

PROBLEM = Problem(
    id="ex14.9",
    title="Thin rod moving in the X1Y1 plane of the polar-parallel frame: T, gravity force, conserved I(thetadot+we)",
    chapter=14,
    source="Wells, Example 14.9",
    system=system,
    answers=[
        KineticEnergy(T_book),
        # F_x1 = -M g cos(Phi - alpha) = -M (g' + omega_e^2 R) cPhi  (14.19 relations)
        GeneralizedForces({x: -M * (gp + w**2 * R) * cF, y: 0, th: 0}),
        # the book's third equation I thetadd = 0, as a first integral
        ConservedMomenta({th: I * (thd + w)}),
    ],
    simulation=Simulation(
        params={M: 1.0, I: 2.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={x: 0.0, y: 0.0, th: 0.0, xd: 100.0, yd: 50.0, thd: 1.0},
        t_end=2,
    ),
    units="cgs in the simulation",
    correction="T as printed omits the constant 1/2 M R^2 omega_e^2 cos^2 Phi (added here). The book's x1, y1 "
    "equations drop the x1 omega_e^2, y1 omega_e^2 terms, so they are not compared (the engine keeps them); "
    "I thetadd = 0 is checked as the conserved momentum of the ignorable theta.",
)
