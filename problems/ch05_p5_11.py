"""Wells, Problem 5.11 — uniform bar (length 2 r2, mass M) hanging from a coil spring (Fig. 5-17)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Simulation

r1, theta, phi = coordinates("r1 theta phi")
M, I, k, r0, r2, g = parameters("M I k r0 r2 g")

# Spring from the fixed support to the bar's end: length r1, angle theta; bar at angle phi; Y measured downward.
cm = (r1 * sp.sin(theta) + r2 * sp.sin(phi), r1 * sp.cos(theta) + r2 * sp.cos(phi))
system = System([r1, theta, phi], T=I * phi.diff(t) ** 2 / 2, bodies=[Particle(M, cm)],
                V=k * (r1 - r0) ** 2 / 2 - M * g * cm[1], name="bar on a coil spring")

r1d, thd, phd = r1.diff(t), theta.diff(t), phi.diff(t)
T_book = (M / 2 * (r1d**2 + r1**2 * thd**2 + r2**2 * phd**2 + 2 * sp.cos(phi - theta) * r1 * r2 * thd * phd
                   - 2 * sp.sin(phi - theta) * r2 * r1d * phd)
          + I * phd**2 / 2)
V_book = k * (r1 - r0) ** 2 / 2 - M * g * (r1 * sp.cos(theta) + r2 * sp.cos(phi))  # L = T_book - V_book

PROBLEM = Problem(
    id="p5.11",
    title="Bar hanging on a coil spring: L in (r1, theta, phi)",
    chapter=5,
    source="Wells, Problem 5.11",
    system=system,
    answers=[
        KineticEnergy(T_book),
        PotentialEnergy(V_book),
    ],
    simulation=Simulation(params={M: 1, I: 1 / 3, k: 30, r0: 1, r2: 1, g: 9.81},
                          initial={r1: 1.3, theta: 0.3, phi: -0.2, r1.diff(t): 0, theta.diff(t): 0, phi.diff(t): 0},
                          t_end=5),
)
