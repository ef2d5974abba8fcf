"""Wells, Sec. 5.1 — work of conservative forces as a line integral: a spring from the origin; F = (3Bx²y², 2Bx³y)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t, work_along
from lagrange.corpus import GeneralizedForces, PotentialEnergy, Problem, Quantity, Simulation

x, y = coordinates("x y")
m, k, l0, B = parameters("m k l0 B")
l = sp.sqrt(x**2 + y**2)

# Spring (k, natural length l0) from the origin to a particle on a smooth horizontal plane.
spring = System([x, y], bodies=[Particle(m, (x, y))], V=k * (l - l0) ** 2 / 2, name="particle on a spring")
# Force field (3Bx²y², 2Bx³y) applied directly by virtual work (no V declared).
cubic = System([x, y], bodies=[Particle(m, (x, y))], forces={x: 3 * B * x**2 * y**2, y: 2 * B * x**3 * y},
               name="particle in the field (3Bx^2y^2, 2Bx^3y)")

x0, y0, x1, y1, s = parameters("x_0 y_0 x_1 y_1 s")
spring_force = [-k * (l - l0) * x / l, -k * (l - l0) * y / l]  # the book's F_x, F_y


def _work(force, start, end):
    """W from ``start`` to ``end`` by :func:`lagrange.work_along`, along a path bent off the straight line
    (x = x0 + s(x1 − x0), y = y0 + s(y1 − y0) + s(1 − s)): path-independent for these fields."""
    path = [start[0] + s * (end[0] - start[0]), start[1] + s * (end[1] - start[1]) + s * (1 - s)]
    return work_along(force, [x, y], path, over=(s, 0, 1))


def _spring_W(X, Y):
    return -k * (X**2 + Y**2 - 2 * l0 * sp.sqrt(X**2 + Y**2)) / 2


PROBLEMS = [
    Problem(
        id="sec5.1-spring",
        title="Spring from the origin: W = -k(x^2+y^2-2 l0 sqrt(x^2+y^2))/2 + const, V = -W",
        chapter=5,
        source="Wells, Sec. 5.1, eq. (5.2)",
        system=spring,
        answers=[
            # V = -W (5.4); the constant (x0, y0) part of (5.2) is dropped.
            PotentialEnergy(sp.Rational(1, 2) * k * (x**2 + y**2 - 2 * l0 * sp.sqrt(x**2 + y**2))),
            GeneralizedForces({x: -k * (l - l0) * x / l, y: -k * (l - l0) * y / l}, which="total"),
            # (5.2): the work of the book's F_x, F_y from (x0, y0) to (x1, y1), along a bent path
            Quantity("W from (x0, y0) to (x1, y1) by work_along (5.2)",
                     lambda _: _work(spring_force, (x0, y0), (x1, y1)), _spring_W(x1, y1) - _spring_W(x0, y0)),
        ],
        simulation=Simulation(params={m: 1, k: 10, l0: 1}, initial={x: 1.2, y: 0, x.diff(t): 0, y.diff(t): 1.0},
                              t_end=5),
    ),
    Problem(
        id="sec5.1-cubic",
        title="Force (3Bx^2y^2, 2Bx^3y) is conservative: W = Bx^3y^2 - Bx0^3y0^2, V = -Bx^3y^2",
        chapter=5,
        source="Wells, Sec. 5.1",
        system=cubic,
        answers=[
            # F_q = -dV/dq with the book's V = -B x^3 y^2, compared with the applied forces.
            GeneralizedForces({x: -sp.diff(-B * x**3 * y**2, x), y: -sp.diff(-B * x**3 * y**2, y)}, which="applied"),
            Quantity("W from (x0, y0) to (x1, y1) by work_along",
                     lambda sys: _work([sys.forces[x], sys.forces[y]], (x0, y0), (x1, y1)),
                     B * x1**3 * y1**2 - B * x0**3 * y0**2),
        ],
        simulation=Simulation(params={m: 1, B: 0.1}, initial={x: 0.5, y: 0.5, x.diff(t): 0, y.diff(t): 0}, t_end=1),
    ),
]
