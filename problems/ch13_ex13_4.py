"""Wells, Example 13.4 and Problem 13.2 — mass m on a smooth rod inclined at θ on a cart M: actuator forces for
different actuator arrangements and coordinates."""

import sympy as sp

from lagrange import System, actuator_forces, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x, s = coordinates("x s")
x1 = coordinates("x1")
M, m, b, g = parameters("M m b g")  # b = tanθ
f1, f2, f3 = sp.symbols("f1 f2 f3", real=True)

system = System([x, s], T=(M + b**2 * m) * s.diff(t) ** 2 / 2 + m * (1 + b**2) * x.diff(t) ** 2 / 2
                - m * b**2 * x.diff(t) * s.diff(t), V=m * g * b * (x - s), name="mass on an inclined rod on a cart")
# (c) coordinates (x1, s) with x1 = x − s
sys_c = System([x1, s], T=system.T.subs(x, x1 + s).doit(), V=m * g * b * x1, name="same, coordinates (x1, s)")

xdd, sdd = x.diff(t, 2), s.diff(t, 2)
eq1 = (M + b**2 * m) * sdd - m * b**2 * xdd - m * g * b  # = F'_s
eq2 = m * (1 + b**2) * xdd - m * b**2 * sdd + m * g * b  # = F'_x
SIM = Simulation(params={M: 3, m: 1, b: 0.5, g: 9.81}, initial={x: 0, s: 0, x.diff(t): 0, s.diff(t): 0}, t_end=1)


def _f(sy, vw, unknowns):
    f = actuator_forces(sy, vw, unknowns)
    return [f[u] for u in unknowns]


def _in_x1(e):
    """Book expressions in (x, s) rewritten for the (x1, s) system: x = x1 + s."""
    return e.subs(xdd, x1.diff(t, 2) + s.diff(t, 2))


PROBLEMS = [
    Problem(
        id="ex13.4",
        title="Mass on an inclined rod on a cart: actuators f1 (ground→cart) and f2 (cart↔m)",
        chapter=13,
        source="Wells, Example 13.4",
        system=system,
        answers=[
            EquationsOfMotion([sp.Eq(eq2, 0), sp.Eq(eq1, 0)], per_equation=True),
            Quantity("f1, f2", lambda sy: _f(sy, f1 * delta(s) + f2 * delta(x - s), [f1, f2]),
                     [M * sdd + m * xdd, eq2]),
        ],
        simulation=SIM,
    ),
    Problem(
        id="p13.2",
        title="Inclined rod on a cart: actuator pairs (f1, f3), (f2, f3) and coordinates (x1, s)",
        chapter=13,
        source="Wells, Problem 13.2",
        system=system,
        answers=[
            Quantity("(a) f1, f3 with F'_s = f1, F'_x = f3", lambda sy: _f(sy, f1 * delta(s) + f3 * delta(x), [f1, f3]),
                     [eq1, eq2]),
            Quantity("(b) f2, f3 with F'_s = −f2, F'_x = f2 + f3",
                     lambda sy: _f(sy, f2 * delta(x - s) + f3 * delta(x), [f2, f3]), [-eq1, eq1 + eq2]),
            Quantity("(c) f1, f2 in coordinates (x1, s) equal those of Ex. 13.4",
                     lambda sy: _f(sys_c, f1 * delta(s) + f2 * delta(x1), [f1, f2]),
                     [_in_x1(M * sdd + m * xdd), _in_x1(eq2)]),
        ],
        simulation=SIM,
        correction="The book gives the equations (1), (2) with the new F' only; the forces follow from them "
                   "(catalog). For (c) the book's expressions are rewritten with ẍ = ẍ1 + s̈.",
    ),
]
