"""Wells, Problems 6.1 and 6.17 — sphere on a rubber band moving in a viscous liquid, spherical coordinates."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

r, theta, phi = coordinates("r theta phi")
m, g, k, r0, a = parameters("m g k r0 a")

# theta from the downward vertical (Z down).
pos = (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta))
speed2 = sum(c.diff(t) ** 2 for c in pos)
system = System([r, theta, phi], bodies=[Particle(m, pos)], V=k * (r - r0) ** 2 / 2 - m * g * pos[2],
                P=-a * speed2 / 2, name="sphere on a rubber band in a viscous liquid")

rd, thd, phd = r.diff(t), theta.diff(t), phi.diff(t)
PROBLEM = Problem(
    id="p6.1",
    title="Viscous drag on a sphere in spherical coordinates: F_r = -a rd, F_theta = -a r^2 thd, F_phi = ...",
    chapter=6,
    source="Wells, Problem 6.1 (P form: Problem 6.17)",
    system=system,
    answers=[
        GeneralizedForces({r: -a * rd, theta: -a * r**2 * thd, phi: -a * r**2 * sp.sin(theta) ** 2 * phd}),
        PowerFunction(-a * (rd**2 + r**2 * thd**2 + r**2 * sp.sin(theta) ** 2 * phd**2) / 2),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 30, r0: 1, a: 0.3},
                          initial={r: 1.3, theta: 0.5, phi: 0, r.diff(t): 0, theta.diff(t): 0, phi.diff(t): 1},
                          t_end=5),
    correction="V (rubber band k, gravity) is supplied for simulation; the book's answers are the drag forces.",
)
