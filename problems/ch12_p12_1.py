"""Wells, Problem 12.1 — bead on a smooth planar wire, described in polar coordinates r, theta: the Cartesian
reaction components f_x, f_y in terms of r, theta and their derivatives."""

import sympy as sp

from lagrange import Force, Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

x, y = coordinates("x y")
m, a, c, Fx, Fy = parameters("m a c F_x F_y")

# "Any" wire: a concrete one is needed to simulate; the limacon r = a + c cos(theta) (a > c) in the XY plane,
# written in x, y (r = sqrt(x^2 + y^2), cos(theta) = x/r): r^2 = a r + c x. Constant applied force (F_x, F_y)
# (gravity may be included in F_y). x, y are kept (one superfluous): the multiplier term on x, y,
# (A^T lambda)_x and (A^T lambda)_y, is the wire's reaction (f_x, f_y) itself (m xdd = F_x + f_x).
R = sp.sqrt(x**2 + y**2)
system = System(
    [x, y],
    bodies=[Particle(m, (x, y), name="bead")],
    forces=[Force(at=(x, y, 0), vector=(Fx, Fy, 0))],
    constraints=[Holonomic(x**2 + y**2 - a * R - c * x, name="wire")],
    name="bead on a planar wire (limacon)",
)

PARAMS = {m: 1.0, a: 1.0, c: 0.4, Fx: 0.5, Fy: -1.5}
_th0, _thd0 = 0.4, 1.3
_r0 = 1.0 + 0.4 * float(sp.cos(_th0))
_rd0 = -0.4 * float(sp.sin(_th0)) * _thd0
INIT = {x: _r0 * float(sp.cos(_th0)), y: _r0 * float(sp.sin(_th0)),
        x.diff(t): _rd0 * float(sp.cos(_th0)) - _r0 * _thd0 * float(sp.sin(_th0)),
        y.diff(t): _rd0 * float(sp.sin(_th0)) + _r0 * _thd0 * float(sp.cos(_th0))}

# The book's answers, in its polar symbols ...
rs, rd, rdd, c_th, s_th, thd, thdd = sp.symbols("r rdot rddot cos_theta sin_theta thetadot thetaddot")
book_fx = -Fx + m * (rdd - rs * thd**2) * c_th - m * (rs * thdd + 2 * rd * thd) * s_th
book_fy = -Fy + m * (rdd - rs * thd**2) * s_th + m * (rs * thdd + 2 * rd * thd) * c_th
# ... evaluated through the definitions of the polar coordinates: r = sqrt(x^2 + y^2), cos(theta) = x/r,
# sin(theta) = y/r, thetadot = (x yd - y xd)/r^2 (and their time derivatives).
THD = (x * y.diff(t) - y * x.diff(t)) / R**2
polar = {rs: R, rd: R.diff(t), rdd: R.diff(t, 2), c_th: x / R, s_th: y / R, thd: THD, thdd: THD.diff(t)}

PROBLEM = Problem(
    id="p12.1",
    title="Bead on a smooth planar wire in polar coordinates: f_x, f_y",
    chapter=12,
    source="Wells, Problem 12.1",
    system=system,
    answers=[
        ConstraintForce("wire", book_fx.subs(polar), PARAMS, INIT, 2.0, coordinate=x, description="f_x"),
        ConstraintForce("wire", book_fy.subs(polar), PARAMS, INIT, 2.0, coordinate=y, description="f_y"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=5),
    correction="The book's wire is arbitrary; a limacon r = a + c cos(theta) and a constant F are chosen to have "
               "a concrete motion (the formulas do not depend on that choice). The bead's Cartesian x, y are the "
               "system's coordinates, so the book's polar expressions are evaluated through r = sqrt(x^2 + y^2), "
               "theta = atan2(y, x) (keeping x, y and r, theta together as tied superfluous coordinates makes the "
               "mass matrix singular, which the simulator does not accept).",
)
