"""Wells, Example 7.9 (Sec. 7.10) — six equimomental particles M/6 on the principal axes."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia, equimomental_particles, point_masses

M, Ix, Iy, Iz = parameters("M Ibar_x Ibar_y Ibar_z")
x, y, z = sp.symbols("x y z", real=True)
particles = equimomental_particles(M, Inertia(Ix, Iy, Iz))
a = sp.sqrt(sp.Rational(3, 2) / M * (Iy + Iz - Ix))
b = sp.sqrt(sp.Rational(3, 2) / M * (Ix + Iz - Iy))
c = sp.sqrt(sp.Rational(3, 2) / M * (Ix + Iy - Iz))
m1 = m2 = m3 = M / 6

PROBLEM = Problem(
    id="ex7.9",
    title="Equimomental body: six particles M/6 at ±a, ±b, ±c on the principal axes",
    chapter=7,
    source="Wells, Sec. 7.10 and Example 7.9",
    system=None,
    answers=[
        Quantity("particle masses", lambda _: [m for m, _p in particles], [M / 6] * 6),
        Quantity("(a, b, c)", lambda _: [particles[0][1][0], particles[2][1][1], particles[4][1][2]], [a, b, c]),
        Quantity("ellipsoid of the particle set", lambda _: point_masses(particles).ellipsoid(x, y, z),
                 (2 * m2 * b**2 + 2 * m3 * c**2) * x**2 + (2 * m1 * a**2 + 2 * m3 * c**2) * y**2
                 + (2 * m1 * a**2 + 2 * m2 * b**2) * z**2),
    ],
    ranges={"Ibar_x": (1.5, 2.0), "Ibar_y": (1.5, 2.0), "Ibar_z": (1.5, 2.0)},
)
