"""Wells, Example 6.14 — two carts and a rod-mounted m3 joined by power-law dashpots (Fig. 6-5), n > 1."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x1, q1, q2 = coordinates("x1 q1 q2")
m1, m2, m3, a1, a2, n = parameters("m1 m2 m3 a1 a2 n")

# q1 = x2 - x1, q2 = x3 - x1 (inferred). Dashpot a1 between m1 and m3, dashpot a2 between m2 and m3;
# force a|dv|^(n-1) dv opposing the relative velocity: P = -a |dv|^(n+1) / (n+1).
X1, X2, X3 = x1, x1 + q1, x1 + q2


def _dashpot(a, u, v):
    return -a * sp.Abs(u.diff(t) - v.diff(t)) ** (n + 1) / (n + 1)


system = System([x1, q1, q2], bodies=[Particle(m1, (X1,)), Particle(m2, (X2,)), Particle(m3, (X3,))],
                P=_dashpot(a1, X3, X1) + _dashpot(a2, X2, X3), name="carts with dashpots")

q1d, q2d = q1.diff(t), q2.diff(t)
PROBLEM = Problem(
    id="ex6.14",
    title="Carts with power-law dashpots: F_x1 = 0, F_q1, F_q2 from relative velocities",
    chapter=6,
    source="Wells, Example 6.14",
    system=system,
    answers=[GeneralizedForces({
        x1: 0,
        q1: -a2 * sp.Abs(q1d - q2d) ** (n - 1) * (q1d - q2d),
        q2: a2 * sp.Abs(q1d - q2d) ** (n - 1) * (q1d - q2d) - a1 * sp.Abs(q2d) ** (n - 1) * q2d,
    })],
    simulation=Simulation(params={m1: 1, m2: 1, m3: 0.5, a1: 0.3, a2: 0.2, n: 2},
                          initial={x1: 0, q1: 1, q2: 0.5, x1.diff(t): 0.2, q1.diff(t): 0.5, q2.diff(t): -0.3},
                          t_end=5),
    ranges={"q1_dot": (-0.9, 0.9), "q2_dot": (-0.9, 0.9)},
    correction="The coordinates q1 = x2 - x1, q2 = x3 - x1 and the dashpot placement are inferred from the answer "
    "(figure not available). The springs (in V) are omitted: the book's answer concerns the dashpots only.",
)
