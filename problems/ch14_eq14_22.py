"""Wells, eq. (14.22) — particle relative to a railroad car on a straight track at angle beta in the X1Y1
plane of the earth frame (Fig. 14-2); the car is at distance S(t) along the track; frame X along the track.

x1 = (S + x) cos(beta) - y sin(beta), y1 = (S + x) sin(beta) + y cos(beta), z1 = z.
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

S, x, y, z = coordinates("S x y z")
m, w, R, Phi, beta, a = parameters("m omega_e R Phi beta a")
sb, cb, sF, cF = sp.sin(beta), sp.cos(beta), sp.sin(Phi), sp.cos(Phi)
Sd, xd, yd, zd = (q.diff(t) for q in (S, x, y, z))
E = EarthFrame(Phi, w, R)
X1 = S * cb + x * cb - y * sb
Y1 = S * sb + x * sb + y * cb
S_t = a * t**2 / 2  # the car's motion S(t), prescribed (uniform acceleration a)
system = System([x, y, z], bodies=[Particle(m, E.point((X1, Y1, z)), name="particle")], prescribed={S: S_t},
                name="particle in a car on a track on the rotating earth")

half = sp.Rational(1, 2)
T_book = (half * m * ((Sd + xd) ** 2 + yd**2 + zd**2)
          + m * w * (yd * (S + x) * sF - y * (Sd + xd) * sF
                     + cF * ((R + z) * (Sd * cb + xd * cb - yd * sb) - X1 * zd))
          + half * m * w**2 * (X1**2 + Y1**2 * sF**2 - 2 * Y1 * (R + z) * sF * cF + (R + z) ** 2 * cF**2))

PROBLEM = Problem(
    id="eq14.22",
    title="Particle in a car on a track at angle beta on the rotating earth: T (14.22)",
    chapter=14,
    source="Wells, eq. (14.22)",
    system=system,
    answers=[KineticEnergy(T_book.subs(Sd, S_t.diff(t)).subs(S, S_t))],
    simulation=Simulation(params={m: 1.0, w: 7.29211e-5, R: 6.378e6, Phi: 0.7, beta: 0.4, a: 1.0},
                          initial={x: 0.0, y: 0.0, z: 0.0, xd: 0.0, yd: 1.0, zd: 0.0}, t_end=2.0),
    units="SI in the simulation",
)
