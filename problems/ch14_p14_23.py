"""Wells, Problem 14.23 — mass m sliding on a rod fixed at angle theta to a vertical shaft (along Z1 through O1
of Fig. 14-2) that turns at the constant rate omega (phi = omega t); spring force k(l - l0 - r) along the rod;
coordinate r along the rod from O1. True gravity (EarthFrame).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Simulation
from lagrange.model.frames import EarthFrame

r = coordinates("r")
m, gp, w, R, Phi, th, om, k, l, l0 = parameters("m g_prime omega_e R Phi theta omega k l l_0")
E = EarthFrame(Phi, w, R)
ph = om * t
p = Particle(m, E.point((r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th))), name="m")
system = System([r], bodies=[p], forces=[Force(p, E.gravity_force(m, gp)), {r: k * (l - l0 - r)}],
                name="mass on a rod turning about the vertical on the rotating earth")

st, ct, sF, cF, sph, cph = sp.sin(th), sp.cos(th), sp.sin(Phi), sp.cos(Phi), sp.sin(ph), sp.cos(ph)
lhs = (m * r.diff(t, 2) - m * r * om**2 * st**2 + 2 * w * om * r * m * st * (ct * sph * cF - st * sF)
       - m * w**2 * r * ((ct * cF - st * sph * sF) ** 2 + st**2 * cph**2))

PROBLEM = Problem(
    id="p14.23",
    title="Mass on a spring along a rod turning about the vertical on the rotating earth",
    chapter=14,
    source="Wells, Problem 14.23",
    system=system,
    answers=[EquationsOfMotion([sp.Eq(lhs, k * (l - l0 - r) - m * gp * ct)], per_equation=True)],
    simulation=Simulation(params={m: 1.0, gp: 9.8, w: 7.29211e-5, R: 6.378e6, Phi: 0.7, th: 0.5, om: 2.0, k: 50.0,
                                  l: 1.0, l0: 0.2},
                          initial={r: 0.8, r.diff(t): 0.0}, t_end=2.0),
    units="SI in the simulation",
    correction="The OCR prints '... - sin(theta) sin(phi)' in the Coriolis bracket; it must be sin(Phi) (latitude), "
    "as the catalog re-derivation shows.",
)
