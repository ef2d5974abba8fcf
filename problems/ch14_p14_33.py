"""Wells, Problem 14.33 — the plumb-line deflection alpha in arc-minutes, the book's approximation (14.33)

    alpha [min] ~= (3437.75 / g) (3.392 + 1.14e-2 sin^2 Phi) sin Phi cos Phi      (g in gal),

against alpha of (14.12) computed by the library (:func:`lagrange.true_gravity_magnitude` on the 1924 ellipsoid,
with g' of (14.9) and R of (14.4)), at the latitudes of Table 14.1. The book's formula is evaluated with the
table's g; it drops terms of relative size ~1e-4, so the comparison is at rtol 3e-4 (0.002').
"""

import math

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import true_gravity_magnitude

G_TABLE = {30: 981.883, 45: 982.326, 60: 982.773}  # g (gal), Table 14.1
ARCMIN = 180 * 60 / sp.pi


def _book_alpha(deg: int) -> float:
    """The book's (14.33) at latitude ``deg`` with the table's g: the expected value."""
    s, c = math.sin(math.radians(deg)), math.cos(math.radians(deg))
    return 3437.75 / G_TABLE[deg] * (3.392 + 1.14e-2 * s * s) * s * c


def _alpha(deg: int):
    """alpha (arc-min) of (14.12) from the library's ellipsoidal earth."""
    return true_gravity_magnitude(sp.pi * deg / 180)[1] * ARCMIN


answers = [Quantity(f"alpha at {deg} deg (arc-min), (14.33)", lambda _, d=deg: _alpha(d), _book_alpha(deg),
                    rtol=3e-4) for deg in G_TABLE]
# the value the book quotes from (14.33) at 45 deg, printed to 0.001'
answers.append(Quantity("alpha at 45 deg (arc-min)", lambda _: _alpha(45), sp.Rational("5.945"), rtol=2e-4))

PROBLEM = Problem(
    id="p14.33",
    title="Plumb-line deflection alpha (arc-min): the approximation (14.33) against (14.12) on the ellipsoid",
    chapter=14,
    source="Wells, Problem 14.33, eq. (14.33), Table 14.1",
    system=None,
    answers=answers,
    units="arc-min (g in gal)",
)
