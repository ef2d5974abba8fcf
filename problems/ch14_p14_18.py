"""Wells, Problem 14.18 — water flowing north at ydot1 on the rotating earth: the free surface tilts by
tan(beta) = 2 omega_e ydot1 sin(Phi)/g', higher on the east bank (Coriolis).

A water particle in the earth frame of Fig. 14-2 with true gravity; the force the surrounding water (pressure,
normal to the free surface) must exert for the motion x1 = 0, y1 = v t, z1 = 0 comes from driving_forces
(Wells 13.1), at t = 0. The surface is normal to it: tan(beta) = -f_x1/f_z1; f_x1 < 0 (pushing west) means the
surface rises toward the east.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, driving_forces, parameters, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
m, gp, w, R, Phi, v = parameters("m g_prime omega_e R Phi v")
E = EarthFrame(Phi, w, R)
p = Particle(m, E.point((x, y, z)), name="water particle")
system = System([x, y, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))], name="water flowing north")


def _f(s):
    return driving_forces(s, {x: 0, y: v * t, z: 0})


PROBLEM = Problem(
    id="p14.18",
    title="Water flowing north: surface tilt tan(beta) = 2 omega_e ydot1 sin(Phi)/g', higher on the east bank",
    chapter=14,
    source="Wells, Problem 14.18",
    system=system,
    answers=[
        Quantity("tan(beta) = -f_x1/f_z1", lambda s: (-_f(s)[x] / _f(s)[z]).subs(t, 0), 2 * w * v * sp.sin(Phi) / gp),
        Quantity("f_x1 (westward push: east bank higher)", lambda s: _f(s)[x].subs(t, 0), -2 * m * w * v * sp.sin(Phi)),
    ],
)
