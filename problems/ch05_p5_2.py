"""Wells, Problem 5.2 — work around a closed rectangular path: 2k(x2 − x1)(y2 − y1) for F = (−ky, kx)
(not conservative), 0 for F = (3Bx²y², 2Bx³y) (conservative)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x, y = coordinates("x y")
m, k, B = parameters("m k B")
x1, x2, y1, y2 = parameters("x_1 x_2 y_1 y_2")
X, Y = sp.symbols("X Y", real=True)
curl = System([x, y], bodies=[Particle(m, (x, y))], forces={x: -k * y, y: k * x}, name="F = (−ky, kx)")
exact = System([x, y], bodies=[Particle(m, (x, y))], forces={x: 3 * B * x**2 * y**2, y: 2 * B * x**3 * y},
               name="F = (3Bx²y², 2Bx³y)")


def _loop_work(s):
    """∮ F_x dx + F_y dy counter-clockwise around the rectangle (x1, y1) → (x2, y1) → (x2, y2) → (x1, y2)."""
    Fx, Fy = (s.forces[q].subs({x: X, y: Y}) for q in (x, y))
    return (sp.integrate(Fx.subs(Y, y1), (X, x1, x2)) + sp.integrate(Fy.subs(X, x2), (Y, y1, y2))
            + sp.integrate(Fx.subs(Y, y2), (X, x2, x1)) + sp.integrate(Fy.subs(X, x1), (Y, y2, y1)))


PROBLEMS = [
    Problem(
        id="p5.2",
        title="Work around a rectangle for F = (−ky, kx): 2k(x2 − x1)(y2 − y1), so F is not conservative",
        chapter=5,
        source="Wells, Problem 5.2 (force of Problem 5.1(c))",
        system=curl,
        answers=[Quantity("closed-path work", _loop_work, 2 * k * (x2 - x1) * (y2 - y1))],
        simulation=Simulation(params={m: 1, k: 1}, initial={x: 1, y: 0, x.diff(t): 0, y.diff(t): 0}, t_end=2),
    ),
    Problem(
        id="p5.2-exact",
        title="Work around a rectangle for F = (3Bx²y², 2Bx³y): zero (conservative)",
        chapter=5,
        source="Wells, Problem 5.2",
        system=exact,
        answers=[Quantity("closed-path work", _loop_work, 0)],
        simulation=Simulation(params={m: 1, B: 0.1}, initial={x: 1, y: 1, x.diff(t): 0, y.diff(t): 0}, t_end=1),
    ),
]
