"""Wells, Problem 7.15 — solid cylinder (axis Y): ellipsoid of inertia at the centre of an end face."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import cylinder

M, R, L = parameters("M R L")
x, y, z = sp.symbols("x y z", real=True)
AXIS_Z_TO_Y = sp.Matrix([[1, 0, 0], [0, 0, 1], [0, -1, 0]])  # rows: new X, Y, Z in the old axes
at_p2 = cylinder(M, R, L).rotated(AXIS_Z_TO_Y).from_centre(M, (0, L / 2, 0))

PROBLEM = Problem(
    id="p7.15",
    title="Solid cylinder: ellipsoid of inertia at the centre p2 of an end face",
    chapter=7,
    source="Wells, Problem 7.15",
    system=None,
    answers=[
        Quantity("ellipsoid at p2 (left side of = 1)", lambda _: at_p2.ellipsoid(x, y, z),
                 (M * (3 * R**2 + L**2) / 12 + M * L**2 / 4) * (x**2 + z**2) + M * R**2 / 2 * y**2),
        Quantity("products at p2 (principal axes parallel to the c.m. axes)",
                 lambda _: [at_p2.I_xy, at_p2.I_xz, at_p2.I_yz], [0, 0, 0]),
    ],
)
