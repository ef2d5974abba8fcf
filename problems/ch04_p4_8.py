"""Wells, Problem 4.8 — the Problem 4.7 cart with the block forced along the incline, q = A sin ωt (f absent)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, KineticEnergy, Problem, Simulation

x, q = coordinates("x q")
M1, M, r, I, m, th, y0, A, w = parameters("M1 M r I m theta y0 A omega")

Mt = M1 + 4 * M + 4 * I / r**2
# The block's motion along the incline is prescribed; the forces driving it do no virtual work (t frozen),
# and nothing else acts along x.
system = System(
    [x],
    T=sp.Rational(1, 2) * Mt * x.diff(t) ** 2,
    bodies=[Particle(m, (x - q * sp.cos(th), y0 - q * sp.sin(th)), name="block")],
    prescribed={q: A * sp.sin(w * t)},
    name="cart with a driven block",
)

PROBLEM = Problem(
    id="p4.8",
    title="Cart with a block driven along its incline: T and conserved x-momentum",
    chapter=4,
    source="Wells, Problem 4.8",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (Mt + m) * x.diff(t) ** 2
                      + sp.Rational(1, 2) * m * (-2 * x.diff(t) * A * w * sp.cos(w * t) * sp.cos(th)
                                                 + A**2 * w**2 * sp.cos(w * t) ** 2)),
        ConservedMomenta({x: (Mt + m) * x.diff(t) - m * A * w * sp.cos(th) * sp.cos(w * t)}),
    ],
    simulation=Simulation(params={M1: 5, M: 0.5, r: 0.2, I: 0.01, m: 1, th: 0.5, A: 0.2, w: 3},
                          initial={x: 0, x.diff(t): 0}, t_end=3),
)
