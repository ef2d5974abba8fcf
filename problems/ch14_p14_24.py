"""Wells, Problem 14.24 — equations of motion from the cylindrical-coordinate T (14.17) on the rotating earth.

x1 = rho cos(phi), y1 = rho sin(phi), z1 = z in the earth frame of Fig. 14-2; gravity by the true g (EarthFrame).
The R omega_e^2 terms cancel against the true gravity, leaving -m g' on the z equation.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation
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

PROBLEM = Problem(
    id="p14.24",
    title="Equations of motion in cylindrical coordinates on the rotating earth (from 14.17)",
    chapter=14,
    source="Wells, Problem 14.24",
    system=system,
    answers=[
        EquationsOfMotion(
            [
                sp.Eq(m * rho.diff(t, 2) - m * rho * pd**2 + m * w * (2 * zd * cp_ * cF - 2 * rho * pd * sF)
                      + m * w**2 * (z * sp_ * sF * cF - rho * (cp_**2 + sp_**2 * sF**2)), 0),
                # phi equation divided by rho, as printed
                sp.Eq(m * rho * phi.diff(t, 2) + 2 * m * rd * pd + 2 * m * w * (rd * sF - zd * sp_ * cF)
                      + m * w**2 * cp_ * cF * (rho * sp_ * cF + z * sF), 0),
                sp.Eq(m * z.diff(t, 2) + 2 * m * w * cF * (rho * pd * sp_ - rd * cp_)
                      + m * w**2 * cF * (rho * sp_ * sF - z * cF), -m * gp),
            ],
            # each printed equation holds a single acceleration (M = diag(m, m rho^2, m)), so the acceleration
            # comparison checks them one by one; the harness's per-equation ratio (sp.cancel) misses
            # cos^2 = 1 - sin^2 and the phi equation is printed divided by rho.
            per_equation=False,
        ),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={rho: 100.0, phi: 0.3, z: 0.0, rd: 10.0, pd: 0.1, zd: 50.0},
        t_end=2,
    ),
    units="cgs in the simulation",
    correction="phi equation: the book prints '2 m rho phi_dot'; the term is 2 m rho_dot phi_dot (d/dt of "
    "m rho^2 phi_dot, divided by rho; dimensionally the printed term lacks a time derivative). Re-derived in the "
    "catalog (sym check).",
)
