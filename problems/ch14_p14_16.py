"""Wells, Problem 14.16 — particle on a smooth board hinged along X1 and inclined at theta to the X1Y1 plane of
the earth frame (Fig. 14-2): y1 = s cos(theta), z1 = s sin(theta); coordinates x1 and s; true gravity.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation
from lagrange.model.frames import EarthFrame

x, s = coordinates("x1 s")
m, gp, w, R, Phi, th = parameters("m g_prime omega_e R Phi theta")
E = EarthFrame(Phi, w, R)
p = Particle(m, E.point((x, s * sp.cos(th), s * sp.sin(th))), name="particle")
system = System([x, s], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))], name="particle on an inclined board")

sd = sp.sin(Phi - th)
PROBLEM = Problem(
    id="p14.16",
    title="Particle on a smooth inclined board hinged along X1 on the rotating earth",
    chapter=14,
    source="Wells, Problem 14.16",
    system=system,
    answers=[EquationsOfMotion([
        sp.Eq(m * x.diff(t, 2) - 2 * m * w * s.diff(t) * sd - m * w**2 * x, 0),
        sp.Eq(m * s.diff(t, 2) + m * w * sd * (2 * x.diff(t) - w * s * sd), -m * gp * sp.sin(th)),
    ], per_equation=True)],
    simulation=Simulation(params={m: 1.0, gp: 9.8, w: 7.29211e-5, R: 6.378e6, Phi: 0.8, th: 0.3},
                          initial={x: 0.0, s: 1.0, x.diff(t): 0.5, s.diff(t): 0.0}, t_end=2.0),
    units="SI in the simulation",
)
