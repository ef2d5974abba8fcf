"""Wells, Example 5.6 — charge Q moving near fixed charges Q1 at x = -s and Q2 at x = +s; far-field V."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, Q, Q1, s = parameters("m Q Q1 s")

pos = (r * sp.cos(theta), r * sp.sin(theta))


def _coulomb(q2):
    d1 = sp.sqrt((pos[0] + s) ** 2 + pos[1] ** 2)  # to Q1 at (-s, 0)
    d2 = sp.sqrt((pos[0] - s) ** 2 + pos[1] ** 2)  # to Q2 at (+s, 0)
    return Q * Q1 / d1 + Q * q2 / d2


def _taylor_in_s(order):
    """Taylor polynomial of the system's V in the small half-separation s, through s**order."""
    def compute(system):
        out, d = 0, system.V
        for n in range(order + 1):
            out += d.subs(s, 0) * s**n / sp.factorial(n)
            d = d.diff(s)
        return sp.simplify(out)
    return compute


dipole = System([r, theta], bodies=[Particle(m, pos)], V=_coulomb(-Q1), name="charge near a dipole")
pair = System([r, theta], bodies=[Particle(m, pos)], V=_coulomb(Q1), name="charge near two equal charges")
law_of_cosines = Q * Q1 / sp.sqrt(r**2 + s**2 + 2 * r * s * sp.cos(theta))

PROBLEMS = [
    Problem(
        id="ex5.6-dipole",
        title="Q near a dipole (Q1 = -Q2), r >> s: V = -2 Q Q1 s cos(theta) / r^2",
        chapter=5,
        source="Wells, Example 5.6",
        system=dipole,
        answers=[
            PotentialEnergy(law_of_cosines - Q * Q1 / sp.sqrt(r**2 + s**2 - 2 * r * s * sp.cos(theta))),
            Quantity("V to first order in s", _taylor_in_s(1), -(2 * Q * Q1 * s * sp.cos(theta)) / r**2),
        ],
        simulation=Simulation(params={m: 1, Q: 1, Q1: 1, s: 0.1},
                              initial={r: 2, theta: 1.0, r.diff(t): 0, theta.diff(t): 0.1}, t_end=3),
        ranges={"r": (3, 6)},
    ),
    Problem(
        id="ex5.6-equal",
        title="Q near two equal charges (Q1 = Q2), r large: V = 2 Q Q1 / r",
        chapter=5,
        source="Wells, Example 5.6",
        system=pair,
        answers=[
            PotentialEnergy(law_of_cosines + Q * Q1 / sp.sqrt(r**2 + s**2 - 2 * r * s * sp.cos(theta))),
            Quantity("V to zeroth order in s", _taylor_in_s(0), 2 * Q * Q1 / r),
        ],
        simulation=Simulation(params={m: 1, Q: 1, Q1: 1, s: 0.1},
                              initial={r: 2, theta: 1.0, r.diff(t): 0, theta.diff(t): 0.1}, t_end=3),
        ranges={"r": (3, 6)},
    ),
]
