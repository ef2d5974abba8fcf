"""Wells, Problem 4.9 — two sliders in horizontal tubes on a shaft (inertia I), joined by a cord containing a spring."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, GeneralizedForces, Problem, Simulation

r1, r2, theta = coordinates("r1 r2 theta")
m1, m2, I, k, c, w = parameters("m1 m2 I k c omega")

# Tubes along opposite directions of one horizontal line turning with the shaft; the cord over the axis has
# stretch r1 + r2 − c.
def sliders(angle):
    e = (sp.cos(angle), sp.sin(angle))
    return [Particle(m1, (r1 * e[0], r1 * e[1]), name="m1"), Particle(m2, (-r2 * e[0], -r2 * e[1]), name="m2")]


spring = -k * (r1 + r2 - c) * delta(r1 + r2)
free = System([r1, r2, theta], T=sp.Rational(1, 2) * I * theta.diff(t) ** 2, bodies=sliders(theta), forces=spring,
              name="sliders in rotating tubes")
driven = System([r1, r2], bodies=sliders(theta), forces=spring, prescribed={theta: w * t},
                name="sliders in tubes turned at constant speed")

thd = theta.diff(t)
S = -k * (r1 + r2 - c)
PROBLEMS = [
    Problem(
        id="p4.9",
        title="Sliders in rotating tubes joined by a spring cord: equations and conserved P_theta",
        chapter=4,
        source="Wells, Problem 4.9(a)",
        system=free,
        answers=[
            GeneralizedForces({r1: S, r2: S, theta: 0}),
            ConservedMomenta({theta: (I + m1 * r1**2 + m2 * r2**2) * thd}),
            EquationsOfMotion([
                sp.Eq(m1 * r1.diff(t, 2) - m1 * r1 * thd**2, S),
                sp.Eq(m2 * r2.diff(t, 2) - m2 * r2 * thd**2, S),
                sp.Eq(sp.diff((I + m1 * r1**2 + m2 * r2**2) * thd, t), 0),
            ], per_equation=True),
        ],
        simulation=Simulation(params={m1: 1, m2: 2, I: 1, k: 50, c: 1},
                              initial={r1: 0.6, r2: 0.6, theta: 0, r1.diff(t): 0, r2.diff(t): 0, thd: 2}, t_end=3),
    ),
    Problem(
        id="p4.9b",
        title="Sliders in tubes held at constant speed omega by a motor",
        chapter=4,
        source="Wells, Problem 4.9(b)",
        system=driven,
        answers=[
            EquationsOfMotion([
                sp.Eq(m1 * r1.diff(t, 2) - m1 * r1 * w**2, S),
                sp.Eq(m2 * r2.diff(t, 2) - m2 * r2 * w**2, S),
            ], per_equation=True),
        ],
        simulation=Simulation(params={m1: 1, m2: 2, k: 50, c: 1, w: 2},
                              initial={r1: 0.6, r2: 0.6, r1.diff(t): 0, r2.diff(t): 0}, t_end=3),
        correction="Part (b) has no separate printed answer: the (a) equations with theta' = omega (catalog, derived).",
    ),
]
