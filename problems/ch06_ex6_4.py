"""Wells, Example 6.4 — thin rod sliding on a rough plane, dry friction f per unit length; (x, y) a point of the
rod, which runs from l = −l2 to l = l1 along its direction θ. The book's (6.6):
F_x = −∫_{−l2}^{l1} f (ẋ − l θ̇ sin θ) dl / [ẋ² + ẏ² + l²θ̇² + 2lθ̇(ẏ cos θ − ẋ sin θ)]^{1/2}.
"""

import sympy as sp
from lagrange_problems._common import dry_friction_along_rod

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem

x, y, theta = coordinates("x y theta")
M, I, f, l1, l2 = parameters("M I f l_1 l_2")
s = sp.Symbol("l", real=True)  # the book's integration variable: distance along the rod from (x, y)

# (x, y) taken as the centre of mass (T = ½M(ẋ² + ẏ²) + ½Iθ̇²); the friction does not depend on that choice
system = System([x, y, theta], bodies=[Particle(M, (x, y))], T=I * theta.diff(t) ** 2 / 2,
                P=dry_friction_along_rod(f, x, y, theta, -l2, l1), name="thin rod on a rough plane")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
speed = sp.sqrt(xd**2 + yd**2 + s**2 * thd**2 + 2 * s * thd * (yd * sp.cos(theta) - xd * sp.sin(theta)))
Fx_book = -sp.Integral(f * (xd - s * thd * sp.sin(theta)) / speed, (s, -l2, l1))

PROBLEM = Problem(
    id="ex6.4",
    title="Thin rod on a rough plane: F_x = −∫ f (ẋ − lθ̇ sin θ)/|v| dl",
    chapter=6,
    source="Wells, Example 6.4, eq. (6.6)",
    system=system,
    answers=[GeneralizedForces({x: Fx_book})],
    correction="The printed (6.6) lacks the leading minus and the factor l in l θ̇ sin θ (catalog, OCR): friction "
    "opposes the element's velocity, whose x component is ẋ − l θ̇ sin θ. The System's P is the closed form of "
    "−f ∫|v| dl (valid while θ̇ ≠ 0), so no simulation; (x, y) is taken as the centre of mass for T.",
)
