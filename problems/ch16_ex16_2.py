"""Wells, Example 16.2 — pendulum bob on a spring (r, θ) in a vertical plane: Hamilton's equations."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

r, th = coordinates("r theta")
m, g, k, r0 = parameters("m g k r_0")
rs, ths = sp.Symbol("r", real=True), sp.Symbol("theta", real=True)
pr, pth = sp.Symbol("p_r", real=True), sp.Symbol("p_theta", real=True)

# θ from the downward vertical; V = -m g r cosθ + ½k(r - r0)^2.
system = System([r, th], bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
                V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2, name="spring pendulum")

PROBLEM = Problem(
    id="ex16.2",
    title="Spring pendulum: p_r, p_theta, H and the canonical equations",
    chapter=16,
    source="Wells, Example 16.2",
    system=system,
    answers=[
        Quantity("momenta", lambda s: hamiltonian(s).momenta, [m * r.diff(t), m * r**2 * th.diff(t)]),
        Quantity("H", lambda s: hamiltonian(s).H,
                 (pr**2 + pth**2 / rs**2) / (2 * m) - m * g * rs * sp.cos(ths) + k * (rs - r0) ** 2 / 2),
        # book: dH/dr = -p_theta^2/(m r^3) - m g cos(theta) + k(r - r0) = -pdot_r ; dH/dtheta = m g r sin(theta) = -pdot_theta
        Quantity("pdot = -dH/dq", lambda s: hamiltonian(s).pdot,
                 [-(-pth**2 / (m * rs**3) - m * g * sp.cos(ths) + k * (rs - r0)), -(m * g * rs * sp.sin(ths))]),
        Quantity("qdot = dH/dp", lambda s: hamiltonian(s).qdot, [pr / m, pth / (m * rs**2)]),
        EquationsOfMotion(
            [
                sp.Eq(m * r.diff(t, 2) - m * r * th.diff(t) ** 2 - m * g * sp.cos(th) + k * (r - r0), 0),
                sp.Eq(m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t) + m * g * r * sp.sin(th), 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1},
                          initial={r: 1.2, th: 0.5, r.diff(t): 0, th.diff(t): 0}, t_end=5),
)
