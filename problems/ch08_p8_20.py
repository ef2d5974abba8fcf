"""Wells, Problem 8.20 — lamina on a horizontal table turning with the prescribed angle α(t).

Coordinates relative to the table: x1, y1 and θ; the lamina origin O is at (r + x1, y1) along the table axes; c.m.
at (x̄, ȳ) along the lamina axes, I_z about O. α(t) = Ω t + A sin(w t) stands for a general prescribed motion.
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.rotations import rot_z

x1, y1, th = coordinates("x1 y1 theta")
M, Iz, xb, yb, r, Om, A, w = parameters("M I_z xbar ybar r Omega A w")
alpha = Om * t + A * sp.sin(w * t)
ad = alpha.diff(t)
x1d, y1d, thd = x1.diff(t), y1.diff(t), th.diff(t)

table = rot_z(alpha)
lamina = RigidBody(M, (0, 0, Iz), origin=table * sp.Matrix([r + x1, y1, 0]), orientation=rot_z(alpha + th),
                   com=(xb, yb, 0), name="lamina")
system = System([x1, y1, th], bodies=[lamina], name="lamina on a rotating table")

x2d = (x1d - y1 * ad) * sp.cos(alpha) - (y1d + ad * (r + x1)) * sp.sin(alpha)
y2d = (x1d - y1 * ad) * sp.sin(alpha) + (y1d + ad * (r + x1)) * sp.cos(alpha)

PROBLEM = Problem(
    id="p8.20",
    title="Lamina on a table turning with alpha(t): omega_z, v_0 and T (rheonomic)",
    chapter=8,
    source="Wells, Problem 8.20",
    system=system,
    answers=[
        Quantity("omega_z", lambda s: lamina.angular_velocity[2], thd + ad),
        Quantity("x2 dot (inertial X1 velocity of O)", lambda s: lamina.origin.diff(t)[0], x2d),
        Quantity("v_0 along the lamina axes", lambda s: list(lamina.R.T * lamina.origin.diff(t))[:2],
                 [x2d * sp.cos(th + alpha) + y2d * sp.sin(th + alpha), -x2d * sp.sin(th + alpha) + y2d * sp.cos(th + alpha)]),
        KineticEnergy(sp.Rational(1, 2) * M * ((x1d - y1 * ad) ** 2 + (y1d + ad * (r + x1)) ** 2)
                      + sp.Rational(1, 2) * Iz * (thd + ad) ** 2
                      + M * (thd + ad) * ((y1d + (r + x1) * ad) * (xb * sp.cos(th) - yb * sp.sin(th))
                                          - (x1d - y1 * ad) * (xb * sp.sin(th) + yb * sp.cos(th)))),
    ],
    simulation=Simulation(params={M: 1.0, Iz: 0.2, xb: 0.2, yb: 0.1, r: 0.5, Om: 1.0, A: 0.3, w: 2.0},
                          initial={x1: 0.1, y1: 0.0, th: 0.0, x1d: 0.0, y1d: 0.0, thd: 0.0}, t_end=3.0),
    correction="The OCR braces of T are garbled; the catalog's corrected form is used. y2 dot (not printed) is "
    "built the same way for v_0. alpha(t) is a concrete prescribed motion standing for the book's general alpha(t); "
    "T depends on t, so there is no energy check.",
)
