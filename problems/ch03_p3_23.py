"""Wells, Problem 3.23 — pendulum hung from a crank bar (angle α(t)) at distance s; spherical angles in bar axes."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EnergySplit, KineticEnergy, Problem, Simulation

theta, phi = coordinates("theta phi")
m, g, s, r, w = parameters("m g s r omega")

# The crank is driven: any α(t); here α = ω t (constant crank speed keeps the derivation fast). Geometry inferred in the catalog (figure not available):
# bob = s(cos α, sin α, 0) + r(sinθ cos(α−φ), sinθ sin(α−φ), −cosθ), r constant.
alpha = w * t
Z = -r * sp.cos(theta)
bob = Particle(m, (s * sp.cos(alpha) + r * sp.sin(theta) * sp.cos(alpha - phi),
                   s * sp.sin(alpha) + r * sp.sin(theta) * sp.sin(alpha - phi), Z), name="bob")
system = System([theta, phi], bodies=[bob], forces=-m * g * delta(Z), name="pendulum on a crank bar")

ad = alpha.diff(t)
th_d, ph_d = theta.diff(t), phi.diff(t)
T_book = sp.Rational(1, 2) * m * (
    s**2 * ad**2 + r**2 * th_d**2 + r**2 * (ad - ph_d) ** 2 * sp.sin(theta) ** 2
    - 2 * s * r * ad * th_d * sp.cos(theta) * sp.sin(phi)
    + 2 * s * r * ad * (ad - ph_d) * sp.sin(theta) * sp.cos(phi)
)

PROBLEM = Problem(
    id="p3.23",
    title="Pendulum hung from a driven crank bar: T in axes rotating with the bar",
    chapter=3,
    source="Wells, Problem 3.23",
    system=system,
    answers=[
        KineticEnergy(T_book),
        # Wells (2.55) pieces read off the printed T (A includes the 1/2).
        EnergySplit(
            A=sp.Matrix([[m * r**2 / 2, 0], [0, m * r**2 * sp.sin(theta) ** 2 / 2]]),
            B=[-m * s * r * ad * sp.cos(theta) * sp.sin(phi),
               -m * r**2 * ad * sp.sin(theta) ** 2 - m * s * r * ad * sp.sin(theta) * sp.cos(phi)],
            C=m / 2 * (s**2 * ad**2 + r**2 * ad**2 * sp.sin(theta) ** 2 + 2 * s * r * ad**2 * sp.sin(theta) * sp.cos(phi)),
        ),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, s: 0.5, r: 1, w: 1},
                          initial={theta: 0.4, phi: 0.1, theta.diff(t): 0, phi.diff(t): 0}, t_end=3),
    correction="Crank drive α(t) taken as ω t (the book leaves α(t) general; T is checked with α' = ω). The variable-r version has "
               "no printed answer and is not included. A, B, C are read off the printed T.",
)
