"""Wells, Example 7.8 — triangle spinning about its Y leg at constant ω: bearing forces at O and O2."""

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import triangle_plate

M, a, b, omega = parameters("M a b omega")
corner = triangle_plate(M, a, b)  # about O, the right-angle corner; the spin axis is the Y leg
x_bar = a / 3  # c.m. distance from the spin axis


def _bearings(_):
    # centrifugal load ω² x dm on each element; its moment about O is ω² Σ m x y = ω² I_xy (Sec. 7.9)
    F2 = omega**2 * corner.I_xy / b  # bearing O2 at y = b balances the moment
    F1 = omega**2 * M * x_bar - F2  # bearing O takes the rest of the resultant
    return [F1, F2]


PROBLEM = Problem(
    id="ex7.8",
    title="Triangle spinning about its Y leg: bearing forces from the product of inertia",
    chapter=7,
    source="Wells, Example 7.8 (Sec. 7.9)",
    system=None,
    answers=[Quantity("(F1 at O, F2 at O2) magnitudes", _bearings, [omega**2 * M * a / 4, omega**2 * M * a / 12])],
    correction="An intermediate step prints (2/3)Mab; it should be (2/9)Mab. The final answers are right.",
)
