"""Wells, Sec. 7.9 — lamina spinning at constant ω about an axis in its plane: the couple from I_xy."""

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia

M, omega, Ix, Iy, Ixy, r_bar, y_bar = parameters("M omega Ibar_x Ibar_y Ibar_xy rbar ybar")
central = Inertia(Ix, Iy, Ix + Iy, Ixy)  # lamina in the XY plane, about its c.m.
at_axis = central.from_centre(M, (-r_bar, -y_bar, 0))  # c.m. at (r̄, ȳ) from O on the spin axis


def _couple(_):
    # each element carries ω² x dm along X; its moment about O (arm y) sums to ω² Σ m x y = ω² I_xy
    return omega**2 * at_axis.I_xy


PROBLEM = Problem(
    id="sec7.9",
    title="Spinning lamina: the bearing couple ω² I_xy by the parallel-axis theorem",
    chapter=7,
    source="Wells, Sec. 7.9",
    system=None,
    answers=[Quantity("couple τ_z", _couple, omega**2 * Ixy + omega**2 * M * r_bar * y_bar)],
    correction="Only the couple is checked: the bearing forces F1, F2 depend on the figure's sign choices.",
)
