"""Wells, Example 7.3 — lamina (ρ = 2 g/cm²): principal moments and direction from the c.m. values."""

import math

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia

R = sp.Rational
lamina = Inertia(16100, 26200, 42300, I_xy=-10360)  # Ī_x, Ī_y, Ī_z, Ī_xy (g·cm²), Wells' positive-sum products


def _angle_deg(_):
    moments, axes = lamina.principal_axes_numeric()
    l, m, _n = axes[1]  # axis of the middle moment, 3.26e4
    return sp.Float(math.degrees(math.atan2(m, l)) % 180.0)


PROBLEM = Problem(
    id="ex7.3",
    title="Lamina: principal moments and principal direction",
    chapter=7,
    source="Wells, Example 7.3 (and Prob. 7.11)",
    system=None,
    answers=[
        Quantity("principal moments, ascending", lambda _: lamina.principal(),
                 [R("0.97e4"), R("3.26e4"), R("4.23e4")], rtol=1e-2),
        Quantity("angle θ of the 3.26e4 axis from X (degrees)", _angle_deg, 58, rtol=1e-2),
    ],
    units="g, cm, g·cm², degrees",
    correction="The book rounds to 3 digits (exact 0.9625e4, 3.2675e4; θ = 57.99°), so rtol 1e-2.",
)
