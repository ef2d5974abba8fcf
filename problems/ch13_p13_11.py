"""Wells, Problem 13.11 — m on a rod at a fixed angle θ to a vertical shaft turning at ω, with a spring:
relative equilibrium radius."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, static_equilibrium, t
from lagrange.corpus import Problem, Quantity, Simulation

r = coordinates("r")
m, k, l, l0, g, w, th = parameters("m k l l_0 g omega theta")
system = System([r], bodies=[Particle(m, (r * sp.sin(th) * sp.cos(w * t), r * sp.sin(th) * sp.sin(w * t),
                                          r * sp.cos(th)))],
                V=k * (r - (l - l0)) ** 2 / 2 + m * g * r * sp.cos(th), name="bead on a spring on a rotating rod")

PROBLEM = Problem(
    id="p13.11",
    title="Bead with a spring on a rod at angle θ to a shaft turning at ω: relative equilibrium r",
    chapter=13,
    source="Wells, Problem 13.11",
    system=system,
    answers=[
        Quantity("equilibrium r", lambda s: static_equilibrium(s, [r])[0][r],
                 (k * (l - l0) - m * g * sp.cos(th)) / (k - m * w**2 * sp.sin(th) ** 2)),
    ],
    simulation=Simulation(params={m: 1, k: 50, l: 1.5, l0: 0.5, g: 9.81, w: 3, th: 0.6},
                          initial={r: 0.8, r.diff(t): 0}, t_end=3),
    correction="The spring's unstretched position is r = l − l0 as in the catalog's implied V.",
)
