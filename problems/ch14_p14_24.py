"""Wells, Problem 14.24 — equations of motion from the cylindrical-coordinate T (14.17) on the rotating earth.

The system is Sec. 14.5's (``ch14_eq14_17``: x1 = rho cos(phi), y1 = rho sin(phi), z1 = z in the earth frame of
Fig. 14-2, gravity by the true g through EarthFrame); this problem checks its equations of motion. The R omega_e^2
terms cancel against the true gravity, leaving -m g' on the z equation.
"""

import sympy as sp
from lagrange_problems import ch14_eq14_17 as sec14_5
from lagrange_problems._common import variant

from lagrange import t
from lagrange.corpus import EquationsOfMotion

rho, phi, z = sec14_5.rho, sec14_5.phi, sec14_5.z
m, gp, w = sec14_5.m, sec14_5.gp, sec14_5.w
sF, cF, sp_, cp_ = sec14_5.sF, sec14_5.cF, sec14_5.sp_, sec14_5.cp_
rd, pd, zd = rho.diff(t), phi.diff(t), z.diff(t)

PROBLEM = variant(
    sec14_5.PROBLEM,
    id="p14.24",
    title="Equations of motion in cylindrical coordinates on the rotating earth (from 14.17)",
    source="Wells, Problem 14.24",
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
    correction="phi equation: the book prints '2 m rho phi_dot'; the term is 2 m rho_dot phi_dot (d/dt of "
    "m rho^2 phi_dot, divided by rho; dimensionally the printed term lacks a time derivative). Re-derived in the "
    "catalog (sym check).",
)
