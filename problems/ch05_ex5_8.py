"""Wells, Example 5.8 — mass on a string to the junction of two springs (Fig. 5-11), smooth horizontal plane."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

r, theta = coordinates("r theta")
m, k, s0, s1, r0 = parameters("m k s0 s1 r0")
l0 = sp.sqrt(s1**2 + s0**2)  # unstretched spring length

# The string pulls the junction a distance y = r - r0 beyond its equilibrium; each spring (anchors at
# (±s1, 0), junction at (0, s0 + y)) has length sqrt(s1^2 + (s0 + y)^2).
yv = r - r0
spring = sp.sqrt(s1**2 + (s0 + yv) ** 2)
system = System([r, theta], bodies=[Particle(m, (r * sp.cos(theta), r * sp.sin(theta)))],
                V=2 * k * (spring - l0) ** 2 / 2, name="mass on a string to two springs")


def _quadratic(sys):
    """Second-order Taylor polynomial of V about r = r0 (the constant dropped)."""
    d1 = sp.diff(sys.V, r).subs(r, r0)
    d2 = sp.diff(sys.V, r, 2).subs(r, r0)
    return sp.simplify(d1) * (r - r0) + sp.simplify(d2) / 2 * (r - r0) ** 2


PROBLEM = Problem(
    id="ex5.8",
    title="String to a junction of two springs: V ~ k (s0^2/l0^2)(r - r0)^2 for small stretch",
    chapter=5,
    source="Wells, Example 5.8",
    system=system,
    answers=[
        PotentialEnergy(k * yv**2 + 2 * k * s0 * yv - 2 * k * l0 * sp.sqrt(s1**2 + (s0 + yv) ** 2)),
        Quantity("quadratic approximation of V", _quadratic, k * (s0**2 / l0**2) * (r - r0) ** 2),
    ],
    simulation=Simulation(params={m: 1, k: 20, s0: 0.5, s1: 1, r0: 1},
                          initial={r: 1.05, theta: 0, r.diff(t): 0, theta.diff(t): 2}, t_end=3),
    correction="Valid while the string is taut (r > r0); the simulation starts with the string stretched and "
    "the centrifugal effect keeps it so.",
)
