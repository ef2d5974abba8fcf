"""Wells, Example 17.4 — geodesic on a cylinder of radius r: s = ∫[1 + r^2 (dθ/dz)^2]^(1/2) dz gives a helix."""

import sympy as sp

from lagrange import euler_lagrange
from lagrange.corpus import Problem, Quantity

z = sp.Symbol("z", real=True)
th = sp.Function("theta")(z)
r = sp.Symbol("r", positive=True)
c2, c3 = sp.symbols("c_2 c_3", real=True)
tp, tpp = sp.symbols("theta_p theta_pp", real=True)

phi = sp.sqrt(1 + r**2 * th.diff(z) ** 2)


def plain(e):
    return e.subs({th.diff(z, 2): tpp}).subs({th.diff(z): tp})


PROBLEM = Problem(
    id="ex17.4",
    title="Geodesic on a cylinder: d/dz[r^2 theta'/(1 + r^2 theta'^2)^(1/2)] = 0, helix r theta = c2 z + c3",
    chapter=17,
    source="Wells, Example 17.4",
    system=None,
    answers=[
        # theta is cyclic: the Euler equation is d/dz (dphi/dtheta') = 0 (Wells' sign: minus euler_lagrange's)
        Quantity("Euler-Lagrange equation", lambda _: plain(-euler_lagrange(phi, [th], z)[0].lhs),
                 plain(sp.diff(r**2 * th.diff(z) / sp.sqrt(1 + r**2 * th.diff(z) ** 2), z))),
        Quantity("helix r theta = c2 z + c3 satisfies it",
                 lambda _: sp.simplify(euler_lagrange(phi, [th], z)[0].lhs.subs(th, (c2 * z + c3) / r).doit()), 0),
    ],
)
