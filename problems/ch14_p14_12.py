"""Wells, Problem 14.12 — a sphere on a 10 m string in viscous oil at latitude 45 deg comes to rest along the
plumb line g' rather than along the true gravity g: its displacement (south) is l tan(alpha), about 1.7 cm.

alpha from the library's EarthFrame.true_gravity (14.11) with Table 14.1's g' and R at 45 deg.
"""

import math

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.frames import EarthFrame

L_CM = 1000.0
E = EarthFrame(sp.Float(math.pi / 4, 30), sp.Float(7.29211e-5, 30), sp.Float(6.389135e8, 30))


def _offset(_):
    g = E.true_gravity(sp.Float(980.629, 30))  # (east, north, up)
    return L_CM * g[1] / -g[2]  # l tan(alpha), toward the south relative to the true-gravity line


PROBLEM = Problem(
    id="p14.12",
    title="Pendulum in viscous oil at 45 deg rests along g', about 1.7 cm from the true-gravity line",
    chapter=14,
    source="Wells, Problem 14.12",
    system=None,
    answers=[Quantity("l tan(alpha) (cm)", _offset, 1.7, rtol=2.5e-2)],
    units="cgs",
    correction="The book rounds to 1.7 cm (catalog: 1.729 cm); compared at rtol 2.5e-2 for the two-figure rounding.",
)
