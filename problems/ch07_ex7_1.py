"""Wells, Example 7.1 — three particles on a massless frame (Fig. 7-5): inertia at O, ellipsoid, c.m. values."""

import sympy as sp

from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import centre_of_mass, point_masses

# Masses in g, coordinates in cm. The figure's coordinates are reconstructed in the catalog from the
# printed sums; they reproduce every printed value and the printed c.m.
PARTICLES = [(100, (10, 12, 5)), (200, (-10, 8, 15)), (150, (-11, -14, 12))]
x, y, z = sp.symbols("x y z", real=True)
R = sp.Rational


def _at_o(_):
    J = point_masses(PARTICLES)
    return [J.I_x, J.I_y, J.I_z, J.I_xy, J.I_xz, J.I_yz]


def _central(_):
    mass, com = centre_of_mass(PARTICLES)
    J = point_masses(PARTICLES).to_centre(mass, com)
    return [J.I_z, J.I_xy]


PROBLEM = Problem(
    id="ex7.1",
    title="Three particles on a massless frame: moments and products at O, ellipsoid, c.m. values",
    chapter=7,
    source="Wells, Example 7.1 (Fig. 7-5)",
    system=None,
    answers=[
        Quantity("(I_x, I_y, I_z, I_xy, I_xz, I_yz) at O", _at_o,
                 [125700, 117250, 104750, 19100, -44800, 4800]),
        Quantity("ellipsoid of inertia at O (7.5)", lambda _: point_masses(PARTICLES).ellipsoid(x, y, z),
                 125700 * x**2 + 117250 * y**2 + 104750 * z**2 - 2 * 19100 * x * y + 2 * 44800 * x * z
                 - 2 * 4800 * y * z),
        Quantity("c.m. (x̄, ȳ)", lambda _: list(centre_of_mass(PARTICLES)[1][:2]), [R("-5.88"), R("1.56")],
                 rtol=5e-3),
        Quantity("(Ī_z, Ī_xy) by the parallel-axis theorem", _central,
                 [104750 - 450 * (R("5.88") ** 2 + R("1.56") ** 2), 19100 - 450 * (R("-5.88") * R("1.56"))],
                 rtol=1e-3),
    ],
    units="g, cm, g·cm²",
    correction="The book evaluates (d) with x̄, ȳ rounded to 3 digits (-5.88, 1.56; exact -5.889, 1.556), "
               "so (d) and the c.m. are compared to rtol 1e-3 and 5e-3. Particle coordinates are the "
               "catalog's reconstruction from the printed sums (the figure is not in the text).",
)
