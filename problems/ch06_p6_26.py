"""Wells, Problem 6.26 — three masses with springs, viscous contacts and a cubic dashpot (Fig. 6-17): P with springs."""


from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PowerFunction, Problem, Simulation

x1, x2, x3 = coordinates("x1 x2 x3")
m1, m2, m3, a1, a2, a3, b, k1, k2, k3, l1, l2, l3 = parameters("m1 m2 m3 a1 a2 a3 b k1 k2 k3 l1 l2 l3")

# Springs (lengths x1, x2 - x1, x3 - x2; natural lengths l_i) enter P as their power (6.18), not V.
springs = [(k1, l1, x1), (k2, l2, x2 - x1), (k3, l3, x3 - x2)]
P_springs = sum(k * (l - s) * s.diff(t) for k, l, s in springs)
P_drag = (-(a1 * x1.diff(t) ** 2 + a2 * (x2.diff(t) - x1.diff(t)) ** 2 + a3 * (x3.diff(t) - x1.diff(t)) ** 2) / 2
          - b * (x3.diff(t) - x2.diff(t)) ** 4 / 4)
system = System([x1, x2, x3], bodies=[Particle(m, (x,)) for m, x in ((m1, x1), (m2, x2), (m3, x3))],
                P=P_drag + P_springs, name="three masses, springs and dashpots")

d1, d2, d3 = x1.diff(t), x2.diff(t), x3.diff(t)
PROBLEM = Problem(
    id="p6.26",
    title="Three masses with springs, viscous contacts and a cubic dashpot: the power function P",
    chapter=6,
    source="Wells, Problem 6.26",
    system=system,
    answers=[PowerFunction(-(a1 * d1**2 + a2 * (d2 - d1) ** 2 + a3 * (d3 - d1) ** 2) / 2 - b * (d3 - d2) ** 4 / 4
                           + k1 * (l1 - x1) * d1 + k2 * (l2 + x1 - x2) * (d2 - d1) + k3 * (l3 + x2 - x3) * (d3 - d2))],
    simulation=Simulation(params={m1: 1, m2: 1, m3: 1, a1: 0.2, a2: 0.1, a3: 0.1, b: 0.05, k1: 10, k2: 10, k3: 10,
                                  l1: 1, l2: 1, l3: 1},
                          initial={x1: 1.1, x2: 2, x3: 3.2, x1.diff(t): 0, x2.diff(t): 0.5, x3.diff(t): 0}, t_end=5),
    correction="Figure 6-17 is not available; the spring lengths x1, x2 - x1, x3 - x2 are read from the printed P.",
)
