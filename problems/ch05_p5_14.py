"""Wells, Problem 5.14 — double pendulum with two springs on m1 (Fig. 5-20), gravity excluded: exact V and the
approximate V = c θ² for small θ about the equilibrium θ = 0."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

theta, phi = coordinates("theta phi")
m1, m2, r1, r2, k1, k2 = parameters("m_1 m_2 r_1 r_2 k_1 k_2")
x1, y1, x2, y2, l1p, l2p = parameters("x_1 y_1 x_2 y_2 l1p l2p")  # anchors; natural lengths l1', l2'
P1 = (r1 * sp.sin(theta), -r1 * sp.cos(theta))
P2 = (P1[0] + r2 * sp.sin(phi), P1[1] - r2 * sp.cos(phi))
# spring anchors at (x1, −y1) and (−x2, −y2) from the rest position (0, −r1) of m1
A1, A2 = (x1, -r1 - y1), (-x2, -r1 - y2)
s1 = sp.sqrt((P1[0] - A1[0]) ** 2 + (P1[1] - A1[1]) ** 2)
s2 = sp.sqrt((P1[0] - A2[0]) ** 2 + (P1[1] - A2[1]) ** 2)
system = System([theta, phi], bodies=[Particle(m1, P1), Particle(m2, P2)],
                V=k1 * (s1 - l1p) ** 2 / 2 + k2 * (s2 - l2p) ** 2 / 2, name="double pendulum with two springs on m1")

l1, l2 = sp.sqrt(x1**2 + y1**2), sp.sqrt(x2**2 + y2**2)
# horizontal equilibrium at θ = 0: k1 (l1 − l1') x1/l1 = k2 (l2 − l2') x2/l2, solved for l2'
eq_l2p = l2 - k1 * (l1 - l1p) * x1 * l2 / (l1 * k2 * x2)
xb, yb = r1 * sp.sin(theta), r1 * (1 - sp.cos(theta))
V_exact = k1 * (sp.sqrt((x1 - xb) ** 2 + (y1 + yb) ** 2) - l1p) ** 2 / 2 \
    + k2 * (sp.sqrt((x2 + xb) ** 2 + (y2 + yb) ** 2) - l2p) ** 2 / 2
c_book = ((k1 + k2) * r1**2 / 2 + (k1 * y1 * (l1 - l1p) / l1 + k2 * y2 * (l2 - l2p) / l2) * r1 / 2
          - (k1 * l1p * y1**2 / l1**3 + k2 * l2p * y2**2 / l2**3) * r1**2 / 2)


def _taylor(s):
    """dV/dθ and ½ d²V/dθ² at θ = 0 with l2' from the equilibrium condition."""
    V = s.V
    return [sp.diff(V, theta).subs(theta, 0).subs(l2p, eq_l2p), (sp.diff(V, theta, 2) / 2).subs(theta, 0)]


PROBLEM = Problem(
    id="p5.14",
    title="Double pendulum with two springs on m1: V_exact and V_approx = c θ²",
    chapter=5,
    source="Wells, Problem 5.14 (Fig. 5-20)",
    system=system,
    answers=[
        PotentialEnergy(V_exact),
        Quantity("linear term (vanishes at equilibrium) and the θ² coefficient of V_approx", _taylor, [0, c_book]),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, r1: 1, r2: 1, k1: 10, k2: 10, x1: 0.5, y1: 0.5, x2: 0.5, y2: 0.5,
                                  l1p: 0.5, l2p: 0.5},
                          initial={theta: 0.1, phi: 0, theta.diff(t): 0, phi.diff(t): 0}, t_end=3),
    correction="Gravity is excluded as in the book's V. The anchors (x1, −y1), (−x2, −y2) are measured from m1's "
               "rest position; l_i = sqrt(x_i² + y_i²) are the spring lengths and l_i' the natural lengths. The "
               "θ-linear term vanishes under the horizontal equilibrium k1(l1 − l1')x1/l1 = k2(l2 − l2')x2/l2 "
               "(catalog, verified).",
)
