"""Wells, Example 10.8 — linear "CO2 molecule" m1–k–m2–k–m1 on a line (Fig. 10-7(b)): a zero root."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

q1, q2, q3 = coordinates("q1 q2 q3")
m1, m2, k, l0 = parameters("m1 m2 k l0")
w = sp.Symbol("omega", positive=True)

# x_i positions, springs of natural length l0; q1 = x1 + l0, q2 = x2, q3 = x3 − l0 absorb the natural lengths.
x1, x2, x3 = q1 - l0, q2, q3 + l0
system = System(
    [q1, q2, q3],
    bodies=[Particle(m1, (x1,), name="O1"), Particle(m2, (x2,), name="C"), Particle(m1, (x3,), name="O2")],
    V=sp.Rational(1, 2) * k * ((x2 - x1 - l0) ** 2 + (x3 - x2 - l0) ** 2),
    name="linear triatomic molecule",
)
BOOK_D = sp.Matrix([[m1 * w**2 - k, k, 0], [k, m2 * w**2 - 2 * k, k], [0, k, m1 * w**2 - k]]).det()

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s)
    return _CACHE[id(s)]


def _ascending(vals):
    pt = {p: 1.3 + 0.17 * i for i, p in enumerate(sorted(set().union(*[sp.sympify(v).free_symbols for v in vals]),
                                                              key=lambda q: q.name))}
    return sorted(vals, key=lambda v: float(sp.sympify(v).subs(pt)))


def _omegas(s):
    return _ascending([sp.sqrt(v) for v in _lin(s).squared_frequencies()])


def _shapes(s):
    """Mode columns (q1 : q2 : q3) scaled to q3 = 1, for ω = 0, ω1, ω3 (null vectors of a ω² − c)."""
    lin = _lin(s)
    out = []
    for w2 in _ascending(lin.squared_frequencies()):
        v = (lin.a * w2 - lin.c).nullspace()[0]
        out += [sp.simplify(v[i] / v[2]) for i in range(3)]
    return out


PROBLEM = Problem(
    id="ex10.8",
    title="Linear CO2 molecule: |a ω² − c|, ω = 0, (k/m1)^½, [k(m2+2m1)/(m1 m2)]^½ and the mode columns",
    chapter=10,
    source="Wells, Example 10.8 (Fig. 10-7(b))",
    system=system,
    answers=[
        Quantity("|a ω² − c|", lambda s: _lin(s).frequency_equation(w), BOOK_D, description="frequency determinant"),
        Quantity("ω2 = 0 < ω1 < ω3", _omegas, [sp.Integer(0), sp.sqrt(k / m1), sp.sqrt(k * (m2 + 2 * m1) / (m1 * m2))],
                 description="frequencies (ascending: zero root, ω1, ω3)"),
        # book: q = vt + b (all equal); ω1: q1 = −c1k², q2 = 0, q3 = c1k²; ω3: c3k², −2c3k² m1/m2, c3k²
        Quantity("mode columns q1 : q2 : q3 (q3 = 1)", _shapes,
                 [1, 1, 1, -1, 0, 1, 1, -2 * m1 / m2, 1], description="mode columns from the book's solution"),
    ],
    simulation=Simulation(params={m1: 16.0, m2: 12.0, k: 100.0},
                          initial={q1: 0.1, q2: 0.0, q3: -0.05, q1.diff(t): 0.0, q2.diff(t): 0.3, q3.diff(t): 0.0},
                          t_end=5.0),
)
