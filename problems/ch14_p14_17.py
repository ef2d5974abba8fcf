"""Wells, Problem 14.17 — scales carried east at speed v along the equator: the reading (support force) is
m g' - m (v^2/R + 2 omega_e v).

Particle in earth-centred spherical coordinates (r, Phi1, phi) on the earth turning at omega_e (14.21);
true gravity at the equator g = g' + omega_e^2 R (from EarthFrame.true_gravity at Phi = 0), radial.
Support force for the prescribed motion r = R, Phi1 = 0, phi = v t / R from driving_forces (13.1).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, driving_forces, parameters, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

r, lat, phi = coordinates("r Phi1 phi")
m, gp, w, R, v = parameters("m g_prime omega_e R v")
g_true = -EarthFrame(0, w, R).true_gravity(gp)[2]  # g' + omega_e^2 R at the equator
lon = phi + w * t
pos = (r * sp.cos(lat) * sp.cos(lon), r * sp.cos(lat) * sp.sin(lon), r * sp.sin(lat))
system = System([r, lat, phi], bodies=[Particle(m, pos, name="scales")], forces={r: -m * g_true},
                name="scales moving east on the equator")


def _reading(s):
    return driving_forces(s, {r: R, lat: 0, phi: v * t / R})[r]


PROBLEM = Problem(
    id="p14.17",
    title="Scales moving east at speed v on the equator read m g' - m(v^2/R + 2 omega_e v)",
    chapter=14,
    source="Wells, Problem 14.17",
    system=system,
    answers=[Quantity("scale reading (radial support force)", _reading, m * gp - m * (v**2 / R + 2 * w * v))],
)
