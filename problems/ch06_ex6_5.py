"""Wells, Example 6.5 — a plane board sliding on a rough horizontal plane, dry friction f per unit area; (x, y)
a point of the board, θ its turn. An element at body coordinates (X, Y) moves with
v = (ẋ − θ̇(X sin θ + Y cos θ), ẏ + θ̇(X cos θ − Y sin θ)), and the generalized forces are integrals over the area:
F_x = −∫∫ f v_x/|v| dA, F_y = −∫∫ f v_y/|v| dA, F_θ = −∫∫ f [−(X sin θ + Y cos θ) v_x + (X cos θ − Y sin θ) v_y]/|v| dA.

Here the board is the rectangle 2a × 2b of Ex. 6.8 with (x, y) at its centre. The System gives the friction as
Wells' power function P = −f ∫∫ |v| dA (Prob. 6.21–6.24): sympy has no closed form for it, so it is kept as an
integral (lagrange.Quadrature), the derivation differentiates under the integral sign and generated code
evaluates it by Gauss–Legendre quadrature (lagrange.codegen.quadrature).
"""

import sympy as sp

from lagrange import Particle, Quadrature, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, f, a, b = parameters("M f a b")
X, Y = sp.symbols("X Y", real=True)  # body coordinates of an element of the board

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
ex, ey = -(X * sp.sin(theta) + Y * sp.cos(theta)), X * sp.cos(theta) - Y * sp.sin(theta)  # ∂r/∂θ of the element
vx, vy = xd + thd * ex, yd + thd * ey
speed = sp.sqrt(vx**2 + vy**2)
area = ((X, -a, a), (Y, -b, b))

# uniform board: T = ½M(ẋ² + ẏ²) + ½·M(a² + b²)/3·θ̇²
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=M * (a**2 + b**2) / 6 * thd**2,
                P=-f * Quadrature(speed, *area), name="board sliding on a rough plane")

book = {
    x: -sp.Integral(f * vx / speed, *area),
    y: -sp.Integral(f * vy / speed, *area),
    theta: -sp.Integral(f * (ex * vx + ey * vy) / speed, *area),
}

PROBLEM = Problem(
    id="ex6.5",
    title="Board on a rough plane: dry friction integrated over the area (quadrature in generated code)",
    chapter=6,
    source="Wells, Example 6.5",
    system=system,
    answers=[GeneralizedForces(book)],
    # |θ̇| (a, b) < |v| of the centre: no element at rest, where the integrands turn sharply (the compared quadrature)
    ranges={"a": (0.1, 0.2), "b": (0.1, 0.2)},
    simulation=Simulation(
        params={M: 1, f: 0.5, a: 0.6, b: 0.4},
        # the instantaneous centre starts inside the board (ω·a > v); the board does not stop before t_end
        initial={x: 0, y: 0, theta: 0, x.diff(t): 0.4, y.diff(t): 0.2, theta.diff(t): 2.0},
        t_end=0.5,
    ),
    correction="The book states the generalized forces for a board of any shape; the rectangle 2a × 2b of Ex. 6.8 "
    "(uniform, (x, y) at its centre) is taken so the integrals have limits. The System declares P = −f ∫∫ |v| dA "
    "(Prob. 6.24's form); its ∂P/∂q̇ are the book's F.",
)
