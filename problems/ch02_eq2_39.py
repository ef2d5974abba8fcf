"""Wells, eq. (2.39) — kinetic energy of a particle in rectangular, spherical and oblique coordinates."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

m, alpha, beta = parameters("m alpha beta")
half = sp.Rational(1, 2)

x, y, z = coordinates("x y z")
rect = System([x, y, z], bodies=[Particle(m, (x, y, z))], name="particle, rectangular")

r, theta, phi = coordinates("r theta phi")
sph = System(
    [r, theta, phi],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta)))],
    name="particle, spherical",
)

q1, q2 = coordinates("q1 q2")
obl = System(
    [q1, q2],
    bodies=[Particle(m, (q1 * sp.cos(alpha) + q2 * sp.cos(beta), q1 * sp.sin(alpha) + q2 * sp.sin(beta)))],
    name="particle, oblique axes",
)

sph_v2 = r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2 + r**2 * sp.sin(theta) ** 2 * phi.diff(t) ** 2
obl_v2 = q1.diff(t) ** 2 + q2.diff(t) ** 2 + 2 * q1.diff(t) * q2.diff(t) * sp.cos(beta - alpha)


def _v2(s):
    return 2 * s.T / m


PROBLEMS = [
    Problem(
        id="eq2.39-rectangular",
        title="Particle kinetic energy in rectangular coordinates",
        chapter=2,
        source="Wells, eqs. (2.23), (2.39)",
        system=rect,
        answers=[KineticEnergy(half * m * (x.diff(t) ** 2 + y.diff(t) ** 2 + z.diff(t) ** 2))],
        simulation=Simulation(params={m: 1}, initial={x: 0, y: 0, z: 0, x.diff(t): 1, y.diff(t): 2, z.diff(t): 3},
                              t_end=1.0),
    ),
    Problem(
        id="eq2.39-spherical",
        title="Particle kinetic energy in spherical coordinates (v^2 of eq. 2.24)",
        chapter=2,
        source="Wells, eqs. (2.24), (2.39)",
        system=sph,
        answers=[KineticEnergy(half * m * sph_v2), Quantity("v^2 = 2T/m (2.24)", _v2, sph_v2)],
        simulation=Simulation(params={m: 1}, initial={r: 1.0, theta: 1.0, phi: 0.0, r.diff(t): 0.1,
                                                      theta.diff(t): 0.2, phi.diff(t): 0.5}, t_end=2.0),
    ),
    Problem(
        id="eq2.39-oblique",
        title="Particle kinetic energy in oblique coordinates at angles α, β (v^2 of eq. 2.25)",
        chapter=2,
        source="Wells, eqs. (2.25), (2.39)",
        system=obl,
        answers=[KineticEnergy(half * m * obl_v2), Quantity("v^2 = 2T/m (2.25)", _v2, obl_v2)],
        simulation=Simulation(params={m: 1, alpha: 0.2, beta: 1.3},
                              initial={q1: 0, q2: 0, q1.diff(t): 1.0, q2.diff(t): -0.5}, t_end=1.0),
    ),
]
