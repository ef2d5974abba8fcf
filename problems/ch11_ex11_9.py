"""Wells, Example 11.9 — spring pendulum hung from an arm l1 on a shaft driven at constant ψ̇ = ω."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, g, k, r1, l1, w = parameters("m g k r_1 l_1 omega")
r0, th0 = parameters("r0 theta0")

rho = l1 + r * sp.sin(theta)
system = System(
    [r, theta],
    bodies=[Particle(m, (rho * sp.cos(w * t), rho * sp.sin(w * t), -r * sp.cos(theta)))],
    V=-m * g * r * sp.cos(theta) + k * (r - r1) ** 2 / 2,
    name="spring pendulum on a driven shaft",
)


def _steady(s):
    d = s.derived
    at = {d.q[0]: r0, d.q[1]: th0, d.qd[0]: 0, d.qd[1]: 0}
    return [d.forcing[0].subs(at) / m, d.forcing[1].subs(at) / m]


def _lin(s):
    lin = linearize(s, about={r: r0, theta: th0})
    return [*(lin.a / m), *(lin.b / m), *(lin.c / m)]


c_sa = g * sp.sin(th0) - w**2 * (l1 * sp.cos(th0) + 2 * r0 * sp.sin(th0) * sp.cos(th0))
PROBLEM = Problem(
    id="ex11.9",
    title="Spring pendulum on a shaft driven at constant ω: equations, steady conditions, linearization",
    chapter=11,
    source="Wells, Example 11.9",
    system=system,
    answers=[
        EquationsOfMotion([
            sp.Eq(r.diff(t, 2) - r * theta.diff(t) ** 2 - w**2 * (l1 + r * sp.sin(theta)) * sp.sin(theta)
                  - g * sp.cos(theta) + k / m * (r - r1), 0),
            sp.Eq(r**2 * theta.diff(t, 2) + 2 * r * r.diff(t) * theta.diff(t)
                  - w**2 * (l1 + r * sp.sin(theta)) * r * sp.cos(theta) + r * g * sp.sin(theta), 0),
        ], per_equation=True),
        Quantity("steady conditions (forcing/m at rest; book: = 0)", _steady, [
            w**2 * (l1 + r0 * sp.sin(th0)) * sp.sin(th0) + g * sp.cos(th0) - k / m * (r0 - r1),
            w**2 * (l1 + r0 * sp.sin(th0)) * r0 * sp.cos(th0) - g * r0 * sp.sin(th0)]),
        Quantity("linearized a, b, c (divided by m)", _lin, [
            1, 0, 0, r0**2,
            0, 0, 0, 0,
            k / m - w**2 * sp.sin(th0) ** 2, c_sa,
            w**2 * (g / w**2 * sp.sin(th0) - l1 * sp.cos(th0) - 2 * r0 * sp.sin(th0) * sp.cos(th0)),
            w**2 * ((l1 + r0 * sp.sin(th0)) * r0 * sp.sin(th0) - r0**2 * sp.cos(th0) ** 2
                    + g * r0 / w**2 * sp.cos(th0))]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 100, r1: 0.5, l1: 0.3, w: 3.0},
                          initial={r: 0.6, theta: 0.3, r.diff(t): 0, theta.diff(t): 0}, t_end=3),
    correction="Linear terms are checked as printed (no gyroscopic terms: b = 0); the book does not use the "
               "steady conditions inside them.",
)
