"""Wells, Problem 14.22 — bead on a conical spiral wire fixed on the rotating earth, X, Y, Z = X1, Y1, Z1 of
Fig. 14-2; coordinate z.

The book's T holds exactly for the spiral x = a z cos(b z), y = -a z sin(b z) (see correction).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

z = coordinates("z")
m, a, b, gp, w, R, Phi = parameters("m a b g_prime omega_e R Phi")
E = EarthFrame(Phi, w, R)
bead = Particle(m, E.point((a * z * sp.cos(b * z), -a * z * sp.sin(b * z), z)), name="bead")
system = System([z], bodies=[bead], forces=[Force(bead, E.gravity_force(m, gp))], name="bead on a conical spiral")

zd = z.diff(t)
sF, cF, sb, cb = sp.sin(Phi), sp.cos(Phi), sp.sin(b * z), sp.cos(b * z)
half = sp.Rational(1, 2)
T_book = (half * m * (a**2 * (1 + b**2 * z**2) + 1) * zd**2
          - m * w * a * zd * (a * b * z**2 * sF - (R + z) * (cb - b * z * sb) * cF + z * cb * cF)
          + half * m * w**2 * (a**2 * z**2 * (cb**2 + sb**2 * sF**2) + (R + z) ** 2 * cF**2
                               + 2 * a * z * (R + z) * sb * sF * cF))

PROBLEM = Problem(
    id="p14.22",
    title="Bead on a conical spiral wire on the rotating earth: T",
    chapter=14,
    source="Wells, Problem 14.22",
    system=system,
    answers=[KineticEnergy(T_book)],
    simulation=Simulation(params={m: 1.0, a: 0.5, b: 2.0, gp: 9.8, w: 7.29211e-5, R: 6.378e6, Phi: 0.7},
                          initial={z: 1.0, zd: 0.0}, t_end=2.0),
    units="SI in the simulation",
    correction="The statement's spiral x = a z cos(bz), y = a z sin(bz) does not give the printed T; the printed T is "
    "exact for y = -a z sin(bz) (opposite handedness; catalog re-derivation), which is used here.",
)
