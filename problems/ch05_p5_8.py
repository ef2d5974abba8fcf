"""Wells, Problem 5.8 — a pendulum near a large sphere M (Fig. 5-15): the bob of a spherical pendulum (length l,
pivot at the origin) is attracted by a sphere of mass M whose centre is a distance h below the pivot; earth's
gravity is neglected. The book gives no printed answer; the catalog's is V = −GMm/d(θ), with
d² = l² + h² − 2hl cosθ the distance from the bob to the centre.

The attraction is declared as an applied force (virtual work, Q_r = F·∂r/∂q_r), not through V: the answers
check that the library's :func:`lagrange.potential_of` finds −GMm/d in the pendulum's own coordinates (θ, φ),
and that the applied forces are −∂V/∂q of the book's V.
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, potential_of, t
from lagrange.corpus import GeneralizedForces, Problem, Quantity, Simulation

theta, phi = coordinates("theta phi")
m, M, G, l, h = parameters("m M G l h")

bob = sp.Matrix([l * sp.sin(theta) * sp.cos(phi), l * sp.sin(theta) * sp.sin(phi), -l * sp.cos(theta)])
to_centre = bob - sp.Matrix([0, 0, -h])
attraction = -G * M * m * to_centre / to_centre.norm() ** 3  # Newton's inverse-square law, toward the centre
Q = {q: sp.expand(attraction.dot(bob.diff(q))) for q in (theta, phi)}
system = System([theta, phi], bodies=[Particle(m, tuple(bob))], forces=Q, name="spherical pendulum near a sphere")

d = sp.sqrt(l**2 + h**2 - 2 * h * l * sp.cos(theta))
V_book = -G * M * m / d
REFERENCE = {theta: sp.pi / 2, phi: 0}  # V is compared up to its constant: both sides vanish at θ = π/2

PROBLEM = Problem(
    id="p5.8",
    title="Pendulum near a large sphere: V = -G M m / d(theta), found from the attraction in (theta, phi)",
    chapter=5,
    source="Wells, Problem 5.8 (Fig. 5-15)",
    system=system,
    answers=[
        GeneralizedForces({q: -sp.diff(V_book, q) for q in (theta, phi)}, which="applied"),
        Quantity("V = potential_of(attraction), zero at theta = pi/2",
                 lambda s: potential_of(list(attraction), [theta, phi], position=list(bob), reference=REFERENCE),
                 V_book - V_book.subs(REFERENCE)),
    ],
    simulation=Simulation(params={m: 1, M: 10, G: 1, l: 1, h: 3},
                          initial={theta: 0.6, phi: 0, theta.diff(t): 0, phi.diff(t): 0.8}, t_end=5),
    correction="No printed answer (Fig. 5-15 not in the text); the sphere is placed on the vertical through the "
    "pivot so that d depends on theta only, as the catalog's d(theta) does.",
)
