"""Wells, Problem 6.30 — a board sliding against a resistance a vⁿ per unit area, written in the instantaneous
board frame: P = −a ∫∫ (1/(n+1)) [(ẋ − x2θ̇ sin θ − y2θ̇ cos θ)² + (ẏ + x2θ̇ cos θ − y2θ̇ sin θ)²]^{(n+1)/2} dx2 dy2
(exponent corrected, see below), which at θ = 0 reduces to [(ẋ − y2θ̇)² + (ẏ + x2θ̇)²]^{(n+1)/2}.
"""

import sympy as sp
from lagrange_problems._common import planar_point_velocity

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Quantity, Simulation

x, y, theta = coordinates("x y theta")
M, I, a_drag, a, b = parameters("M I a_d a b")  # a_d: the book's a (resistance per unit area); board 2a x 2b
x2, y2 = sp.symbols("x2 y2", real=True)  # board-fixed coordinates of an area element, origin at (x, y)
n = 3

# Each area element resists with a vⁿ against its velocity: power function −a v^{n+1} dA/(n+1) (6.17).
vx, vy = planar_point_velocity(x, y, theta, x2, y2)
P = -sp.integrate(sp.expand(a_drag * (vx**2 + vy**2) ** sp.Rational(n + 1, 2) / (n + 1)), (x2, -a, a), (y2, -b, b))
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=I * theta.diff(t) ** 2 / 2, P=P,
                name="board with v^3 drag")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
book_integrand = (1 / sp.Integer(n + 1)) * ((xd - x2 * thd * sp.sin(theta) - y2 * thd * sp.cos(theta)) ** 2
                                            + (yd + x2 * thd * sp.cos(theta) - y2 * thd * sp.sin(theta)) ** 2
                                            ) ** sp.Rational(n + 1, 2)
P_book = -a_drag * sp.integrate(sp.expand(book_integrand), (x2, -a, a), (y2, -b, b))  # polynomial for n = 3
frame_integrand = ((xd - y2 * thd) ** 2 + (yd + x2 * thd) ** 2) ** sp.Rational(n + 1, 2) / (n + 1)
P_frame = -a_drag * sp.integrate(sp.expand(frame_integrand), (x2, -a, a), (y2, -b, b))

PROBLEM = Problem(
    id="p6.30",
    title="Board with vⁿ drag (n = 3, rectangle 2a × 2b): P in the instantaneous board frame",
    chapter=6,
    source="Wells, Problem 6.30",
    system=system,
    answers=[PowerFunction(P_book),
             Quantity("P at θ = 0 (the instantaneous-frame form)",
                      lambda s: s.P.subs(theta, 0), P_frame.subs(theta, 0))],
    simulation=Simulation(params={M: 1, I: 0.1, a_drag: 0.5, a: 0.5, b: 0.3},
                          initial={x: 0, y: 0, theta: 0, xd: 1.0, yd: 0.3, thd: 2.0}, t_end=2.0),
    correction="The book prints the exponent n/2 (i.e. vⁿ); by (6.17) the power function of a vⁿ resistance is "
    "v^{n+1}/(n+1), so the exponent is (n+1)/2 (catalog). Checked for n = 3 on a rectangle 2a × 2b with the "
    "reference point at its centre (the book's board is of any shape); M and I are assumed for T.",
)
