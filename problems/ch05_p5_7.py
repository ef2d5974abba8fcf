"""Wells, Problem 5.7 — bar and block (total mass M) hanging from two identical symmetric springs (Fig. 5-14)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

y = coordinates("y")
M, g, k, l0, s1, s0 = parameters("M g k l0 s1 s0")

# y = vertical drop below the spring anchors (half-span s1 each side); Y up, so the height is -y.
length = sp.sqrt(s1**2 + y**2)
system = System([y], bodies=[Particle(M, (0, -y))], V=-M * g * y + 2 * k * (length - l0) ** 2 / 2,
                name="block on two symmetric springs")
lsym = sp.Symbol("l", positive=True)


def _dV_at_s0(sys):
    return sp.diff(sys.V, y).subs(y, s0)


def _length_at_equilibrium(sys):
    # dV/dy = 0 at y = s0, with the spring length sqrt(s1^2 + s0^2) written l; solve for l.
    eq = _dV_at_s0(sys).subs(sp.sqrt(s1**2 + s0**2), lsym)
    return sp.solve(eq, lsym)[0]


def _polynomial(sys):
    # Clear the square root: dV/dy * L = a + b L (L = spring length); equilibrium <=> b^2 L^2 - a^2 = 0.
    L = sp.sqrt(s1**2 + s0**2)
    expr = sp.expand(_dV_at_s0(sys) * L)
    b = expr.coeff(L)
    a = sp.expand(expr - b * L)
    return sp.expand(b**2 * L**2 - a**2)


def _stiffness(sys):
    return sp.diff(sys.V, y, 2).subs(y, s0)


PROBLEM = Problem(
    id="p5.7",
    title="Block on two springs: equilibrium length l = 2 k l0 s0/(2 k s0 - M g) and the quartic for s0",
    chapter=5,
    source="Wells, Problem 5.7 (b), (d); (c) derived",
    system=system,
    answers=[
        Quantity("(d) spring length at equilibrium", _length_at_equilibrium, 2 * k * l0 * s0 / (2 * k * s0 - M * g)),
        Quantity("(b) equilibrium equation for s0", _polynomial,
                 4 * k**2 * s0**4 - 4 * M * g * k * s0**3 + (M**2 * g**2 + 4 * k**2 * s1**2 - 4 * k**2 * l0**2) * s0**2
                 - 4 * M * g * k * s1**2 * s0 + M**2 * g**2 * s1**2),
        Quantity("(c) vertical stiffness at y = s0 (derived)", _stiffness,
                 2 * k * (1 - l0 * s1**2 / sp.sqrt(s1**2 + s0**2) ** 3)),
    ],
    simulation=Simulation(params={M: 1, g: 9.81, k: 50, l0: 1, s1: 0.8}, initial={y: 1.0, y.diff(t): 0}, t_end=5),
    correction="(b) the text prints -4 k l0^2 in the s0^2 coefficient; dimensionally and on re-derivation it is "
    "-4 k^2 l0^2. (c) is DERIVED in the catalog: stiffness 2k(1 - l0 s1^2/l^3), period "
    "2 pi sqrt(M l^3/(2k(l^3 - l0 s1^2))). Geometry (symmetric springs, half-span s1, drop s0) is inferred.",
)
