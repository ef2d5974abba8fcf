"""Wells, Problem 17.1 — geodesics on a sphere are great circles (Euler–Lagrange equation of the arc length)."""

import sympy as sp

from lagrange import euler_lagrange
from lagrange.corpus import Problem, Quantity

ph = sp.Symbol("phi", real=True)
th = sp.Function("theta")(ph)
a, ph0 = sp.symbols("a phi_0", real=True)

# arc length on the unit sphere with theta(phi): s = ∫ (theta'^2 + sin^2 theta)^(1/2) dphi
F = sp.sqrt(th.diff(ph) ** 2 + sp.sin(th) ** 2)

# great circle: the sphere cut by a plane through the centre, cot(theta) = a cos(phi - phi_0)
circle = sp.acot(a * sp.cos(ph - ph0))


def _residual(_):
    e = euler_lagrange(F, [th], ph)[0].lhs
    return sp.simplify(sp.expand_trig(e).subs(th, circle).doit())  # expand sin(2 theta) etc. first (fast)


PROBLEM = Problem(
    id="p17.1",
    title="Geodesic on a sphere: the great circle cot(theta) = a cos(phi - phi0) satisfies the Euler equation",
    chapter=17,
    source="Wells, Problem 17.1",
    system=None,
    answers=[Quantity("Euler-Lagrange residual on a great circle", _residual, 0)],
    ranges={"a": (0.3, 2.0), "phi_0": (-0.5, 0.5), "phi": (0.1, 1.2)},
    correction="Catalog tag [PARTIAL]: the book states the result (great circle) without a formula; the great-circle "
    "equation cot(theta) = a cos(phi - phi0) (plane through the centre) is the derived form checked here.",
)
