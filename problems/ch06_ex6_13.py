"""Wells, Example 6.13 — a rod sliding on a plane against a resistance α vⁿ per unit length (x, y a point of the
rod, which runs from l = −l2 to l = l1 along θ): the power function (6.21)
P = −∫_{−l2}^{l1} (α/(n+1)) [(ẋ − lθ̇ sin θ)² + (ẏ + lθ̇ cos θ)²]^{(n+1)/2} dl.
"""

import sympy as sp
from lagrange_problems._common import planar_point_velocity

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, I, alpha, l1, l2 = parameters("M I alpha l_1 l_2")
s = sp.Symbol("l", real=True)  # distance of a rod element from (x, y)
n = 3  # the book's n is general; n = 3 makes the integrand a polynomial, so the System's P has a closed form

# Each element dl resists with α vⁿ dl against its velocity: its power function is −α v^{n+1} dl/(n+1) (6.17),
# integrated over the rod here (a polynomial in l for n = 3).
vx, vy = planar_point_velocity(x, y, theta, s, 0)
P = -sp.integrate(sp.expand(alpha * (vx**2 + vy**2) ** sp.Rational(n + 1, 2) / (n + 1)), (s, -l2, l1))
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=I * theta.diff(t) ** 2 / 2, P=P,
                name="rod with v^3 drag along its length")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
P_book = -sp.Integral(alpha / (n + 1) * ((xd - s * thd * sp.sin(theta)) ** 2 + (yd + s * thd * sp.cos(theta)) ** 2)
                      ** sp.Rational(n + 1, 2), (s, -l2, l1))

PROBLEM = Problem(
    id="ex6.13",
    title="Rod with vⁿ drag along its length (n = 3): P = −∫ α v^{n+1}/(n+1) dl (6.21)",
    chapter=6,
    source="Wells, Example 6.13, eq. (6.21)",
    system=system,
    answers=[PowerFunction(P_book)],
    simulation=Simulation(params={M: 1, I: 0.1, alpha: 0.5, l1: 0.6, l2: 0.4},
                          initial={x: 0, y: 0, theta: 0, xd: 1.0, yd: 0.3, thd: 2.0}, t_end=2.0),
    tags=("slow",),  # over 5 s of CPU to check (30-digit quadrature at random states)
    correction="The book's n is general; it is checked for n = 3, where the System's integral has a closed form "
    "(for other n sympy finds none and the library refuses it by name). (x, y) is taken as the centre of mass "
    "(mass M, inertia I) for T.",
)
