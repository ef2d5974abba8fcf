"""Wells, eq. (14.23) (= Problem 14.21) — particle on a table turning by beta(t) about Z1 at O1 of the earth
frame (Fig. 14-2); T by v = v0 + rdot + omega x r with the table's v0 and omega along the table axes.

Position: E.point(rot_z(beta) (x, y, z)); beta(t) = Omega t prescribed (substituted in the book's T).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame
from lagrange.model.rotations import rot_z

beta, x, y, z = coordinates("beta x y z")
m, w, R, Phi, Om = parameters("m omega_e R Phi Omega")
sb, cb, sF, cF = sp.sin(beta), sp.cos(beta), sp.sin(Phi), sp.cos(Phi)
bd, xd, yd, zd = (q.diff(t) for q in (beta, x, y, z))
E = EarthFrame(Phi, w, R)
beta_t = Om * t  # the table turns uniformly (prescribed)
system = System([x, y, z], bodies=[Particle(m, E.point(rot_z(beta) * sp.Matrix([x, y, z])), name="particle")],
                prescribed={beta: beta_t},
                name="particle on a rotating table on the earth")

v0x, v0y, v0z = R * w * cb * cF, -R * w * sb * cF, 0
wx, wy, wz = w * sb * cF, w * cb * cF, bd + w * sF
T_book = sp.Rational(1, 2) * m * ((v0x + xd + wy * z - wz * y) ** 2 + (v0y + yd + wz * x - wx * z) ** 2
                                  + (v0z + zd + wx * y - wy * x) ** 2)

PROBLEM = Problem(
    id="eq14.23",
    title="Particle on a rotating table at O1 on the earth: T (14.23) by v0 + rdot + omega x r",
    chapter=14,
    source="Wells, eq. (14.23), Problem 14.21",
    system=system,
    answers=[KineticEnergy(T_book.subs(bd, beta_t.diff(t)).subs(beta, beta_t))],
    simulation=Simulation(params={m: 1.0, w: 7.29211e-5, R: 6.378e6, Phi: 0.7, Om: 1.0},
                          initial={x: 1.0, y: 0.0, z: 0.0, xd: 0.0, yd: 0.5, zd: 0.0}, t_end=2.0),
    units="SI in the simulation",
)
