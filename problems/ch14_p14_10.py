"""Wells, Problem 14.10 — particle in cylindrical coordinates rho, phi, z in the polar-parallel frame (Fig. 14-3).

x1 = rho cos(phi), y1 = rho sin(phi), z1 = z in the frame of Fig. 14-3 (Z1 parallel to the polar axis, X1 outward
from it, Y1 east, origin at R cos(Phi) from the axis), turning at omega_e. True gravity as in (14.19):
m g cos(Phi - alpha) = m (g' + omega_e^2 R) cPhi along -X1 and m g sin(Phi - alpha) = m g' sPhi along -Z1.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame, Frame
from lagrange.model.rotations import rot_z

rho, phi, z = coordinates("rho phi z")
m, gp, w, R, Phi = parameters("m g_prime omega_e R Phi")
sF, cF = sp.sin(Phi), sp.cos(Phi)
sp_, cp_ = sp.sin(phi), sp.cos(phi)
rd, pd, zd = rho.diff(t), phi.diff(t), z.diff(t)

spin = rot_z(w * t)
polar = Frame(origin=spin * sp.Matrix([R * cF, 0, R * sF]), rotation=spin, name="polar-parallel")
E = EarthFrame(Phi, w, R)  # true gravity vector only
p = Particle(m, polar.point((rho * cp_, rho * sp_, z)), name="particle")
system = System([rho, phi, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))],
                name="particle in cylindrical coordinates, polar-parallel frame")

mg_cos = m * (gp + w**2 * R) * cF   # m g cos(Phi - alpha), from (14.11) / (14.19)
T_book = sp.Rational(1, 2) * m * (rd**2 + rho**2 * pd**2 + zd**2 + 2 * rho**2 * w * pd + rho**2 * w**2
                                  + 2 * R * w * rd * sp_ * cF + 2 * R * rho * w * (w + pd) * cp_ * cF)
T_book += sp.Rational(1, 2) * m * R**2 * w**2 * cF**2  # constant not printed (see correction)

PROBLEM = Problem(
    id="p14.10",
    title="Cylindrical coordinates in the polar-parallel frame: T and gravity forces",
    chapter=14,
    source="Wells, Problem 14.10",
    system=system,
    answers=[
        KineticEnergy(T_book),
        GeneralizedForces({rho: -mg_cos * cp_, phi: mg_cos * rho * sp_, z: -m * gp * sF}),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={rho: 100.0, phi: 0.3, z: 0.0, rd: 10.0, pd: 0.1, zd: 50.0},
        t_end=2,
    ),
    units="cgs in the simulation",
    correction="Forces: the book prints F_rho = -m g sin(phi) cos(Phi - alpha), F_phi = -m g rho cos(phi) "
    "cos(Phi - alpha), which belong to x1 = rho sin(phi); its own T needs x1 = rho cos(phi) (the 2 R omega_e "
    "rho_dot sin(phi) cPhi term), giving F_rho = -m g cos(phi) cos(Phi - alpha), F_phi = +m g rho sin(phi) "
    "cos(Phi - alpha) (catalog). The constant 1/2 m R^2 omega_e^2 cos^2 Phi of T is not printed; added here.",
)
