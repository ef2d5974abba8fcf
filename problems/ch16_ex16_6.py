"""Wells, Example 16.6 — the spring pendulum of Ex. 16.2 with viscous drag a on the bob (power function)."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation

r, th = coordinates("r theta")
m, g, k, r0, a = parameters("m g k r_0 a")
rs, ths = sp.Symbol("r", real=True), sp.Symbol("theta", real=True)
pr, pth = sp.Symbol("p_r", real=True), sp.Symbol("p_theta", real=True)

system = System(
    [r, th],
    bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))],
    V=-m * g * r * sp.cos(th) + k * (r - r0) ** 2 / 2,
    P=-a * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2) / 2,
    name="spring pendulum with viscous drag",
)

# rdot, thetadot in terms of the momenta (book: p_r = m rdot, p_theta = m r^2 thetadot)
rd_p, thd_p = pr / m, pth / (m * rs**2)
F_r, F_th = -a * rd_p, -a * rs**2 * thd_p
dH_dr = -pth**2 / (m * rs**3) - m * g * sp.cos(ths) + k * (rs - r0)
dH_dth = m * g * rs * sp.sin(ths)

PROBLEM = Problem(
    id="ex16.6",
    title="Spring pendulum with viscous drag: canonical equations with F_q from P",
    chapter=16,
    source="Wells, Example 16.6",
    system=system,
    answers=[
        GeneralizedForces({r: -a * r.diff(t), th: -a * r**2 * th.diff(t)}),
        Quantity("H", lambda s: hamiltonian(s).H,
                 (pr**2 + pth**2 / rs**2) / (2 * m) - m * g * rs * sp.cos(ths) + k * (rs - r0) ** 2 / 2),
        Quantity("F_q in (q, p)", lambda s: hamiltonian(s).nonconservative, [F_r, F_th]),
        # (16.6): dH/dq = F_q - pdot  ->  pdot = F_q - dH/dq
        Quantity("pdot", lambda s: hamiltonian(s).pdot, [F_r - dH_dr, F_th - dH_dth]),
        Quantity("dH/dt (16.11)", lambda s: hamiltonian(s).energy_rate(), F_r * rd_p + F_th * thd_p),
        EquationsOfMotion(
            [
                sp.Eq(m * r.diff(t, 2) - m * r * th.diff(t) ** 2 - m * g * sp.cos(th) + k * (r - r0), -a * r.diff(t)),
                sp.Eq(m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t) + m * g * r * sp.sin(th),
                      -a * r**2 * th.diff(t)),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 40, r0: 1, a: 0.3},
                          initial={r: 1.2, th: 0.5, r.diff(t): 0, th.diff(t): 0}, t_end=5),
    correction="The book prints dH/dr = a rdot - pdot_r and dH/dtheta = a r^2 thetadot - pdot_theta; with "
    "P = -1/2 a(rdot^2 + r^2 thetadot^2) the forces are F_r = -a rdot, F_theta = -a r^2 thetadot, so (16.6) "
    "reads dH/dr = -a rdot - pdot_r (same for theta). Only the corrected signs reproduce the book's own EOM "
    "m rddot - m r thetadot^2 - m g cos(theta) + k(r - r0) = -a rdot.",
)
