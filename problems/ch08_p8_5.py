"""Wells, Problem 8.5 — the rod of Ex 8.7 (same system and axes as problems/ch08_ex8_7.py: Z1 down): body and space components
of ω and its direction cosines. Body: ω_x = −θ̇2, ω_y = θ̇1 cθ2, ω_z = θ̇1 sθ2 (Ex 9.4), ω² = θ̇1² + θ̇2²."""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation
from lagrange.model.rotations import rot_z

th1, th2 = coordinates("theta1 theta2")
M, L, R, g = parameters("M L R g")
t1d, t2d = th1.diff(t), th2.diff(t)
s2, c2 = sp.sin(th2), sp.cos(th2)
arm = rot_z(th1)
R_rod = arm * sp.Matrix([[0, s2, -c2], [-1, 0, 0], [0, c2, s2]])  # columns: body X, Y (rod), Z in arm axes
rod = RigidBody(M, (M * L**2 / 3, 0, M * L**2 / 3), origin=arm * sp.Matrix([R, 0, 0]), orientation=R_rod,
                com=(0, L / 2, 0), name="rod")
system = System([th1, th2], bodies=[rod], V=-M * g * rod.centre_of_mass[2], name="rod on a rotating arm")
w = sp.sqrt(t1d**2 + t2d**2)
W_BODY, W_SPACE = rod.angular_velocity, rod.space_angular_velocity

PROBLEM = Problem(
    id="p8.5",
    title="Rod of Ex 8.7: body and space components and direction cosines of omega",
    chapter=8,
    source="Wells, Problem 8.5 (with Ex 9.4)",
    system=system,
    answers=[
        Quantity("omega along the body axes", lambda s: W_BODY, [-t2d, t1d * c2, t1d * s2]),
        Quantity("omega^2", lambda s: sum(v**2 for v in W_BODY), t1d**2 + t2d**2),
        Quantity("body direction cosines l, m, n", lambda s: W_BODY / w, [-t2d / w, t1d * c2 / w, t1d * s2 / w]),
        Quantity("space direction cosines l1, m1, n1", lambda s: W_SPACE / w,
                 [-t2d * sp.sin(th1) / w, t2d * sp.cos(th1) / w, t1d / w]),
    ],
    simulation=Simulation(params={M: 1.0, L: 1.0, R: 0.5, g: 9.81},
                          initial={th1: 0.0, th2: 0.3, t1d: 2.0, t2d: 0.0}, t_end=5.0),
)
