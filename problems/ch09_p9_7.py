"""Wells, Problem 9.7 — T of the particle of Ex. 9.10(a): frame carried north along a meridian at the constant
rate Phi_dot on the rotating earth (X1 east, Y1 north, Z1 up; Phi = Phi0 + Phi_dot t; radius R)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x y z")
m, w, R, Phi0, Phid = parameters("m omega_e R Phi_0 Phi_dot")
Phi = Phi0 + Phid * t
s, c = sp.sin(Phi), sp.cos(Phi)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

E = EarthFrame(Phi, w, R)
system = System([x, y, z], bodies=[Particle(m, E.point((x, y, z)), name="particle")],
                name="particle in a frame moving north on the rotating earth")

T_book = sp.Rational(1, 2) * m * ((R * w * c + z * w * c + xd - y * w * s) ** 2
                                  + (R * Phid + yd + x * w * s + z * Phid) ** 2
                                  + (zd - y * Phid - x * w * c) ** 2)

PROBLEM = Problem(
    id="p9.7",
    title="Kinetic energy of a particle in a frame moving north on the rotating earth",
    chapter=9,
    source="Wells, Problem 9.7",
    system=system,
    answers=[KineticEnergy(T_book)],
    simulation=Simulation(params={m: 1.0, w: 7.29211e-5, R: 6.378e8, Phi0: 0.5, Phid: 1e-4},
                          initial={x: 0.0, y: 0.0, z: 0.0, xd: 10.0, yd: 0.0, zd: 0.0}, t_end=5),
    units="cgs in the simulation",
    correction="OCR puts dots on omega_e; omega_e is the constant earth rate.",
)
