"""Wells, Problem 12.8 — bar (length 2l, mass M_1) with its upper end sliding on a smooth vertical wall and its
lower end pinned to the centre of a disk (M_2, I_2, radius r) rolling without slipping on the floor (Fig. 12-9):
the wall's reaction f_x, with the bar's distance from the wall as a superfluous coordinate."""

import sympy as sp

from lagrange import Holonomic, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

th, u = coordinates("theta u")
M1, M2, I2, l, r, g = parameters("M_1 M_2 I_2 l r g")

# X horizontal away from the wall, Y up. theta: bar angle from the vertical wall. u: X of the bar's upper end
# (u = 0 against the wall; freed). Bar c.m. at (u + l sin(theta), r + l cos(theta)), moment of inertia
# M_1 l^2/3 about it; disk centre at X = u + 2 l sin(theta); rolling: disk angle = X/r.
# Rigid bodies given through T directly.
xc, yc = u + l * sp.sin(th), r + l * sp.cos(th)
xd = u + 2 * l * sp.sin(th)
T = (sp.Rational(1, 2) * M1 * (xc.diff(t) ** 2 + yc.diff(t) ** 2) + sp.Rational(1, 2) * M1 * l**2 / 3 * th.diff(t) ** 2
     + sp.Rational(1, 2) * M2 * xd.diff(t) ** 2 + sp.Rational(1, 2) * I2 * (xd.diff(t) / r) ** 2)
system = System(
    [th, u],
    T=T,
    V=M1 * g * yc,
    constraints=[Holonomic(u, name="wall")],
    name="bar on a smooth wall and a rolling disk, wall distance freed",
)

PARAMS = {M1: 1.0, M2: 0.8, I2: 0.1, l: 0.5, r: 0.25, g: 9.81}
INIT = {th: 0.2, u: 0.0, th.diff(t): 0.0, u.diff(t): 0.0}

PROBLEM = Problem(
    id="p12.8",
    title="Bar on a smooth wall, lower end on a rolling disk: wall reaction f_x",
    chapter=12,
    source="Wells, Problem 12.8 (Fig. 12-9)",
    system=system,
    answers=[
        # phi = u, A = 1: lambda = generalized force on u = the wall's horizontal push f_x on the bar (distorting u,
        # the rolling contact and the smooth floor do no work). Book: f_x = (M1 + 2 M2 + 2 I2/r^2)(l thdd cos - l thd^2 sin)
        ConstraintForce("wall", (M1 + 2 * M2 + 2 * I2 / r**2) * (l * th.diff(t, 2) * sp.cos(th)
                                                                 - l * th.diff(t) ** 2 * sp.sin(th)),
                        PARAMS, INIT, 0.6, description="f_x"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=0.6),
    correction="Geometry inferred (figure not in the text): bar c.m. at x = l sin(theta), disk centre at "
               "x = 2 l sin(theta). The bar's own moment of inertia does not enter f_x; M_1 l^2/3 is used.",
)
