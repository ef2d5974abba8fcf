"""Wells, Problem 9.13 — compound pendulum on a horizontal axis ab (body Y), bearings a, b at y = +s, -s.

Body origin O on the axis; c.m. (x_bar, y_bar, z_bar) and I_x, I_y, I_z, I_xy, I_xz, I_yz about O on body axes.
theta is measured from the downward vertical to body X: the body turns by theta about Y (rot_y) and the inertial
X1 axis points down, so gravity along body axes is M g (cos theta, 0, sin theta), as in the book's (1)-(6).
"""

import sympy as sp

from lagrange import Inertia, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation
from lagrange.derive.euler import euler_equations, support_loads
from lagrange.model.rotations import rot_y

th = coordinates("theta")
M, g, xb, yb, zb, Ix, Iy, Iz, Ixy, Ixz, Iyz = parameters("M g xbar ybar zbar I_x I_y I_z I_xy I_xz I_yz")
s, c = sp.sin(th), sp.cos(th)
thd, thdd = th.diff(t), th.diff(t, 2)

body = RigidBody(M, Inertia(Ix, Iy, Iz, I_xy=Ixy, I_xz=Ixz, I_yz=Iyz), orientation=rot_y(th), com=(xb, yb, zb),
                 name="compound pendulum")
gravity = (M * g, 0, 0)  # X1 points down
system = System([th], bodies=[body], V=-M * g * body.centre_of_mass[0], name="compound pendulum on bearings")

_TH = sp.Symbol("theta_s")


def _rest_tan(sys_):
    """tan(theta0) from dV/dtheta = 0."""
    dV = sp.diff(sys_.V, th).subs(th, _TH)
    root = sp.solve(dV, _TH)[0]
    return sp.tan(root)


def _omega_squared(sys_):
    """K/M at the stable rest angle theta0 = atan(zbar/xbar) (xbar, zbar > 0)."""
    th0 = sp.atan(zb / xb)
    K = sp.diff(sys_.V, th, 2).subs(th, th0)
    return K / sys_.mass_matrix[0, 0]


def _bearing_force_sum(_s):
    F, _tau = support_loads(body, gravity, frame="inertial")
    return list(body.R.T * F)


PROBLEM = Problem(
    id="p9.13",
    title="Compound pendulum on bearings: Euler's equations (1)-(6), rest angle tan(theta0) = zbar/xbar, omega^2",
    chapter=9,
    source="Wells, Problem 9.13",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(Iy * thdd, M * g * zb * c - M * g * xb * s)], per_equation=True),   # (5)
        # (1)-(3): f_ax + f_bx = M(thdd zbar - thd^2 xbar) - M g c, f_ay + f_by = 0, f_az + f_bz = -M(...) - M g s
        Quantity("bearing force sums (1)-(3)", _bearing_force_sum,
                 [M * (thdd * zb - thd**2 * xb) - M * g * c, 0, -M * (thdd * xb + thd**2 * zb) - M * g * s]),
        # (4), (6): left sides (moments about O along body X and Z), and (5)
        Quantity("Euler's equations (4), (5), (6), left sides", lambda _s: list(euler_equations(body)),
                 [-Ixy * thdd - Iyz * thd**2, Iy * thdd, Ixy * thd**2 - Iyz * thdd]),
        Quantity("rest angle tan(theta0)", _rest_tan, zb / xb),
        Quantity("small-oscillation omega^2", _omega_squared, M * g * sp.sqrt(xb**2 + zb**2) / Iy),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, xb: 0.3, zb: 0.1, Iy: 0.2},
                          initial={th: 0.8, thd: 0.0}, t_end=5),
    correction="OCR: (1) prints f_ay for f_ax; tan(theta0) prints zdot/xdot for zbar/xbar. omega^2 = M g "
    "(xbar^2 + zbar^2)^(1/2) / I_y is derived in the catalog (the book says 'integrate'). Bearing a at y = +s "
    "and b at y = -s, as implied by (4), (6).",
)
