"""Wells, Problem 3.8 — disk (M, R, I) rolling without slipping, carrying a point mass m at distance r from its centre."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

theta = coordinates("theta")
M, R, I, m, r, g = parameters("M R I m r g")

# Centre at (Rθ, R) (rolling); m starts below the centre: at centre + (−r sinθ, −r cosθ).
Ym = R - r * sp.cos(theta)
system = System(
    [theta],
    T=sp.Rational(1, 2) * I * theta.diff(t) ** 2,
    bodies=[Particle(M, (R * theta, R), name="disk centre"), Particle(m, (R * theta - r * sp.sin(theta), Ym), name="m")],
    forces=-m * g * delta(Ym),
    name="rolling disk with an eccentric point mass",
)


def period(s):
    rest = {theta.diff(t): 0}
    K = -sp.diff(s.generalized_forces()[theta].subs(rest), theta).subs(theta, 0)
    Mt = s.mass_matrix[0, 0].subs(theta, 0)
    return 2 * sp.pi * sp.sqrt(Mt / K)


PROBLEM = Problem(
    id="p3.8",
    title="Rolling disk with an eccentric point mass: T and small-oscillation period",
    chapter=3,
    source="Wells, Problem 3.8",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * theta.diff(t) ** 2
                      * (M * R**2 + I + m * R**2 - 2 * m * r * R * sp.cos(theta) + m * r**2)),
        Quantity("period P", period, 2 * sp.pi * sp.sqrt((I + M * R**2 + m * (R - r) ** 2) / (m * g * r))),
    ],
    simulation=Simulation(params={M: 2, R: 0.5, I: 0.25, m: 0.5, r: 0.3, g: 9.81},
                          initial={theta: 0.5, theta.diff(t): 0}, t_end=5),
)
