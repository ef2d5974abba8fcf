"""Wells, Example 17.1 — shortest plane curve: Euler–Lagrange equation of ∫(1 + y'^2)^(1/2) dx."""

import sympy as sp

from lagrange import euler_lagrange
from lagrange.corpus import Problem, Quantity

x = sp.Symbol("x", real=True)
y = sp.Function("y")(x)
c2, c3 = sp.symbols("c_2 c_3", real=True)
yp, ypp = sp.symbols("y_p y_pp", real=True)  # y', y'' as plain symbols for the numeric comparison

phi = sp.sqrt(1 + y.diff(x) ** 2)


def plain(e):
    return e.subs({y.diff(x, 2): ypp}).subs({y.diff(x): yp})


def _el(_):
    # euler_lagrange returns dphi/dy - d/dx dphi/dy' = 0; Wells (17.1) writes d/dx dphi/dy' - dphi/dy = 0
    return plain(-euler_lagrange(phi, [y], x)[0].lhs)


PROBLEM = Problem(
    id="ex17.1",
    title="Shortest plane curve: d/dx[y'/(1 + y'^2)^(1/2)] = 0, so y = c2 x + c3",
    chapter=17,
    source="Wells, Example 17.1",
    system=None,
    answers=[
        Quantity("Euler-Lagrange equation (17.1)", _el, plain(sp.diff(y.diff(x) / sp.sqrt(1 + y.diff(x) ** 2), x))),
        Quantity("y = c2 x + c3 satisfies it",
                 lambda _: sp.simplify(euler_lagrange(phi, [y], x)[0].lhs.subs(y, c2 * x + c3).doit()), 0),
    ],
)
