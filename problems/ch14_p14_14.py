"""Wells, Problem 14.14 — elevator (3000 lb) rising at 30 mi/h at latitude 45 deg: the horizontal force the
guides must exert, f_x1 = 2 M omega_e zdot1 cos(Phi) = 13.6 poundals (east), and f_y1 = 0 at z1 = 0.

Particle (the elevator) in the earth frame of Fig. 14-2 with true gravity; the force needed for the prescribed
motion x1 = y1 = 0, z1 = v t comes from driving_forces (Wells 13.1), evaluated at t = 0 (z1 = 0).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, driving_forces, parameters, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
M, gp, w, R, Phi, v = parameters("M g_prime omega_e R Phi v")
E = EarthFrame(Phi, w, R)
car = Particle(M, E.point((x, y, z)), name="elevator")
system = System([x, y, z], bodies=[car], forces=[Force(car, E.gravity_force(M, gp))], name="rising elevator")

VALUES = {M: 3000, gp: sp.Float("32.174"), w: sp.Float("7.29211e-5"), R: sp.Float("20.96e6"), Phi: sp.pi / 4,
          v: 44}  # fps units: lb, ft/s^2, ft; 30 mi/h = 44 ft/s

def _f(q):
    def compute(s):
        f = driving_forces(s, {x: 0, y: 0, z: v * t})
        return sp.N(f[q].subs(t, 0).subs(VALUES), 20)
    return compute

PROBLEM = Problem(
    id="p14.14",
    title="Elevator rising at 30 mi/h at 45 deg: guide force f_x1 = 2 M omega_e zdot cos(Phi) = 13.6 poundals",
    chapter=14,
    source="Wells, Problem 14.14",
    system=system,
    answers=[
        Quantity("f_x1 (poundals)", _f(x), 13.6, rtol=5e-3),
        Quantity("f_x1 symbolic", lambda s: driving_forces(s, {x: 0, y: 0, z: v * t})[x],
                 2 * M * w * v * sp.cos(Phi)),
        Quantity("f_y1 at z1 = 0", lambda s: driving_forces(s, {x: 0, y: 0, z: v * t})[y].subs(t, 0), 0),
    ],
    units="fps (poundals)",
    correction="13.6 is rounded (13.61 computed); rtol 5e-3.",
)
