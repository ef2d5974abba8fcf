"""Wells, Problem 4.2 — pulley (M, I, R) hung on a spring k, with masses m1 and m2 on a cord over it (Fig. 4-9)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Simulation

y, y1 = coordinates("y y1")
m1, m2, M, I, R, k, y0, g = parameters("m1 m2 M I R k y0 g")

# Downward positions: pulley centre y (spring relaxed at y = y0); masses at y + y1 and y − y1; pulley turns by y1/R.
d1, d2 = y + y1, y - y1
system = System(
    [y, y1],
    T=sp.Rational(1, 2) * I / R**2 * y1.diff(t) ** 2,
    bodies=[Particle(M, (0, y), name="pulley"), Particle(m1, (0, d1), name="m1"), Particle(m2, (0, d2), name="m2")],
    forces=-k * (y - y0) * delta(y) + g * (M * delta(y) + m1 * delta(d1) + m2 * delta(d2)),
    name="pulley on a spring",
)

A_, B_, C_ = m1 + m2 + M, m1 + m2 + I / R**2, m1 - m2
PROBLEM = Problem(
    id="p4.2",
    title="Pulley on a spring with two hanging masses: y is SHM, y1 accelerates uniformly",
    chapter=4,
    source="Wells, Problem 4.2",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m1 * (y.diff(t) + y1.diff(t)) ** 2 + sp.Rational(1, 2) * m2 * (y.diff(t) - y1.diff(t)) ** 2
                      + sp.Rational(1, 2) * M * y.diff(t) ** 2 + sp.Rational(1, 2) * (I / R**2) * y1.diff(t) ** 2),
        EquationsOfMotion([
            sp.Eq(y.diff(t, 2), -k * (B_ / (A_ * B_ - C_**2)) * (y - y0) + g),
            sp.Eq(B_ * y1.diff(t, 2) + C_ * y.diff(t, 2), C_ * g),
        ]),
    ],
    simulation=Simulation(params={m1: 2, m2: 1, M: 1, I: 0.1, R: 0.2, k: 100, y0: 1, g: 9.81},
                          initial={y: 1, y1: 0, y.diff(t): 0, y1.diff(t): 0}, t_end=1),
    correction="y0 is the spring's relaxed position of the pulley (implied by the printed answer).",
)
