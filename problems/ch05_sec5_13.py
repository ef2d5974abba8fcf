"""Wells, Sec. 5.13 — the energy integral T + V = E (5.16) for an autonomous conservative system (Ex. 5.1)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import JacobiIntegral, Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, g, k, r0 = parameters("m g k r0")

bob = (r * sp.sin(theta), -r * sp.cos(theta))
system = System([r, theta], bodies=[Particle(m, bob)], V=k * (r - r0) ** 2 / 2 + m * g * bob[1],
                name="elastic pendulum")

E = m * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2) / 2 + k * (r - r0) ** 2 / 2 - m * g * r * sp.cos(theta)


def _sum_qd_dL_dqd(s):
    # (5.15): sum qd dL/dqd - L must equal E; T is homogeneous quadratic so this is 2T - (T - V) = T + V.
    L = s.T - s.V
    return sum(q.diff(t) * sp.diff(L, q.diff(t)) for q in s.coordinates) - L


PROBLEM = Problem(
    id="sec5.13",
    title="Energy integral: sum qd dL/dqd = L + E, i.e. T + V = E, for the elastic pendulum",
    chapter=5,
    source="Wells, Sec. 5.13, eqs. (5.15)-(5.16)",
    system=system,
    answers=[
        JacobiIntegral(E),
        Quantity("sum qd dL/dqd - L (5.15)", _sum_qd_dL_dqd, E),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1},
                          initial={r: 1.2, theta: 0.6, r.diff(t): 0, theta.diff(t): 0.5}, t_end=20),
)
