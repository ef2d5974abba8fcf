"""Wells, Problem 10.14 — four equal masses in a line between two walls, five equal springs (Fig. 10-12)."""

import math

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, normal_modes, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

xs = coordinates("x1 x2 x3 x4")
m, k, d, l0 = parameters("m k d l0")  # d: spacing at equilibrium (walls 5d apart), l0: natural length

# exact spring energies with preload (d ≠ l0); x_i displacements from equilibrium
pos = [0] + [(i + 1) * d + xs[i] for i in range(4)] + [5 * d]
system = System(
    list(xs),
    bodies=[Particle(m, (pos[i + 1],), name=f"m{i + 1}") for i in range(4)],
    V=sum(sp.Rational(1, 2) * k * (pos[i + 1] - pos[i] - l0) ** 2 for i in range(5)),
    name="four masses between walls",
)
NUM = {m: 300.0, k: 2e4}


def _modes(s):
    return normal_modes(linearize(s), NUM)


def _shapes(s):
    R = _modes(s).ratios(0)  # columns ascending ω, first component 1
    return [sp.Float(R[i, j], 15) for j in range(4) for i in range(1, 4)]


PROBLEM = Problem(
    id="p10.14",
    title="Four masses, five springs between walls: V = k(Σx² − x1x2 − x2x3 − x3x4); frequencies, sine modes",
    chapter=10,
    source="Wells, Problem 10.14 (Fig. 10-12)",
    system=system,
    answers=[
        PotentialEnergy(k * (xs[0] ** 2 + xs[1] ** 2 + xs[2] ** 2 + xs[3] ** 2
                             - xs[0] * xs[1] - xs[1] * xs[2] - xs[2] * xs[3])),
        Quantity("ω_j (m = 300 g, k = 2e4)", lambda s: [sp.Float(v, 15) for v in _modes(s).omega],
                 [sp.Float(math.sqrt(2e4 / 300 * (2 - 2 * math.cos(j * math.pi / 5))), 15) for j in range(1, 5)],
                 rtol=1e-9, description="ω² = (k/m)(2 − 2cos(jπ/5)) = 5.046, 9.598, 13.211, 15.531 (derived)"),
        Quantity("mode ratios x_i/x_1", _shapes,
                 [sp.Float(math.sin(i * j * math.pi / 5) / math.sin(j * math.pi / 5), 15)
                  for j in range(1, 5) for i in range(2, 5)],
                 rtol=1e-9, description="sine modes x_i ∝ sin(ijπ/5) (derived)"),
    ],
    simulation=Simulation(params={**NUM, d: 10.0, l0: 8.0}, initial={**{q: 0.0 for q in xs}, xs[0]: 1.0,
                                                    **{q.diff(t): 0.0 for q in xs}}, t_end=3.0),
    units="CGS",
    correction="The book prints only V_exact; the frequencies and sine mode shapes are derived in the catalog "
               "(not printed in the book) for m = 300 g, k = 2e4 dyn/cm.",
)
