"""Wells, Problem 7.6 — thin disk: moments about an inclined line and about lines through a displaced point."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import disk

M, R, theta, s, y_bar = parameters("M R theta s ybar")
l, m, n = sp.symbols("l m n", real=True)
central = disk(M, R)  # axis Z

PROBLEM = Problem(
    id="p7.6",
    title="Disk: moment about a line at θ to the axis, and about lines through O1 displaced along Y",
    chapter=7,
    source="Wells, Problem 7.6",
    system=None,
    answers=[
        Quantity("(a) I_bc, line at θ to the axis crossing it at s from the c.m.",
                 lambda _: central.from_centre(M, (0, 0, s)).about_line(sp.sin(theta), 0, sp.cos(theta)),
                 M * R**2 / 2 * sp.cos(theta) ** 2 + (M * R**2 / 4 + M * s**2) * sp.sin(theta) ** 2),
        Quantity("(b) line (l, m, n) through O1 at ȳ on Y",
                 lambda _: central.from_centre(M, (0, y_bar, 0)).about_line(l, m, n),
                 (M * R**2 / 4 + M * y_bar**2) * l**2 + M * R**2 / 4 * m**2 + (M * R**2 / 2 + M * y_bar**2) * n**2),
    ],
    correction="(a) The OCR prints ½Mr² cosθ; the moment about the axis enters with cos²θ (7.2), so ½MR² cos²θ. "
               "The geometry of line bc (crossing the axis at s from the c.m.) is inferred in the catalog.",
)
