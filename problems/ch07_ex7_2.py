"""Wells, Example 7.2 — thin right triangle, legs a (X) and b (Y): inertia at the corner, c.m., principal, rotated frame."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import plane_rotation
from lagrange.model.standard_bodies import triangle_plate

M, a, b, beta = parameters("M a b beta")
x, y, z, x_c, y_c = sp.symbols("x y z x_c y_c", real=True)
corner = triangle_plate(M, a, b)
central = corner.to_centre(M, (a / 3, b / 3, 0))


def _symmetric(values):
    v1, v2, v3 = values
    return [v1 + v2 + v3, v1 * v2 + v1 * v3 + v2 * v3, v1 * v2 * v3]


def _rotated_frame(_):
    J = central.from_centre(M, (x_c, y_c, 0)).rotated(plane_rotation(beta))
    return [J.I_x, J.I_y, J.I_xy, J.I_z]


root = sp.sqrt(a**4 + b**4 - a**2 * b**2)
PROBLEM = Problem(
    id="ex7.2",
    title="Thin right triangle: inertia about the corner and the c.m., principal moments, rotated frame",
    chapter=7,
    source="Wells, Example 7.2",
    system=None,
    answers=[
        Quantity("(I_x, I_y, I_z, I_xy, I_xz, I_yz) at the corner O",
                 lambda _: [corner.I_x, corner.I_y, corner.I_z, corner.I_xy, corner.I_xz, corner.I_yz],
                 [M * b**2 / 6, M * a**2 / 6, M * (a**2 + b**2) / 6, M * a * b / 12, 0, 0]),
        Quantity("ellipsoid about O", lambda _: corner.ellipsoid(x, y, z),
                 M / 6 * (b**2 * x**2 + a**2 * y**2 + (a**2 + b**2) * z**2 - a * b * x * y)),
        Quantity("(Ī_x, Ī_y, Ī_z, Ī_xy) at the c.m.",
                 lambda _: [central.I_x, central.I_y, central.I_z, central.I_xy],
                 [M * b**2 / 18, M * a**2 / 18, M * (a**2 + b**2) / 18, -M * a * b / 36]),
        Quantity("principal c.m. moments (compared through their symmetric functions)",
                 lambda _: _symmetric(central.principal()),
                 _symmetric([M / 36 * (a**2 + b**2 + root), M / 36 * (a**2 + b**2 - root), M * (a**2 + b**2) / 18])),
        Quantity("(f) I_x1, I_y1, I_x1y1, I_z1 in the frame at (x_c, y_c) turned by β", _rotated_frame,
                 [M * (b**2 / 18 + y_c**2) * sp.cos(beta) ** 2 + M * (a**2 / 18 + x_c**2) * sp.sin(beta) ** 2
                  - 2 * M * (x_c * y_c - a * b / 36) * sp.sin(beta) * sp.cos(beta),
                  M * (b**2 / 18 + y_c**2) * sp.sin(beta) ** 2 + M * (a**2 / 18 + x_c**2) * sp.cos(beta) ** 2
                  + 2 * M * (x_c * y_c - a * b / 36) * sp.sin(beta) * sp.cos(beta),
                  M * (x_c * y_c - a * b / 36) * sp.cos(2 * beta) + M * (b**2 / 18 + y_c**2) * sp.sin(beta) * sp.cos(beta)
                  - M * (a**2 / 18 + x_c**2) * sp.sin(beta) * sp.cos(beta),
                  M * (a**2 + b**2) / 18 + M * (x_c**2 + y_c**2)]),
    ],
)
