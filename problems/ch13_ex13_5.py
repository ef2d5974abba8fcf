"""Wells, Example 13.5 and Problem 13.5 — particle m on disk D2, pivoted at distance s on disk D1 (Fig. 2-21):
T in (θ1, θ2, r, α), and the forces keeping r, α̇, θ̇1, θ̇2 constant."""

import sympy as sp

from lagrange import Particle, System, coordinates, driving_forces, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

th1, th2, r, al = coordinates("theta1 theta2 r alpha")
m, s, r0, w1, w2, w3 = parameters("m s r_0 omega_1 omega_2 omega_3")
ang = th1 + th2 + al
system = System([th1, th2, r, al],
                bodies=[Particle(m, (s * sp.cos(th1) + r * sp.cos(ang), s * sp.sin(th1) + r * sp.sin(ang)))],
                name="particle on a disk carried by a turning disk")

d1, d2, rd, ad = th1.diff(t), th2.diff(t), r.diff(t), al.diff(t)
T_book = m / 2 * (rd**2 + r**2 * ad**2 + 2 * s * d1 * sp.sin(th2 + al) * rd
                  + (2 * r**2 * (d1 + d2) + 2 * s * d1 * r * sp.cos(th2 + al)) * ad
                  + r**2 * (d1 + d2) ** 2 + 2 * s * r * d1 * (d1 + d2) * sp.cos(th2 + al) + s**2 * d1**2)


def _forces(sys_):
    f = driving_forces(sys_, {th1: w1 * t, th2: w2 * t, r: r0, al: w3 * t})
    return [f[r], f[al]]


PROBLEMS = [
    Problem(
        id="ex13.5",
        title="Particle on disk D2 pivoted on turning disk D1: T in (θ1, θ2, r, α)",
        chapter=13,
        source="Wells, Example 13.5, equation (1) (Fig. 2-21)",
        system=system,
        answers=[KineticEnergy(T_book)],
        simulation=Simulation(params={m: 1, s: 1, r0: 0.5, w1: 1, w2: 1, w3: 1},
                              initial={th1: 0, th2: 0, r: 0.5, al: 0, th1.diff(t): 1, th2.diff(t): 0.5,
                                       r.diff(t): 0, al.diff(t): 0.2}, t_end=3),
    ),
    Problem(
        id="p13.5",
        title="Particle on D2 with r constant and α̇, θ̇1, θ̇2 constant: f_r and F_α",
        chapter=13,
        source="Wells, Problem 13.5",
        system=system,
        answers=[
            Quantity("f_r, F_α = r f_α", _forces, [
                -m * r0 * (w1 + w2 + w3) ** 2 - m * s * w1**2 * sp.cos((w2 + w3) * t),
                m * s * r0 * w1**2 * sp.sin((w2 + w3) * t)]),
        ],
        correction="The book prints f_α = m s r ω1² sin(ω2+ω3)t, which has units of force×length: it is the "
                   "generalized force F_α = r f_α (δW = f_α r δα); the tangential force is m s ω1² sin(ω2+ω3)t. "
                   "Compared here as F_α (catalog, verified).",
    ),
]
