"""Wells, Section 12.1C — bead on a smooth parabolic wire y = b x² (Y vertical) with gravity and an
applied force F = (F_x, F_y): the reaction f of the wire, by superfluous coordinates (multipliers)."""

import sympy as sp

from lagrange import Force, Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Simulation

x, y = coordinates("x y")
r, th = coordinates("r theta")
m, g, b, Fx, Fy = parameters("m g b F_x F_y")

# F_x large enough to keep the bead on the x > 0 branch (polar coordinates are singular at the vertex r = 0)
PARAMS = {m: 1.0, g: 9.81, b: 0.5, Fx: 6.0, Fy: 1.3}
NOTE = ("Engine sign: the multiplier term A^T lambda is added to the applied forces, so (A^T lambda)_q is Wells' "
        "generalized force of constraint on q; for Cartesian x, y that is the reaction component f_x, f_y itself, "
        "for polar r, theta it is f_r and r f_theta.")

# (a) Cartesian x, y with y superfluous: the wire y = b x^2 is the constraint; gravity through V = m g y.
cartesian = System(
    [x, y],
    bodies=[Particle(m, (x, y), name="bead")],
    V=m * g * y,
    forces=[Force(at=(x, y, 0), vector=(Fx, Fy, 0))],
    constraints=[Holonomic(y - b * x**2, name="wire")],
    name="bead on a parabolic wire (x, y free)",
)
INIT_XY = {x: 0.8, y: 0.32, x.diff(t): -0.4, y.diff(t): -0.32}

# (b) polar r, theta with one superfluous coordinate: the wire is r sin(theta) = b r^2 cos^2(theta).
F_r = Fx * sp.cos(th) + Fy * sp.sin(th)
F_th = -Fx * sp.sin(th) + Fy * sp.cos(th)
polar = System(
    [r, th],
    bodies=[Particle(m, (r * sp.cos(th), r * sp.sin(th)), name="bead")],
    V=m * g * r * sp.sin(th),
    forces=[Force(at=(r * sp.cos(th), r * sp.sin(th), 0), vector=(Fx, Fy, 0))],
    constraints=[Holonomic(r * sp.sin(th) - b * r**2 * sp.cos(th) ** 2, name="wire")],
    name="bead on a parabolic wire (polar r, theta)",
)
# same state as INIT_XY: x = 0.8, y = 0.32, xdot = -0.4, ydot = -0.32
_r0, _th0 = float(sp.sqrt(0.8**2 + 0.32**2)), float(sp.atan2(0.32, 0.8))
INIT_POLAR = {r: _r0, th: _th0,
              r.diff(t): (0.8 * -0.4 + 0.32 * -0.32) / _r0,
              th.diff(t): (0.8 * -0.32 - 0.32 * -0.4) / _r0**2}

reduced = eliminate(cartesian, {y: b * x**2})

PROBLEMS = [
    Problem(
        id="sec12.1C",
        title="Bead on a smooth parabolic wire y = b x^2 with gravity and applied F: Newton reactions f_x, f_y",
        chapter=12,
        source="Wells, Section 12.1C, eqs. (1)-(2) (Fig. 12-1)",
        system=cartesian,
        answers=[
            # Book: m xdd = F_x + f_x,  m ydd = F_y + f_y - m g.  (A^T lambda)_x = f_x, (A^T lambda)_y = f_y.
            ConstraintForce("wire", m * x.diff(t, 2) - Fx, PARAMS, INIT_XY, 2.0, coordinate=x,
                            description="f_x = m xdd - F_x"),
            ConstraintForce("wire", m * y.diff(t, 2) - Fy + m * g, PARAMS, INIT_XY, 2.0, coordinate=y,
                            description="f_y = m ydd - F_y + m g"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT_XY, t_end=5),
        correction=NOTE,
    ),
    Problem(
        id="sec12.1C-polar",
        title="Bead on y = b x^2 in polar coordinates r, theta (one superfluous): f_r and f_theta",
        chapter=12,
        source="Wells, Section 12.1C, eqs. (9)-(10)",
        system=polar,
        answers=[
            # Book (9): m rdd - m r thd^2 = f_r - m g sin(theta) + F_r      -> (A^T lambda)_r = f_r
            ConstraintForce("wire", m * r.diff(t, 2) - m * r * th.diff(t) ** 2 + m * g * sp.sin(th) - F_r,
                            PARAMS, INIT_POLAR, 2.0, coordinate=r, description="f_r (eq. 9)"),
            # Book (10), corrected: m r^2 thdd + 2 m r rd thd = r f_th - m g r cos(theta) + r F_th
            #                                                    -> (A^T lambda)_theta = r f_theta
            ConstraintForce("wire", m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t)
                            + m * g * r * sp.cos(th) - r * F_th,
                            PARAMS, INIT_POLAR, 2.0, coordinate=th, description="r f_theta (eq. 10)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT_POLAR, t_end=5),
        correction=("Book eq. (10) prints m r^2 thdd + 2 m r rd thd = f_theta - m g r cos(theta) + F_theta, omitting "
                    "the factor r on the right: the generalized force on theta is F.dr/dtheta = r F_theta "
                    "(dimensions: the left side is a torque). Corrected form used. " + NOTE),
    ),
    Problem(
        id="sec12.1C-reduced",
        title="Bead on y = b x^2 with gravity and applied F: equation of motion after eliminating y",
        chapter=12,
        source="Wells, Section 12.1C, eq. (3)",
        system=reduced,
        answers=[
            EquationsOfMotion(
                [sp.Eq(m * x.diff(t, 2) * (1 + 4 * b**2 * x**2) + 4 * m * b**2 * x * x.diff(t) ** 2,
                       -2 * m * g * b * x + Fx + 2 * b * x * Fy)],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params=PARAMS, initial={x: 0.8, x.diff(t): -0.4}, t_end=5),
    ),
]
