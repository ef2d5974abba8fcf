"""Wells, Problem 7.3 — moment about the line from O through the point (x, y, z)."""

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia

I_x, I_y, I_z, I_xy, I_xz, I_yz = sp.symbols("I_x I_y I_z I_xy I_xz I_yz", real=True)
x, y, z = sp.symbols("x y z", real=True)

PROBLEM = Problem(
    id="p7.3",
    title="Moment of inertia about the line through O and (x, y, z)",
    chapter=7,
    source="Wells, Problem 7.3",
    system=None,
    answers=[Quantity("I_Oa", lambda _: Inertia(I_x, I_y, I_z, I_xy, I_xz, I_yz).about_direction(x, y, z),
                      (I_x * x**2 + I_y * y**2 + I_z * z**2 - 2 * I_xy * x * y - 2 * I_xz * x * z
                       - 2 * I_yz * y * z) / (x**2 + y**2 + z**2))],
    correction="The OCR prints the last term as -I_yz yz; (7.2) with l = x/s etc. gives -2 I_yz yz.",
)
