"""Wells, Problem 14.1 — the geocentric radius R1 and the plumb-line gravity g' at geographic latitude 45 deg.

R1 is the distance from the earth's centre to the surface point of the international (1924) ellipsoid at
geographic latitude Phi (14.1 with the geocentric latitude of 14.6), g' the international gravity formula (14.9).
Both come from the library (:data:`lagrange.WELLS_1924`, :func:`lagrange.apparent_gravity`), not from the
printed formulas, and are compared with the book's answer (which agrees with Table 14.1).
"""

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import WELLS_1924, apparent_gravity

PHI = sp.pi / 4

PROBLEM = Problem(
    id="p14.1",
    title="R1 and g' at 45 deg latitude on the international ellipsoid: 6,367,695 m and 980.629 gal",
    chapter=14,
    source="Wells, Problem 14.1, eqs. (14.1)-(14.9)",
    system=None,
    answers=[
        # printed to the metre: rtol 1e-7 is 0.64 m at 6.4e6 m
        Quantity("R1 at 45 deg (m)", lambda _: WELLS_1924.geocentric_radius(PHI), 6_367_695, rtol=1e-7),
        # printed to 0.001 gal: rtol 1e-6 is 0.001 gal
        Quantity("g' at 45 deg (gal)", lambda _: 100 * apparent_gravity(PHI), sp.Rational("980.629"), rtol=1e-6),
    ],
    units="m, gal (cm/s^2)",
)
