"""Wells, Example 8.5 — lamina moving freely in the X1Y1 plane; forces f1, f2 at body points.

Coordinates x, y (inertial position of a body point O) and θ (body X from X1). The c.m. is at (x̄, ȳ) along the
body axes; I_z is about O. Forces f1 at body point (a1, b1), f2 at (a2, b2): given by their inertial components
(F1X, F1Y), (F2X, F2Y); their body-axis components are f_ix = F_iX cθ + F_iY sθ, f_iy = −F_iX sθ + F_iY cθ.
(c) with O at the c.m.
"""

import sympy as sp

from lagrange import Force, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.rotations import rot_z

x, y, th = coordinates("x y theta")
M, Iz, xb, yb, Ic = parameters("M I_z xbar ybar Ibar_z")
a1, b1, a2, b2, F1X, F1Y, F2X, F2Y = parameters("a1 b1 a2 b2 F1X F1Y F2X F2Y")
xd, yd, thd = x.diff(t), y.diff(t), th.diff(t)
xdd, ydd, thdd = x.diff(t, 2), y.diff(t, 2), th.diff(t, 2)
c, s = sp.cos(th), sp.sin(th)

lamina = RigidBody(M, (0, 0, Iz), origin=(x, y, 0), orientation=rot_z(th), com=(xb, yb, 0), name="lamina")
forces = [Force(at=lamina.point((a1, b1, 0)), vector=(F1X, F1Y, 0)),
          Force(at=lamina.point((a2, b2, 0)), vector=(F2X, F2Y, 0))]
system = System([x, y, th], bodies=[lamina], forces=forces, name="free lamina in a plane")

f1x, f1y = F1X * c + F1Y * s, -F1X * s + F1Y * c
f2x, f2y = F2X * c + F2Y * s, -F2X * s + F2Y * c
F_th = f1y * a1 - f1x * b1 + f2y * a2 - f2x * b2


def theta_residual(sys_):
    e = sys_.equations()[2]
    return e.lhs - e.rhs


centred = System([x, y, th], bodies=[RigidBody(M, (0, 0, Ic), origin=(x, y, 0), orientation=rot_z(th))],
                 name="free lamina, origin at the c.m.")
SIM_PARAMS = {M: 1.0, Iz: 0.3, xb: 0.2, yb: 0.1, a1: 0.5, b1: 0.0, a2: 0.0, b2: 0.4,
              F1X: 0.0, F1Y: 1.0, F2X: -1.0, F2Y: 0.0}

PROBLEMS = [
    Problem(
        id="ex8.5",
        title="Free lamina in a plane, origin off the c.m.: T (8.10), theta equation, F_x, F_y, F_theta",
        chapter=8,
        source="Wells, Example 8.5 (a)",
        system=system,
        answers=[
            Quantity("v_0 along the body axes",
                     lambda s_: list(lamina.R.T * lamina.origin.diff(t))[:2], [xd * c + yd * s, yd * c - xd * s]),
            KineticEnergy(sp.Rational(1, 2) * M * (xd**2 + yd**2) + sp.Rational(1, 2) * Iz * thd**2
                          + M * thd * ((yd * xb - xd * yb) * c - (xd * xb + yd * yb) * s)),
            GeneralizedForces({x: F1X + F2X, y: F1Y + F2Y, th: F_th}),
            Quantity("theta equation (lhs - F_theta)", theta_residual,
                     Iz * thdd + M * ((ydd * xb - xdd * yb) * c - (xdd * xb + ydd * yb) * s) - F_th),
        ],
        simulation=Simulation(params=SIM_PARAMS, initial={x: 0.0, y: 0.0, th: 0.0, xd: 0.0, yd: 0.0, thd: 1.0},
                              t_end=3.0),
        correction="OCR prints the bars of xbar, ybar as dots. The book reuses f_x, f_y for F_x = f_1x + f_2x; for x, y "
        "inertial these are the inertial X1, Y1 components (F1X + F2X), while F_theta uses the body-axis components "
        "and body-axis application points (a_i, b_i).",
    ),
    Problem(
        id="ex8.5-c",
        title="Free lamina in a plane with the origin at the c.m.: T = 1/2 M(x'^2 + y'^2) + 1/2 Ibar_z theta'^2",
        chapter=8,
        source="Wells, Example 8.5 (c)",
        system=centred,
        answers=[KineticEnergy(sp.Rational(1, 2) * M * (xd**2 + yd**2) + sp.Rational(1, 2) * Ic * thd**2)],
        simulation=Simulation(params={M: 1.0, Ic: 0.3}, initial={x: 0.0, y: 0.0, th: 0.0, xd: 1.0, yd: 0.5, thd: 1.0},
                              t_end=3.0),
    ),
]
