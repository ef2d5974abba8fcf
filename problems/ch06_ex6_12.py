"""Wells, Example 6.12 — board of any shape sliding on a viscous film (α per unit area): the power function in
terms of the area A, its first moments A x̄2, A ȳ2 and I = α ∫(x2² + y2²) dA (board-fixed axes at the point x, y)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, Ib, alpha, A, xb, yb, Jxx, Jyy, Jxy = parameters("M I_b alpha A xbar_2 ybar_2 J_xx J_yy J_xy")
x2, y2 = sp.symbols("x2 y2", real=True)

# Velocity of the board element at board-fixed (x2, y2); P = −(α/2)∫ v² dA with the area integrals replaced by
# the moments ∫dA = A, ∫x2 dA = A x̄2, ∫y2 dA = A ȳ2, ∫x2² dA = J_xx, ∫y2² dA = J_yy, ∫x2 y2 dA = J_xy.
X = x + x2 * sp.cos(theta) - y2 * sp.sin(theta)
Y = y + x2 * sp.sin(theta) + y2 * sp.cos(theta)
v2 = sp.Poly(sp.expand(X.diff(t) ** 2 + Y.diff(t) ** 2), x2, y2)
moment = {(0, 0): A, (1, 0): A * xb, (0, 1): A * yb, (2, 0): Jxx, (0, 2): Jyy, (1, 1): Jxy}
P = -alpha / 2 * sum(c * moment[mon] for mon, c in v2.terms())

# T: the board's mass M at its c.m. is not needed for P; take the reference point as c.m. for the dynamics
system = System([x, y, theta], T=Ib * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (x, y))], P=P,
                name="board of any shape on a viscous film")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
I = alpha * (Jxx + Jyy)
P_book = -(alpha * A * (xd**2 + yd**2) / 2 + I * thd**2 / 2
           - alpha * A * thd * xd * (xb * sp.sin(theta) + yb * sp.cos(theta))
           + alpha * A * thd * yd * (xb * sp.cos(theta) - yb * sp.sin(theta)))
PROBLEM = Problem(
    id="ex6.12",
    title="Board of any shape on a viscous film: P in A, x̄2, ȳ2 and I = α∫(x2² + y2²) dA",
    chapter=6,
    source="Wells, Example 6.12",
    system=system,
    answers=[
        PowerFunction(P_book),
        GeneralizedForces({x: sp.diff(P_book, xd), y: sp.diff(P_book, yd), theta: sp.diff(P_book, thd)}),
    ],
    simulation=Simulation(params={M: 1, Ib: 0.2, alpha: 0.5, A: 1, xb: 0.1, yb: 0.2, Jxx: 0.1, Jyy: 0.08},
                          initial={x: 0, y: 0, theta: 0, xd: 1, yd: 0.5, thd: 2}, t_end=3),
    correction="Area moments are kept as symbols (A, x̄2, ȳ2 and the second moments J_xx, J_yy, J_xy); the product "
               "moment J_xy cancels and J_xx + J_yy enters only through I = α(J_xx + J_yy), as in the book. "
               "The reference point (x, y) is taken as the c.m. for T; P does not depend on that choice. "
               "The generalized forces are ∂P/∂q̇ of the book's P (6.10).",
)
