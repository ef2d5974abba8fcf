"""Wells, Example 13.5 — particle m on disk D2, pivoted at distance s on disk D1 (Fig. 2-21): T in (θ1, θ2, r, α)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem

th1, th2, r, al = coordinates("theta1 theta2 r alpha")
m, s = parameters("m s")
ang = th1 + th2 + al
system = System([th1, th2, r, al],
                bodies=[Particle(m, (s * sp.cos(th1) + r * sp.cos(ang), s * sp.sin(th1) + r * sp.sin(ang)))],
                name="particle on a disk carried by a turning disk")

d1, d2, rd, ad = th1.diff(t), th2.diff(t), r.diff(t), al.diff(t)
T_book = m / 2 * (rd**2 + r**2 * ad**2 + 2 * s * d1 * sp.sin(th2 + al) * rd
                  + (2 * r**2 * (d1 + d2) + 2 * s * d1 * r * sp.cos(th2 + al)) * ad
                  + r**2 * (d1 + d2) ** 2 + 2 * s * r * d1 * (d1 + d2) * sp.cos(th2 + al) + s**2 * d1**2)

PROBLEM = Problem(
    id="ex13.5",
    title="Particle on disk D2 pivoted on turning disk D1: T in (θ1, θ2, r, α)",
    chapter=13,
    source="Wells, Example 13.5, equation (1) (Fig. 2-21)",
    system=system,
    answers=[KineticEnergy(T_book)],
    correction="No simulation: the disks are massless in the book's T, so the four coordinates of one particle "
               "give a singular mass matrix (θ1, θ2 are meant to be driven).",
)
