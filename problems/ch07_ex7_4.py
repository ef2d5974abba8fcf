"""Wells, Example 7.4 — block 2a×2b×2c: c.m. values, values at a corner, moment about a line through (10, 9, 13)."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import block

M, a, b, c = parameters("M a b c")
central = block(M, a, b, c)
corner = central.from_centre(M, (-a, -b, -c))  # O at a corner; the block fills the positive octant

PROBLEM = Problem(
    id="ex7.4",
    title="Block 2a×2b×2c: inertia at the c.m. and at a corner, moment about the line O → (10, 9, 13)",
    chapter=7,
    source="Wells, Example 7.4",
    system=None,
    answers=[
        Quantity("(Ī_x, Ī_y, Ī_z)", lambda _: [central.I_x, central.I_y, central.I_z],
                 [M * (b**2 + c**2) / 3, M * (a**2 + c**2) / 3, M * (a**2 + b**2) / 3]),
        Quantity("(I_x, I_y, I_z, I_xy, I_xz, I_yz) at the corner",
                 lambda _: [corner.I_x, corner.I_y, corner.I_z, corner.I_xy, corner.I_xz, corner.I_yz],
                 [4 * M * (b**2 + c**2) / 3, 4 * M * (a**2 + c**2) / 3, 4 * M * (a**2 + b**2) / 3,
                  M * a * b, M * a * c, M * b * c]),
        Quantity("I_Oa, line through (10, 9, 13)", lambda _: corner.about_direction(10, 9, 13),
                 sp.Rational(1, 350) * (sp.Rational(4, 3) * M * (b**2 + c**2) * 100
                                        + sp.Rational(4, 3) * M * (a**2 + c**2) * 81
                                        + sp.Rational(4, 3) * M * (a**2 + b**2) * 169
                                        - 2 * M * a * b * 90 - 2 * M * a * c * 130 - 2 * M * b * c * 117)),
    ],
    correction="The last term of I_Oa is printed 2Mab×117; it is 2Mbc×117 (the yz product with y·z = 9·13 = 117).",
)
