"""Wells, Example 13.2 — dumbbell in a vertical plane: actuator forces f_x1, f_y1 on m1 and f_y2 on m2."""

import sympy as sp

from lagrange import System, actuator_forces, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x, y, theta = coordinates("x y theta")
M, I, l1, l2, g = parameters("M I l_1 l_2 g")
fx1, fy1, fy2 = sp.symbols("f_x1 f_y1 f_y2", real=True)
system = System([x, y, theta], T=M * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2 + I * theta.diff(t) ** 2 / 2,
                V=M * g * y, name="dumbbell in a vertical plane")

# m1 at c.m. − l1(cosθ, sinθ), m2 at c.m. + l2(cosθ, sinθ)
vw = fx1 * delta(x - l1 * sp.cos(theta)) + fy1 * delta(y - l1 * sp.sin(theta)) + fy2 * delta(y + l2 * sp.sin(theta))


def _forces(s):
    f = actuator_forces(s, vw, [fx1, fy1, fy2])
    return [f[fx1], f[fy1], f[fy2]]


xdd, ydd, thdd = x.diff(t, 2), y.diff(t, 2), theta.diff(t, 2)
den = (l1 + l2) * sp.cos(theta)
PROBLEM = Problem(
    id="ex13.2",
    title="Dumbbell in a vertical plane: actuator forces for a prescribed motion",
    chapter=13,
    source="Wells, Example 13.2",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(M * xdd, 0), sp.Eq(M * ydd + M * g, 0), sp.Eq(I * thdd, 0)], per_equation=True),
        Quantity("f_x1, f_y1, f_y2", _forces, [
            M * xdd,
            (M * (ydd + g) * l2 * sp.cos(theta) - I * thdd + M * xdd * l1 * sp.sin(theta)) / den,
            (M * (ydd + g) * l1 * sp.cos(theta) + I * thdd - M * xdd * l1 * sp.sin(theta)) / den]),
    ],
    simulation=Simulation(params={M: 2, I: 0.5, g: 9.81},
                          initial={x: 0, y: 0, theta: 0.3, x.diff(t): 1, y.diff(t): 3, theta.diff(t): 2}, t_end=1),
)
