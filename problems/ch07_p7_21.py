"""Wells, Problem 7.21 — moments and product of a lamina in axes turned by θ in its plane."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia, plane_rotation

Ix1, Iy1, theta = parameters("Ibar_x1 Ibar_y1 theta")
Ixy1 = sp.Symbol("Ibar_x1y1", real=True)
c, s = sp.cos(theta), sp.sin(theta)


def _turned(_):
    J = Inertia(Ix1, Iy1, Ix1 + Iy1, Ixy1).rotated(plane_rotation(theta))
    return [J.I_x, J.I_y, J.I_xy]


PROBLEM = Problem(
    id="p7.21",
    title="Rotation of axes in the plane (Wells 7.18-7.19 for a lamina)",
    chapter=7,
    source="Wells, Problem 7.21",
    system=None,
    answers=[Quantity("(Ī_x2, Ī_y2, Ī_x2y2)", _turned,
                      [Ix1 * c**2 + Iy1 * s**2 - 2 * Ixy1 * s * c,
                       Ix1 * s**2 + Iy1 * c**2 + 2 * Ixy1 * s * c,
                       Ixy1 * (c**2 - s**2) + (Ix1 - Iy1) * s * c])],
)
