"""Wells, Problem 6.25 — a rod (length l; x, y at one end, θ to X) sliding on a rough plane with dry friction f per
unit length: P = −f ∫₀ˡ |v(r)| dr = −f ∫₀ˡ (a r² + b r + c)^{1/2} dr, a = θ̇², b = 2θ̇(ẏ cos θ − ẋ sin θ), c = ẋ² + ẏ².

The System carries the integral's closed form (``_common.dry_friction_along_rod``: generated code has no
quadrature); the book's integral is the answer, evaluated by 30-digit quadrature at random states.
"""

import sympy as sp
from lagrange_problems._common import dry_friction_along_rod, rod_from_end

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem

x, y, theta = coordinates("x y theta")
M, l, f = parameters("M l f")
r = sp.Symbol("r", real=True)  # distance of a rod element from the end (x, y)

rod, T_rot = rod_from_end(M, l, x, y, theta)
system = System([x, y, theta], bodies=[rod], T=T_rot, P=dry_friction_along_rod(f, x, y, theta, 0, l),
                name="rod sliding on a rough plane (dry friction along its length)")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
speed2 = xd**2 + yd**2 + r**2 * thd**2 + 2 * r * thd * (yd * sp.cos(theta) - xd * sp.sin(theta))
P_book = -f * sp.Integral(sp.sqrt(speed2), (r, 0, l))

PROBLEM = Problem(
    id="p6.25",
    title="Rod with dry friction along its length: P = −f ∫₀ˡ (a r² + b r + c)^{1/2} dr",
    chapter=6,
    source="Wells, Problem 6.25",
    system=system,
    answers=[PowerFunction(P_book)],  # compared through ∂P/∂q̇ for x, y and θ
    tags=("slow",),  # over 5 s of CPU to check (30-digit quadrature at random states)
    correction="The rod is taken uniform (mass M, centre at l/2) for T; P does not depend on it. The System's P is "
    "the closed form of the book's integral (valid while the rod turns, θ̇ ≠ 0: at θ̇ = 0 it is the limit −f l |v|); "
    "no simulation, since a rod that stops turning meets that removable singularity.",
)
