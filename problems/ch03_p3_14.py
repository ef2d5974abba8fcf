"""Wells, Problem 3.14 — bead on a rod fixed at angle θ to a vertical shaft spinning at ω, with a spring and gravity."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

r = coordinates("r")
m, g, k, w, theta, l, l0 = parameters("m g k omega theta l l_0")

# r along the rod from the shaft; the spring fills the rest of the rod, s = l − r (free length l0).
Z = r * sp.cos(theta)
system = System(
    [r],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(w * t), r * sp.sin(theta) * sp.sin(w * t), Z), name="bead")],
    forces=-k * ((l - r) - l0) * delta(l - r) - m * g * delta(Z),
    name="bead on a spinning inclined rod with a spring",
)


def _linear(s):
    eq = s.equations()[0]
    res = sp.expand(eq.lhs - eq.rhs)
    acc, vel = r.diff(t, 2), r.diff(t)
    mass = res.coeff(acc)
    rest = res.subs({acc: 0, vel: 0})
    return mass, rest


def equilibrium(s):
    _, rest = _linear(s)
    return sp.solve(rest, r)[0]


def period(s):
    mass, rest = _linear(s)
    stiff = sp.diff(rest, r)
    return 2 * sp.pi * sp.sqrt(mass / stiff)


PROBLEM = Problem(
    id="p3.14",
    title="Bead on a spinning inclined rod with spring: equation, equilibrium and period",
    chapter=3,
    source="Wells, Problem 3.14 (Fig. 3-9)",
    system=system,
    answers=[
        EquationsOfMotion(
            [sp.Eq(m * r.diff(t, 2) - m * r * w**2 * sp.sin(theta) ** 2,
                   k * (l - l0) - k * r - m * g * sp.cos(theta))],
            per_equation=True,
        ),
        Quantity("equilibrium r", equilibrium,
                 (k * (l - l0) - m * g * sp.cos(theta)) / (k - m * w**2 * sp.sin(theta) ** 2)),
        Quantity("period P", period, 2 * sp.pi * sp.sqrt(m / (k - m * w**2 * sp.sin(theta) ** 2))),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 50, w: 2, theta: 0.6, l: 2, l0: 1},
                          initial={r: 0.8, r.diff(t): 0}, t_end=5),
    ranges={"k": (8, 12), "omega": (0.5, 1.0), "theta": (0.2, 1.3)},
)
