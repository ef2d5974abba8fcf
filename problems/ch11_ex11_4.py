"""Wells, Example 11.4 — bar pivoted at O with a mass on a spring at its end (horizontal plane): θ becomes
ignorable after the change of coordinate β = φ − θ."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, KineticEnergy, PotentialEnergy, Problem, Simulation

theta, beta, r = coordinates("theta beta r")
m, s_, I, k, r1 = parameters("m s I k r_1")

# Bar end at s(cosθ, sinθ); m at distance r from the end along direction φ = θ + β.
phi = theta + beta
system = System(
    [theta, beta, r],
    T=I * theta.diff(t) ** 2 / 2,
    bodies=[Particle(m, (s_ * sp.cos(theta) + r * sp.cos(phi), s_ * sp.sin(theta) + r * sp.sin(phi)))],
    V=k * (r - r1) ** 2 / 2,
    name="bar with a spring-mounted mass, coordinates (θ, β = φ − θ, r)",
)

thd, bd, rd = theta.diff(t), beta.diff(t), r.diff(t)
PROBLEM = Problem(
    id="ex11.4",
    title="Bar with spring-mounted mass: β = φ − θ makes θ ignorable",
    chapter=11,
    source="Wells, Example 11.4",
    system=system,
    answers=[
        KineticEnergy(m * rd**2 / 2 + (I + m * s_**2 + m * r**2 + 2 * m * r * s_ * sp.cos(beta)) * thd**2 / 2
                      + m * r**2 * bd**2 / 2 + m * s_ * rd * thd * sp.sin(beta)
                      + m * (r**2 + r * s_ * sp.cos(beta)) * thd * bd),
        PotentialEnergy(k * (r - r1) ** 2 / 2),
        ConservedMomenta({theta: (I + m * s_**2 + m * r**2 + 2 * m * r * s_ * sp.cos(beta)) * thd
                          + m * (r**2 * bd + r * s_ * bd * sp.cos(beta) + s_ * rd * sp.sin(beta))}),
    ],
    simulation=Simulation(params={m: 1, s_: 1, I: 2, k: 20, r1: 0.5},
                          initial={theta: 0, beta: 0.3, r: 0.6, theta.diff(t): 1.0, beta.diff(t): 0, r.diff(t): 0},
                          t_end=5),
    correction="OCR prints the cross term as 'msrθ̇ sinβ' (dot on r lost) and says θ is non-ignorable; the catalog "
               "re-derived m s ṙ θ̇ sinβ, and with β = φ − θ the coordinate θ is ignorable.",
)
