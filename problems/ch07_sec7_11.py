"""Wells, Sec. 7.11 — product of inertia from the measured moment about a line at 45° in the XY plane."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia

Ix, Iy, Iz, I_op1 = parameters("Ibar_x Ibar_y Ibar_z I_Op1")
Ixy = sp.Symbol("Ibar_xy", real=True)


def _product(_):
    moment = Inertia(Ix, Iy, Iz, Ixy).about_line(1 / sp.sqrt(2), 1 / sp.sqrt(2), 0)
    (solution,) = sp.solve(sp.Eq(moment, I_op1), Ixy)
    return solution


PROBLEM = Problem(
    id="sec7.11",
    title="Experimental inertia: Ī_xy from the moment about a line at 45° (torsion pendulum)",
    chapter=7,
    source="Wells, Sec. 7.11",
    system=None,
    answers=[Quantity("Ī_xy", _product, (Ix + Iy) / 2 - I_op1)],
    correction="The period relation Ī_z = P²c/(4π²) - I_f of the same section is not an inertia computation "
               "and is not checked here.",
)
