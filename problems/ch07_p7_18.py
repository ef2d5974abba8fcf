"""Wells, Problem 7.18 — solid cylinder (axis Ȳ): spherical ellipsoid, spherical points and foci."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import foci, spherical_points
from lagrange.model.standard_bodies import cylinder

M, R, L = parameters("M R L")
AXIS_Z_TO_Y = sp.Matrix([[1, 0, 0], [0, 0, 1], [0, -1, 0]])  # rows: new X, Y, Z in the old axes


def cyl(length):
    return cylinder(M, R, length).rotated(AXIS_Z_TO_Y)


sphere_like = cyl(R * sp.sqrt(3))
Ibar_x, Ibar_y = M * (3 * R**2 + L**2) / 12, M * R**2 / 2

PROBLEMS = [
    Problem(
        id="p7.18",
        title="Cylinder: L = R√3 gives a spherical c.m. ellipsoid; R = L and L → 0 give spherical points on Ȳ",
        chapter=7,
        source="Wells, Problem 7.18(a), (b), (d)",
        system=None,
        answers=[
            Quantity("(a) c.m. moments for L = R√3", lambda _: [sphere_like.I_x, sphere_like.I_y, sphere_like.I_z],
                     [M * R**2 / 2] * 3),
            Quantity("(b) spherical points for R = L", lambda _: spherical_points(M, cyl(R), "y"), R / sp.sqrt(6)),
            Quantity("(b) the moment there", lambda _: cyl(R).from_centre(M, (0, R / sp.sqrt(6), 0)).I_x,
                     M * R**2 / 2),
            Quantity("(d) spherical points as L → 0", lambda _: spherical_points(M, cyl(0), "y"), R / 2),
        ],
    ),
    Problem(
        id="p7.18-foci",
        title="Cylinder with L > R√3: foci on X̄ and Z̄",
        chapter=7,
        source="Wells, Problem 7.18(c)",
        system=None,
        answers=[
            Quantity("(c) focus distance on X̄", lambda _: foci(M, cyl(L), "x")["y"], sp.sqrt((Ibar_x - Ibar_y) / M)),
            Quantity("(c) focus distance on Z̄", lambda _: foci(M, cyl(L), "z")["y"], sp.sqrt((Ibar_x - Ibar_y) / M)),
        ],
        ranges={"R": (1.0, 1.5), "L": (3.0, 4.0)},
    ),
]
