"""Wells, Example 17.2 — brachistochrone: bead released with speed v1 at p1(x1, y1), y up, x(y) unknown."""

import sympy as sp

from lagrange import euler_lagrange
from lagrange.corpus import Problem, Quantity

y = sp.Symbol("y", real=True)
X = sp.Function("x")(y)
g, v1, y1, c3, R, x0 = sp.symbols("g v_1 y_1 c_3 R x_0", positive=True)
al = sp.Symbol("alpha", real=True)
xp, xpp = sp.symbols("x_p x_pp", real=True)

# time t = ∫ [(1 + x'^2) / (v1^2 - 2g(y - y1))]^(1/2) dy
phi = sp.sqrt((1 + X.diff(y) ** 2) / (v1**2 - 2 * g * (y - y1)))
c2 = v1**2 / (2 * g) + y1


_EL = []


def _residual(sol_xp, sol_xpp, yval):
    """The Euler–Lagrange expression with x', x'' (and y) replaced by the given values."""
    if not _EL:
        _EL.append(euler_lagrange(phi, [X], y)[0].lhs)
    e = _EL[0]
    e = e.subs({X.diff(y, 2): xpp}).subs({X.diff(y): xp}).subs({xp: sol_xp, xpp: sol_xpp})
    return e.subs(y, yval)


# book's first integral x' = [(c2 - y)/(c3 + y)]^(1/2) with c2 = v1^2/2g + y1
first = sp.sqrt((c2 - y) / (c3 + y))

# book's cycloid x = x0 + R(alpha - sin alpha), y = y0 - R(1 - cos alpha), y0 = c2; x' = dx/dy along it
xc, yc = x0 + R * (al - sp.sin(al)), c2 - R * (1 - sp.cos(al))
dxdy = sp.diff(xc, al) / sp.diff(yc, al)
d2xdy2 = sp.diff(dxdy, al) / sp.diff(yc, al)

PROBLEM = Problem(
    id="ex17.2",
    title="Brachistochrone: the first integral x' = [(c2 - y)/(c3 + y)]^(1/2) and the cycloid solve the Euler equation",
    chapter=17,
    source="Wells, Example 17.2",
    system=None,
    answers=[
        # the Euler equation is d/dy (dphi/dx') = 0 (phi has no x): its residual vanishes on the first integral
        Quantity("first integral satisfies the Euler equation",
                 lambda _: sp.simplify(_residual(first, sp.diff(first, y), y)), 0),
        Quantity("cycloid (y0 = v1^2/2g + y1) satisfies the Euler equation",
                 lambda _: _residual(dxdy, d2xdy2, yc), 0),
        # the conserved quantity dphi/dx' is constant in y along the first integral
        Quantity("d/dy (dphi/dx') on the first integral",
                 lambda _: sp.diff(sp.diff(phi.subs(X.diff(y), xp), xp).subs(xp, first), y), 0),
    ],
    ranges={"alpha": (0.3, 2.8)},
    correction="The bead moves down (x increasing, y decreasing), so dx/dy < 0 along the cycloid while the book "
    "writes the positive root; the Euler equation is odd in x', so both roots satisfy it.",
)
