"""Wells, Example 6.8 — rectangular board 2a x 2b sliding on a viscous film (alpha per unit area)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, I, alpha, a, b = parameters("M I alpha a b")
x2, y2 = sp.symbols("x2 y2", real=True)  # board-fixed coordinates of an area element, origin at the centre

# Velocity of the element at (x2, y2); P = -(1/2) integral alpha v^2 dA over the board (6.17 with n = 1).
X = x + x2 * sp.cos(theta) - y2 * sp.sin(theta)
Y = y + x2 * sp.sin(theta) + y2 * sp.cos(theta)
v2 = sp.expand(X.diff(t) ** 2 + Y.diff(t) ** 2)
P = -alpha / 2 * sp.integrate(v2, (x2, -a, a), (y2, -b, b))
system = System([x, y, theta], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (x, y))], P=sp.simplify(P),
                name="board on a viscous film")

A = 4 * a * b
PROBLEM = Problem(
    id="ex6.8",
    title="Rectangle on a viscous film: F_x = -A alpha xd, F_y = -A alpha yd, F_theta = -(1/3) A alpha (a^2+b^2) thd",
    chapter=6,
    source="Wells, Example 6.8",
    system=system,
    answers=[GeneralizedForces({x: -A * alpha * x.diff(t), y: -A * alpha * y.diff(t),
                                theta: -A * alpha * (a**2 + b**2) * theta.diff(t) / 3})],
    simulation=Simulation(params={M: 1, I: 0.2, alpha: 0.3, a: 0.5, b: 0.3},
                          initial={x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}, t_end=5),
    correction="The distributed drag is integrated symbolically over the board; M and I (about the centre) "
    "are assumed for T.",
)
