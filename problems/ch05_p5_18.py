"""Wells, Problem 5.18 — the bar on a coil spring of Prob. 5.11 with the support oscillating vertically, A sin(wt)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Simulation

r1, theta, phi = coordinates("r1 theta phi")
M, I, k, r0, r2, g, A, w = parameters("M I k r0 r2 g A omega")

# Y measured downward (as the book's answer implies); the support is at (0, A sin wt).
cm = (r1 * sp.sin(theta) + r2 * sp.sin(phi), A * sp.sin(w * t) + r1 * sp.cos(theta) + r2 * sp.cos(phi))
system = System([r1, theta, phi], T=I * phi.diff(t) ** 2 / 2, bodies=[Particle(M, cm)],
                V=k * (r1 - r0) ** 2 / 2 - M * g * cm[1], name="bar on a spring, oscillating support")

r1d, thd, phd = r1.diff(t), theta.diff(t), phi.diff(t)
T_book = (M / 2 * (r1d**2 + r1**2 * thd**2 + r2**2 * phd**2 + A**2 * w**2 * sp.cos(w * t) ** 2
                   + 2 * r1 * r2 * thd * phd * sp.cos(phi - theta) - 2 * r1d * r2 * phd * sp.sin(phi - theta)
                   + 2 * A * w * sp.cos(w * t) * (r1d * sp.cos(theta) - r1 * thd * sp.sin(theta) - r2 * phd * sp.sin(phi)))
          + I * phd**2 / 2)
V_book = k * (r1 - r0) ** 2 / 2 - M * g * (r1 * sp.cos(theta) + r2 * sp.cos(phi) + A * sp.sin(w * t))

PROBLEM = Problem(
    id="p5.18",
    title="Bar on a coil spring, support oscillating vertically y = A sin(wt): L with explicit t",
    chapter=5,
    source="Wells, Problem 5.18",
    system=system,
    answers=[KineticEnergy(T_book), PotentialEnergy(V_book)],
    simulation=Simulation(params={M: 1, I: 1 / 3, k: 30, r0: 1, r2: 1, g: 9.81, A: 0.1, w: 3},
                          initial={r1: 1.3, theta: 0.3, phi: -0.2, r1.diff(t): 0, theta.diff(t): 0, phi.diff(t): 0},
                          t_end=5),
    correction="Y is taken downward, as the book's answer implies (catalog).",
)
