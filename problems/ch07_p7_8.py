"""Wells, Problem 7.8 — the moment of inertia of a body about the line through two points p1, p2 (coordinates
relative to the centre of mass), in centre-of-mass quantities: (7.14) with the direction cosines
(l, m, n) = (p2 − p1)/|p2 − p1| and the line passing through p1,

I = Ī_x l² + Ī_y m² + Ī_z n² − 2Ī_xy lm − 2Ī_xz ln − 2Ī_yz mn + M[(x1² + y1² + z1²) − (l x1 + m y1 + n z1)²].
"""

import sympy as sp

from lagrange import Inertia, parameters
from lagrange.corpus import Problem, Quantity

M, Ix, Iy, Iz, Ixy, Ixz, Iyz = parameters("M Ibar_x Ibar_y Ibar_z Ibar_xy Ibar_xz Ibar_yz")
x1, y1, z1, x2, y2, z2 = sp.symbols("x1 y1 z1 x2 y2 z2", real=True)
central = Inertia(Ix, Iy, Iz, I_xy=Ixy, I_xz=Ixz, I_yz=Iyz)

d = sp.Matrix([x2 - x1, y2 - y1, z2 - z1])
l, m, n = d / sp.sqrt(d.dot(d))
book = (Ix * l**2 + Iy * m**2 + Iz * n**2 - 2 * Ixy * l * m - 2 * Ixz * l * n - 2 * Iyz * m * n
        + M * ((x1**2 + y1**2 + z1**2) - (l * x1 + m * y1 + n * z1) ** 2))

PROBLEM = Problem(
    id="p7.8",
    title="Moment of inertia about the line through two points, in centre-of-mass quantities (7.14)",
    chapter=7,
    source="Wells, Problem 7.8",
    system=None,
    answers=[Quantity("I about the line p1 p2 (parallel axes to p1, then the direction p2 − p1)",
                      lambda _: central.from_centre(M, (x1, y1, z1)).about_direction(*d), book)],
    ranges={"Ibar_xy": (0.1, 0.3), "Ibar_xz": (0.1, 0.3), "Ibar_yz": (0.1, 0.3)},  # a positive-definite tensor
    correction="The catalog gives the printed formula as (7.14) with the normalized difference as direction; it "
    "is written out here for a body with products of inertia (Wells' signs: products enter with −2).",
)
