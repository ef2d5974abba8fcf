"""Wells, Problem 2.18 — light rod m1–m3 of length l carrying a bead m2; p is the CM of m1 and m3."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

x, y, theta, s = coordinates("x y theta s")
m1, m2, m3, l = parameters("m1 m2 m3 l")
half = sp.Rational(1, 2)

a = m1 * l / (m1 + m3)          # distance from p to m3
I = m1 * m3 * l**2 / (m1 + m3)  # moment of inertia of m1, m3 about p
e = (sp.cos(theta), sp.sin(theta))
system = System(
    [x, y, theta, s],
    bodies=[
        Particle(m1, (x - (l - a) * e[0], y - (l - a) * e[1]), name="m1"),
        Particle(m3, (x + a * e[0], y + a * e[1]), name="m3"),
        Particle(m2, (x + (a - s) * e[0], y + (a - s) * e[1]), name="bead m2"),
    ],
    name="rod with a sliding bead",
)

xd, yd, thd, sd = x.diff(t), y.diff(t), theta.diff(t), s.diff(t)
PROBLEM = Problem(
    id="p2.18",
    title="Rod m1-m3 with a bead m2: T in (x, y, θ, s) about the CM p of m1, m3",
    chapter=2,
    source="Wells, Problem 2.18 (answer key)",
    system=system,
    answers=[
        KineticEnergy(
            half * (m1 + m2 + m3) * (xd**2 + yd**2) + half * I * thd**2
            + half * m2 * (sd**2 + (a - s) ** 2 * thd**2
                           + 2 * thd * (a - s) * (yd * sp.cos(theta) - xd * sp.sin(theta))
                           - 2 * sd * (yd * sp.sin(theta) + xd * sp.cos(theta)))
        ),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 0.5, m3: 2, l: 2},
        initial={x: 0, y: 0, theta: 0, s: 0.3, xd: 0.2, yd: 0, thd: 1.0, sd: 0.1},
        t_end=1.0,
    ),
    correction="Geometry inferred (figure not available): m3 at p + a ê, m1 at p − (l − a) ê, a = m1 l/(m1+m3), "
    "so I = m1 m3 l²/(m1+m3) is the rod's moment of inertia about p.",
)
