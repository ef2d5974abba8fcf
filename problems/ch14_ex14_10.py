"""Wells, Example 14.10 (and eq. 14.29 / Problem 14.29) — top with its tip fixed at O1 on the rotating earth.

Earth frame of Fig. 14-2 (X1 east, Y1 north, Z1 up). Body axes at the tip, oriented relative to X1Y1Z1 by Wells'
Euler angles (psi precession, theta nutation, phi spin; R = Rz(psi) Rx(theta) Rz(phi)); c.m. at distance r along
the body Z axis; principal moments I_x = I_y, I_z about the tip. True gravity from EarthFrame.
(14.24): omega_i = (Euler-rate terms) + alpha_i2 omega_e cPhi + alpha_i3 omega_e sPhi with Table A.1 cosines.
"""

import sympy as sp

from lagrange import Force, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame
from lagrange.model.rotations import rot_x, rot_z

psi, th, phi = coordinates("psi theta phi")
M, Ix, Iz, r, gp, w, R, Phi = parameters("M I_x I_z r g_prime omega_e R Phi")
sF, cF = sp.sin(Phi), sp.cos(Phi)
sps, cps, st, ct, sph, cph = sp.sin(psi), sp.cos(psi), sp.sin(th), sp.cos(th), sp.sin(phi), sp.cos(phi)
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)

E = EarthFrame(Phi, w, R)
top = RigidBody(M, (Ix, Ix, Iz), origin=E.point((0, 0, 0)),
                orientation=E.to_inertial()[1] * rot_z(psi) * rot_x(th) * rot_z(phi), com=(0, 0, r), name="top")
system = System([psi, th, phi], bodies=[top], forces=[Force(top.centre_of_mass, E.gravity_force(M, gp))],
                name="top on the rotating earth")

# Table A.1 (= Table 8.2) direction cosines
a11, a12 = cph * cps - sph * sps * ct, cph * sps + sph * cps * ct
a21, a22 = -sph * cps - cph * sps * ct, -sph * sps + cph * cps * ct
a31, a32, a13, a23, a33 = st * sps, -st * cps, st * sph, st * cph, ct
# (14.24)
wx = psd * st * sph + thd * cph + a12 * w * cF + a13 * w * sF
wy = psd * st * cph - thd * sph + a22 * w * cF + a23 * w * sF
wz = phd + psd * ct + a32 * w * cF + a33 * w * sF
v0x, v0y = R * w * a11 * cF, R * w * a21 * cF
# (14.27): body axes at the tip
T_a = (sp.Rational(1, 2) * M * R**2 * w**2 * cF**2 + sp.Rational(1, 2) * Ix * (wx**2 + wy**2)
       + sp.Rational(1, 2) * Iz * wz**2 + M * (v0x * wy - v0y * wx) * r)
# (14.29): c.m. velocity along X1, Y1, Z1
v_cm = [R * w * cF + r * thd * ct * sps + r * psd * st * cps + w * r * ct * cF + w * r * st * cps * sF,
        r * psd * st * sps - r * thd * ct * cps + w * r * st * sps * sF,
        -r * thd * st - w * r * st * sps * cF]
# (b): axes at the c.m., I_bar_x = I_x - M r^2 (parallel axes)
T_b = (sp.Rational(1, 2) * M * sum(v**2 for v in v_cm) + sp.Rational(1, 2) * (Ix - M * r**2) * (wx**2 + wy**2)
       + sp.Rational(1, 2) * Iz * wz**2)
# (14.28)
V_book = M * r * (ct * (gp + w**2 * R * cF**2) + st * (w**2 * R * sF * cF) * cps)

PROBLEM = Problem(
    id="ex14.10",
    title="Top with its tip fixed on the rotating earth: omega (14.24), T (14.27), c.m. velocity (14.29), V (14.28)",
    chapter=14,
    source="Wells, Example 14.10, eqs. (14.24), (14.27)-(14.29); Problem 14.29",
    system=system,
    answers=[
        Quantity("body angular velocity (14.24)", lambda _s: list(top.angular_velocity), [wx, wy, wz]),
        KineticEnergy(T_a),
        Quantity("c.m. velocity along X1, Y1, Z1 (14.29)",
                 lambda _s: list(E.to_inertial()[1].T * top.centre_of_mass.diff(t)), v_cm),
        KineticEnergy(T_b),
        GeneralizedForces({psi: -sp.diff(V_book, psi), th: -sp.diff(V_book, th), phi: 0}),
    ],
    simulation=Simulation(
        params={M: 1.0, Ix: 2.0, Iz: 1.0, r: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={psi: 0.0, th: 0.5, phi: 0.0, psd: 0.0, thd: 0.0, phd: 100.0},
        t_end=1,
    ),
    ranges={"theta": (0.3, 1.2)},
    units="cgs in the simulation",
    correction="The book gives T and V but no equations of motion (catalog: PARTIAL); T (a) and (b) and V are "
    "compared. The c.m. is taken at r (sin th sin psi, -sin th cos psi, cos th) from O1 (catalog reading of (14.29)).",
)
