"""Wells, Problem 7.19 — direction of the principal axes at a point in a principal plane."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia, plane_rotation

M, Ix, Iy, Iz, phi = parameters("M Ibar_xp Ibar_yp Ibar_zp phi")
x_bar, y_bar = sp.symbols("xbar ybar", real=True)
at_point = Inertia(Ix, Iy, Iz).from_centre(M, (x_bar, y_bar, 0))


def _tan_2phi(_):
    # the product in axes turned by φ is A cos2φ + B sin2φ; it vanishes at tan2φ = -A/B
    product = at_point.rotated(plane_rotation(phi)).I_xy
    A, B = product.subs(phi, 0), product.subs(phi, sp.pi / 4)
    return -A / B


PROBLEM = Problem(
    id="p7.19",
    title="Principal directions at (x̄, ȳ) in the principal plane X̄Ȳ",
    chapter=7,
    source="Wells, Problem 7.19",
    system=None,
    answers=[Quantity("tan 2φ", _tan_2phi, 2 * M * x_bar * y_bar / ((Iy + M * x_bar**2) - (Ix + M * y_bar**2)))],
)
