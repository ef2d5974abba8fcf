"""Wells, Sec. 14.5, eq. (14.17) (= Problem 14.9) — particle in cylindrical coordinates about Z1 in the earth frame.

x1 = rho cos(phi), y1 = rho sin(phi), z1 = z in the frame of Fig. 14-2, substituted through EarthFrame. Gravity by
the true g: F_rho = m g sin(alpha) sin(phi), F_phi = m g rho sin(alpha) cos(phi), F_z = -m g cos(alpha), with
(14.11) g sin(alpha) = omega_e^2 R sPhi cPhi and g cos(alpha) = g' + omega_e^2 R cos^2 Phi.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

rho, phi, z = coordinates("rho phi z")
m, gp, w, R, Phi = parameters("m g_prime omega_e R Phi")
sF, cF = sp.sin(Phi), sp.cos(Phi)
sp_, cp_ = sp.sin(phi), sp.cos(phi)
rd, pd, zd = rho.diff(t), phi.diff(t), z.diff(t)

E = EarthFrame(Phi, w, R)
p = Particle(m, E.point((rho * cp_, rho * sp_, z)), name="particle")
system = System([rho, phi, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))],
                name="particle in cylindrical coordinates on the rotating earth")

g_sin_alpha = w**2 * R * sF * cF          # (14.11)
g_cos_alpha = gp + w**2 * R * cF**2       # (14.11)

T_book = (sp.Rational(1, 2) * m * (rd**2 + rho**2 * pd**2 + zd**2)
          + m * w * (rho**2 * pd * sF + (R + z) * (rd * cp_ - rho * pd * sp_) * cF - rho * zd * cp_ * cF)
          + sp.Rational(1, 2) * m * w**2 * (rho**2 * (cp_**2 + sp_**2 * sF**2) + (R + z) ** 2 * cF**2
                                            - 2 * rho * (R + z) * sp_ * sF * cF))

PROBLEM = Problem(
    id="eq14.17",
    title="Particle in cylindrical coordinates on the rotating earth: T (14.17) and gravity forces (Prob. 14.9)",
    chapter=14,
    source="Wells, Sec. 14.5, eq. (14.17); Problem 14.9",
    system=system,
    answers=[
        KineticEnergy(T_book),
        GeneralizedForces({rho: m * g_sin_alpha * sp_, phi: m * g_sin_alpha * rho * cp_, z: -m * g_cos_alpha}),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={rho: 100.0, phi: 0.3, z: 0.0, rd: 10.0, pd: 0.1, zd: 50.0},
        t_end=2,
    ),
    units="cgs in the simulation",
    correction="The book prints F_phi = m g_rho sin(alpha) cos(phi); 'g_rho' is an OCR slip for g*rho (virtual "
    "work of the north component m g sin(alpha) through y1 = rho sin(phi)). g sin(alpha), g cos(alpha) are "
    "written with (14.11) since the engine takes the plumb-line g'.",
)
