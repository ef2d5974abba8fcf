"""Wells, Problem 7.16 — solid hemisphere (Fig. 7-19): the spherical points of inertia on its axis."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import spherical_points
from lagrange.model.standard_bodies import hemisphere

M, R = parameters("M R")
central = hemisphere(M, R)  # axis Z, dome towards +Z, c.m. 3R/8 above the flat face
s = spherical_points(M, central, "z")
at_O = central.from_centre(M, (0, 0, -s))  # the spherical point below the c.m.
at_p1 = central.from_centre(M, (0, 0, s))

PROBLEM = Problem(
    id="p7.16",
    title="Hemisphere: O (centre of the flat face) and p1 on the axis are spherical points",
    chapter=7,
    source="Wells, Problem 7.16 (Fig. 7-19)",
    system=None,
    answers=[
        Quantity("distance from the c.m. to the spherical points (O is 3R/8 below)", lambda _: s,
                 sp.Rational(3, 8) * R),
        Quantity("moments at O (all equal: a spherical point)", lambda _: [at_O.I_x, at_O.I_y, at_O.I_z],
                 [sp.Rational(2, 5) * M * R**2] * 3),
        Quantity("moments at p1", lambda _: [at_p1.I_x, at_p1.I_y, at_p1.I_z], [sp.Rational(2, 5) * M * R**2] * 3),
    ],
    correction="The book states that O and p1 are spherical points; the numbers (I = 2MR²/5, p1 on the axis "
               "3R/4 from O, i.e. 3R/8 beyond the c.m.) are derived in the catalog, not printed.",
)
