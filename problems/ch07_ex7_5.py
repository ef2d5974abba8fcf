"""Wells, Example 7.5 — solid cone: c.m. values, axes at the base centre, axes at a base-rim point O2."""

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import cone

M, r, h = parameters("M r h")
central = cone(M, r, h)  # z from the base to the apex; c.m. h/4 above the base
base_centre = central.from_centre(M, (0, 0, -h / 4))
rim = central.from_centre(M, (0, r, -h / 4))  # O2 on the rim of the base, on the Y side
Ibar = 3 * M * (4 * r**2 + h**2) / 80

PROBLEM = Problem(
    id="ex7.5",
    title="Solid cone: inertia at the c.m., at the base centre and at a base-rim point",
    chapter=7,
    source="Wells, Example 7.5",
    system=None,
    answers=[
        Quantity("(Ī_x, Ī_y, Ī_z)", lambda _: [central.I_x, central.I_y, central.I_z],
                 [Ibar, Ibar, 3 * M * r**2 / 10]),
        Quantity("I_x about base-centre axes", lambda _: base_centre.I_x, Ibar + M * h**2 / 16),
        Quantity("(I_x, I_y, I_yz, I_xy) at the rim point O2",
                 lambda _: [rim.I_x, rim.I_y, rim.I_yz, rim.I_xy],
                 [Ibar + M * (r**2 + h**2 / 16), Ibar + M * h**2 / 16, -M * r * h / 4, 0]),
    ],
)
