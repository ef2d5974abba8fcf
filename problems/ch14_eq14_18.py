"""Wells, eq. (14.18) — particle relative to the geocentric frame X'Y'Z' at O1: Z' along the earth's radius
(geocentric latitude Phi1, radius R1), Y' toward the pole; the plumb line (geodetic latitude Phi) makes the
angle Phi - Phi1 with Z'.

The frame is EarthFrame(Phi1, omega_e, R1). True gravity comes from the geodetic frame's (14.11)
(EarthFrame(Phi, omega_e, R).gravity_force) with the normal length R = R1 cos(Phi1)/cos(Phi) (both give the
distance of O1 from the polar axis). The equations take the form of (14.16) with R1, Phi1 and right-hand sides
0, -g' sin(Phi - Phi1), -g' cos(Phi - Phi1).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x y z")
m, gp, w, R1, Phi, Phi1 = parameters("m g_prime omega_e R_1 Phi Phi_1")
Eg = EarthFrame(Phi1, w, R1)
Ed = EarthFrame(Phi, w, R1 * sp.cos(Phi1) / sp.cos(Phi))
p = Particle(m, Eg.point((x, y, z)), name="particle")
system = System([x, y, z], bodies=[p], forces=[Force(p, Ed.gravity_force(m, gp))],
                name="particle in the geocentric frame")

s1, c1 = sp.sin(Phi1), sp.cos(Phi1)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
PROBLEM = Problem(
    id="eq14.18",
    title="Particle in the geocentric frame X'Y'Z': (14.16) form with R1, Phi1 and g' components along Y', Z'",
    chapter=14,
    source="Wells, eq. (14.18)",
    system=system,
    answers=[EquationsOfMotion([
        sp.Eq(x.diff(t, 2) + 2 * w * (zd * c1 - yd * s1) - w**2 * x, 0),
        sp.Eq(y.diff(t, 2) + 2 * w * xd * s1 + w**2 * s1 * (z * c1 - y * s1), -gp * sp.sin(Phi - Phi1)),
        sp.Eq(z.diff(t, 2) - 2 * w * xd * c1 - w**2 * c1 * (z * c1 - y * s1), -gp * sp.cos(Phi - Phi1)),
    ], per_equation=True)],
    simulation=Simulation(params={m: 1.0, gp: 9.8, w: 7.29211e-5, R1: 6.367e6, Phi: 0.7854, Phi1: 0.7820},
                          initial={x: 0.0, y: 0.0, z: 100.0, xd: 10.0, yd: 0.0, zd: 0.0}, t_end=2.0),
    ranges={Phi: (0.6, 0.9), Phi1: (0.4, 0.59)},
    units="SI in the simulation",
    correction="The R omega_e^2 terms cancel only with R cos(Phi) = R1 cos(Phi1) (distance of O1 from the polar axis), "
    "the ellipsoid relation the book uses implicitly.",
)
