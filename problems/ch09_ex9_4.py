"""Wells, Example 9.4 and Problem 9.6 — the rod of Ex. 8.7 (slender, mass M, pivoted at O on an arm of radius R
turning by θ1, swinging by θ2 in the arm's vertical plane) by Euler's method.

(1), which Problem 9.6 asks to derive from the transformation equations: the c.m. acceleration along the body
axes (X = −arm normal, Y along the rod, Z = X × Y; ȳ the c.m. distance from O),
A_x = −(R + ȳ sθ2) θ̈1 − 2θ̇1θ̇2 ȳ cθ2,  A_y = −(R + ȳ sθ2) θ̇1² sθ2 − θ̇2² ȳ,  A_z = (R + ȳ sθ2) θ̇1² cθ2 − θ̈2 ȳ;
and the first of (3), the same as Lagrange's θ2 equation:
I_x θ̈2 − I_z θ̇1² sθ2 cθ2 − M ȳ R θ̇1² cθ2 + M g ȳ sθ2 = 0.
"""

import sympy as sp
from lagrange_problems import ch08_ex8_7 as ex8_7
from lagrange_problems._common import variant

from lagrange import t
from lagrange.corpus import Quantity
from lagrange.model.coordinates import to_symbols

th1, th2, M, R, g, L = ex8_7.th1, ex8_7.th2, ex8_7.M, ex8_7.R, ex8_7.g, ex8_7.L
rod, Ix, Iz, yb = ex8_7.rod, ex8_7.Ix, ex8_7.Iz, ex8_7.yb
t1d, t2d, t1dd, t2dd = th1.diff(t), th2.diff(t), th1.diff(t, 2), th2.diff(t, 2)
s2, c2 = sp.sin(th2), sp.cos(th2)

A_book = [-(R + yb * s2) * t1dd - 2 * t1d * t2d * yb * c2,
          -(R + yb * s2) * t1d**2 * s2 - t2d**2 * yb,
          (R + yb * s2) * t1d**2 * c2 - t2dd * yb]
theta2_book = Ix * t2dd - Iz * t1d**2 * s2 * c2 - M * yb * R * t1d**2 * c2 + M * g * yb * s2


def _acceleration_body(_s):
    """Second time derivative of the c.m.'s inertial position (the transformation equations), along the body axes."""
    return list(rod.R.T * rod.centre_of_mass.diff(t, 2))


def _theta2_equation(s):
    """Row θ2 of the derived M q̈ − f (Lagrange's equation, unscaled)."""
    eqs = s.derived
    qdd = sp.Matrix(eqs.qdd)
    return (eqs.mass_matrix.row(1) * qdd)[0] - eqs.forcing[1]


base = ex8_7.PROBLEMS[0]
PROBLEMS = [
    variant(base, id="ex9.4", title="Rod on a rotating arm by Euler's method: c.m. acceleration (1) and the θ2 "
            "equation (3)", chapter=9, source="Wells, Example 9.4, eqs. (1), (3); Problem 9.6",
            answers=[Quantity("c.m. acceleration along the body axes (1)", _acceleration_body, A_book),
                     Quantity("θ2 equation, first of (3)", _theta2_equation, to_symbols(theta2_book, [th1, th2]))],
            correction="The OCR prints ȳ = ⅓L and a_0x = −Rθ̇1²; a uniform rod has ȳ = L/2 and (1) needs −Rθ̈1 "
            "(catalog). Axes as rebuilt for Ex. 8.7 (Z1 down, so V = −M g ȳ cθ2)."),
]
