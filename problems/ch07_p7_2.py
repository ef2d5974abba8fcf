"""Wells, Problem 7.2 — thin right triangle: moment about the line from the corner through (4, 5, 7)."""

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.standard_bodies import triangle_plate

M, a, b = parameters("M a b")

PROBLEM = Problem(
    id="p7.2",
    title="Triangle: moment about the line O → (4, 5, 7)",
    chapter=7,
    source="Wells, Problem 7.2(b)",
    system=None,
    answers=[Quantity("I_Oa", lambda _: triangle_plate(M, a, b).about_direction(4, 5, 7),
                      M / (6 * 90) * (16 * b**2 + 25 * a**2 + 49 * (a**2 + b**2) - 20 * a * b))],
)
