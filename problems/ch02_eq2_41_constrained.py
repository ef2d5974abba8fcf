"""Wells, eq. (2.41) with y1 kept — double pendulum in rectangular coordinates, string x1² + y1² = r1².

Multiplier form: coordinates (x1, y1, x2, y2), the upper string as ``Holonomic(x1² + y1² − r1²)``.
A = (2 x1, 2 y1, 0, 0), so the constraint force on m1 is λ(2 x1, 2 y1) = 2 λ r1 e_r (e_r outward from the
support): a string in tension τ1 pulls inward, hence λ = −τ1/(2 r1) (engine convention: λ·A_kr is added to the
applied forces). As in (2.41) m2 is free (the lower string is not imposed). Gravity is added here (−m g δy,
y up) so that the tension is not trivial; (2.41) itself gives only T, which the "-reduced" variant
(y1 = −(r1² − x1²)^(1/2) eliminated, m1 below the support) reproduces.
Expected tension (derived, radial Newton balance of m1): τ1 = m1 v1²/r1 − m1 g y1/r1.
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, delta, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, Problem, Quantity, Simulation

x1, y1, x2, y2 = coordinates("x1 y1 x2 y2")
m1, m2, r1, g = parameters("m1 m2 r1 g")

system = System(
    [x1, y1, x2, y2],
    bodies=[Particle(m1, (x1, y1), name="m1"), Particle(m2, (x2, y2), name="m2")],
    forces=-m1 * g * delta(y1) - m2 * g * delta(y2),
    constraints=[Holonomic(x1**2 + y1**2 - r1**2, name="string1")],
    name="double pendulum, rectangular coordinates (multipliers)",
)
reduced = eliminate(system, {y1: -sp.sqrt(r1**2 - x1**2)})

PARAMS = {m1: 1.0, m2: 1.5, r1: 1.0, g: 9.81}
INITIAL = {x1: 0.6, y1: -0.8, x2: 0.5, y2: -1.5, x1.diff(t): 0.8, y1.diff(t): 0.6, x2.diff(t): 0.1, y2.diff(t): 0.0}
tau1 = m1 * (x1.diff(t) ** 2 + y1.diff(t) ** 2) / r1 - m1 * g * y1 / r1

PROBLEMS = [
    Problem(
        id="eq2.41-multipliers",
        title="Double pendulum in rectangular coordinates with the string x1^2 + y1^2 = r1^2 as a multiplier",
        chapter=2,
        source="Wells, Sec. 2.9, eq. (2.41)",
        system=system,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * m1 * (x1.diff(t) ** 2 + y1.diff(t) ** 2)
                          + sp.Rational(1, 2) * m2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)),
            ConstraintForce("string1", -tau1 / (2 * r1), PARAMS, INITIAL, t_end=1.5),
            # generalized reaction on x1: 2 x1 λ = −τ1 x1/r1 (the string's pull, x component)
            ConstraintForce("string1", -tau1 * x1 / r1, PARAMS, INITIAL, t_end=1.5, coordinate=x1),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=3),
        correction="(2.41) gives only T (no forces); gravity is added to make the string tension non-trivial, "
        "and the tension is the derived radial balance of m1 (no book value).",
    ),
    Problem(
        id="eq2.41-multipliers-reduced",
        title="Double pendulum: y1 eliminated from the multiplier form gives the book's T (2.41)",
        chapter=2,
        source="Wells, Sec. 2.9, eq. (2.41)",
        system=reduced,
        answers=[
            KineticEnergy(
                sp.Rational(1, 2) * m1 * x1.diff(t) ** 2 * r1**2 / (r1**2 - x1**2)
                + sp.Rational(1, 2) * m2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)
            ),
            Quantity("degrees of freedom", lambda s: sp.Integer(len(s.coordinates)), sp.Integer(3)),
        ],
        ranges={"r1": (1.1, 2.3), "x1": (0.15, 0.85)},
        simulation=Simulation(params=PARAMS, initial={x1: 0.6, x2: 0.5, y2: -1.5, x1.diff(t): 0.8,
                                                       x2.diff(t): 0.1, y2.diff(t): 0.0}, t_end=0.3),
    ),
]
