"""Wells, Sec. 10.8(b), Fig. 10-7(a) — pendulum (m2, length r) hung from a cart m1 sliding freely: a zero root;
the book's linear solution is compared with the nonlinear motion at small amplitude."""

import math

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation, TrajectoryValues

x1, th = coordinates("x1 theta")
m1, m2, r, g = parameters("m1 m2 r g")
w = sp.Symbol("omega", positive=True)

system = System(
    [x1, th],
    bodies=[Particle(m1, (x1, 0), name="cart"), Particle(m2, (x1 + r * sp.sin(th), -r * sp.cos(th)), name="bob")],
    V=-m2 * g * r * sp.cos(th),
    name="pendulum on a free cart",
)
BOOK_D = sp.Matrix([[(m1 + m2) * w**2, m2 * r * w**2], [m2 * r * w**2, m2 * r**2 * w**2 - m2 * g * r]]).det()

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s, about={x1: 0, th: 0})
    return _CACHE[id(s)]


def _ascending(s):
    vals = _lin(s).squared_frequencies()
    pt = {p: 1.3 + 0.17 * i for i, p in enumerate(sorted(set().union(*[sp.sympify(v).free_symbols for v in vals]),
                                                              key=lambda q: q.name))}
    return sorted(vals, key=lambda v: float(sp.sympify(v).subs(pt)))


# Book's linear solution (Ex. 4.4): x1 + m2 r θ/(m1+m2) = C1 t + C2, θ = A sin(ωt + δ); released from rest
# with θ = ε, x1 = 0: θ = ε cos ωt, x1 = m2 r (ε − θ)/(m1 + m2).
M1, M2, R, G = 2.0, 1.0, 0.5, 9.8
NUM = {m1: M1, m2: M2, r: R, g: G}
OM = math.sqrt((M1 + M2) * G / (M1 * R))
EPS = 1e-3
TIMES = [0.25, 0.6, 1.2, 2.0]

PROBLEM = Problem(
    id="sec10.8b",
    title="Pendulum on a freely sliding cart: D = |..| = 0, ω1 = 0, ω2 = [(m1+m2) g/(m1 r)]^½",
    chapter=10,
    source="Wells, Sec. 10.8(b) (Fig. 10-7(a)); Example 4.4",
    system=system,
    answers=[
        Quantity("|a ω² − c|", lambda s: _lin(s).frequency_equation(w), BOOK_D, description="frequency determinant"),
        Quantity("ω1², ω2²", _ascending, [sp.Integer(0), (m1 + m2) * g / (m1 * r)],
                 description="ω1 = 0, ω2² = (m1+m2) g/(m1 r)"),
        TrajectoryValues(
            NUM, {x1: 0.0, th: EPS, x1.diff(t): 0.0, th.diff(t): 0.0}, TIMES,
            {th: [EPS * math.cos(OM * tt) for tt in TIMES],
             x1: [M2 * R * EPS * (1 - math.cos(OM * tt)) / (M1 + M2) for tt in TIMES]},
            tolerance=1e-8,
            description="nonlinear motion at θ0 = 1e-3 follows the book's linear solution",
        ),
    ],
    simulation=Simulation(params=NUM, initial={x1: 0.0, th: 0.5, x1.diff(t): 0.2, th.diff(t): 0.0}, t_end=5.0),
    correction="The text prints ω2 = [(m1+m2) g/r]^½ and an expansion with m2 r² ω⁴ instead of m2² r² ω⁴; "
               "Example 4.4 gives ω = [(m1+m2) g/(m1 r)]^½, which the book's own determinant yields — corrected. "
               "Trajectory tolerance 1e-8 = 1e-5 of the amplitude (nonlinear corrections O(ε³)).",
)
