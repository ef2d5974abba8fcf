"""Wells, Problem 7.13 — principal moments and direction of a lamina."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia, plane_rotation

I_x, I_y, I_xy = parameters("I_x I_y I_xy")
I_z = I_x + I_y  # lamina in the XY plane
lamina = Inertia(I_x, I_y, I_z, I_xy)
root = sp.sqrt(I_z**2 - 4 * (I_x * I_y - I_xy**2))
I_1 = (I_z + root) / 2
I_2 = (I_z - root) / 2


def _symmetric(values):
    v1, v2, v3 = values
    return [v1 + v2 + v3, v1 * v2 + v1 * v3 + v2 * v3, v1 * v2 * v3]


def _rotated_product(tan_theta):
    return lambda _: lamina.rotated(plane_rotation(sp.atan(tan_theta))).I_xy


PROBLEM = Problem(
    id="p7.13",
    title="Lamina: principal moments I_{1,2} = ½[I_z ± √(I_z² - 4(I_x I_y - I_xy²))] and their direction",
    chapter=7,
    source="Wells, Problem 7.13",
    system=None,
    answers=[
        Quantity("principal moments (symmetric functions)", lambda _: _symmetric(lamina.principal()),
                 _symmetric([I_1, I_2, I_z])),
        Quantity("product of inertia in axes at tanθ = I_xy/(I_y - I_1)", _rotated_product(I_xy / (I_y - I_1)), 0),
        Quantity("product of inertia in axes at tanθ = (I_x - I_1)/I_xy", _rotated_product((I_x - I_1) / I_xy), 0),
    ],
)
