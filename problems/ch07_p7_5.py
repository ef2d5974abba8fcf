"""Wells, Problem 7.5 — solid cone: moment about a line at angle θ to the axis, through the base centre and the c.m."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import cone

M, r, h, theta = parameters("M r h theta")
central = cone(M, r, h)
direction = (sp.sin(theta), 0, sp.cos(theta))  # in the XZ plane, θ from the cone's axis Z

PROBLEM = Problem(
    id="p7.5",
    title="Cone: moment about a line at θ to the axis through the base centre O and through the c.m.",
    chapter=7,
    source="Wells, Problem 7.5",
    system=None,
    answers=[
        Quantity("(a) I_Oa, O at the base centre", lambda _: central.from_centre(M, (0, 0, -h / 4)).about_line(*direction),
                 (M * h**2 / 16 + 3 * M * (4 * r**2 + h**2) / 80) * sp.sin(theta) ** 2
                 + 3 * M * r**2 / 10 * sp.cos(theta) ** 2),
        Quantity("(b) through the c.m.", lambda _: central.about_line(*direction),
                 3 * M * (4 * r**2 + h**2) / 80 * sp.sin(theta) ** 2 + 3 * M * r**2 / 10 * sp.cos(theta) ** 2),
    ],
)
