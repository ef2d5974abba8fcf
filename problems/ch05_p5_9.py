"""Wells, Problem 5.9 — linear quadrupole (+Q, -2Q, +Q at x = -s, 0, +s) and a movable charge Q1, r >> s."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, Q, Q1, s = parameters("m Q Q1 s")

pos = (r * sp.cos(theta), r * sp.sin(theta))
V = sum(q * Q1 / sp.sqrt((pos[0] - xs) ** 2 + pos[1] ** 2) for q, xs in ((Q, -s), (-2 * Q, 0), (Q, s)))
system = System([r, theta], bodies=[Particle(m, pos)], V=V, name="charge near a linear quadrupole")


def _leading(system):
    """Taylor polynomial of V in s through s**2 (orders 0 and 1 vanish)."""
    out, d = 0, system.V
    for n in range(3):
        out += d.subs(s, 0) * s**n / sp.factorial(n)
        d = d.diff(s)
    return sp.simplify(out)


PROBLEM = Problem(
    id="p5.9",
    title="Quadrupole: V = 2 Q Q1 s^2 cos^2(theta)/r^3 - Q Q1 s^2 sin^2(theta)/r^3 for r >> s",
    chapter=5,
    source="Wells, Problem 5.9",
    system=system,
    answers=[
        Quantity("V to second order in s", _leading,
                 2 * Q * Q1 * s**2 * sp.cos(theta) ** 2 / r**3 - Q * Q1 * s**2 * sp.sin(theta) ** 2 / r**3),
    ],
    simulation=Simulation(params={m: 1, Q: 1, Q1: 1, s: 0.1},
                          initial={r: 2, theta: 1.0, r.diff(t): 0, theta.diff(t): 0.1}, t_end=3),
    ranges={"r": (3, 6)},
)
