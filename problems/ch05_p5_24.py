"""Wells, Problem 5.24 — for an autonomous L with non-conservative forces, d(T + V)/dt = Σ F_q q̇; checked on the
elastic pendulum (Ex. 5.1) in a viscous liquid (F_r = −a ṙ, F_θ = −a r² θ̇, Prob. 6.1)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, g, k, r0, a = parameters("m g k r_0 a")
rd, thd = r.diff(t), theta.diff(t)
system = System([r, theta], bodies=[Particle(m, (r * sp.sin(theta), -r * sp.cos(theta)))],
                V=k * (r - r0) ** 2 / 2 - m * g * r * sp.cos(theta), P=-a * (rd**2 + r**2 * thd**2) / 2,
                name="elastic pendulum with viscous drag")


def _energy_rate(s):
    """d(T + V)/dt with the accelerations taken from the derived equations of motion."""
    E = s.T + s.V
    dE = E.diff(t)
    acc = sp.solve([e.lhs - e.rhs for e in s.equations()], [r.diff(t, 2), theta.diff(t, 2)], dict=True)[0]
    return dE.subs(acc)


PROBLEM = Problem(
    id="p5.24",
    title="d(T + V)/dt = Σ F_q q̇ (elastic pendulum with viscous drag)",
    chapter=5,
    source="Wells, Problem 5.24 (identity; forces of Problem 6.1)",
    system=system,
    answers=[Quantity("d(T+V)/dt", _energy_rate, (-a * rd) * rd + (-a * r**2 * thd) * thd)],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1, a: 0.2},
                          initial={r: 1.2, theta: 0.5, rd: 0, thd: 0}, t_end=3),
    correction="The book states the identity in general; it is checked on this damped example (Σ F_q q̇ with the "
               "book's F_r = −a ṙ, F_θ = −a r² θ̇ of Problem 6.1).",
)
