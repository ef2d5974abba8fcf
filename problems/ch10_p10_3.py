"""Wells, Problem 10.3 — double torsion pendulum wall–k1–I1–k2–I2–k3–wall (Fig. 10-1(d))."""

import sympy as sp

from lagrange import System, coordinates, linearize, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

th1, th2 = coordinates("theta1 theta2")
I1, I2, k1, k2, k3 = parameters("I1 I2 k1 k2 k3")
I, k = parameters("I k")

system = System(
    [th1, th2],
    T=sp.Rational(1, 2) * (I1 * th1.diff(t) ** 2 + I2 * th2.diff(t) ** 2),
    V=sp.Rational(1, 2) * (k1 * th1**2 + k2 * (th2 - th1) ** 2 + k3 * th2**2),
    name="double torsion pendulum",
)
EQUAL = {I1: I, I2: I, k1: k, k2: k, k3: k}
a_, b_, c_ = k1 + k2, k2 + k3, k1 * k2 + k1 * k3 + k2 * k3
ROOT = sp.sqrt((I1 * b_ + I2 * a_) ** 2 - 4 * I1 * I2 * c_)
G1 = (th1 + th2) * sp.sqrt(I / 2)  # book's g1 (the k/I mode)
G2 = (th2 - th1) * sp.sqrt(I / 2)  # book's g2 (the 3k/I mode)

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s)
    return _CACHE[id(s)]


def _descending(vals):
    pt = {p: 1.3 + 0.17 * i for i, p in enumerate(sorted(set().union(*[sp.sympify(v).free_symbols for v in vals]),
                                                              key=lambda q: q.name))}
    return sorted(vals, key=lambda v: -float(sp.sympify(v).subs(pt)))


def _quad(s, M, v):
    v = sp.Matrix(v)
    return (v.T * M.subs(EQUAL) * v)[0] / 2


PROBLEM = Problem(
    id="p10.3",
    title="Double torsion pendulum: ω² formula, equal case ω² = 3k/I, k/I and normal coordinates",
    chapter=10,
    source="Wells, Problem 10.3 (Fig. 10-1(d))",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(I1 * th1.diff(t, 2) + (k1 + k2) * th1 - k2 * th2, 0),
                           sp.Eq(I2 * th2.diff(t, 2) + (k2 + k3) * th2 - k2 * th1, 0)], per_equation=True),
        Quantity("ω²", lambda s: _descending(_lin(s).squared_frequencies()),
                 [(I1 * b_ + I2 * a_ + ROOT) / (2 * I1 * I2), (I1 * b_ + I2 * a_ - ROOT) / (2 * I1 * I2)],
                 description="ω² = [I1 b + I2 a ± √((I1 b + I2 a)² − 4 I1 I2 c)]/(2 I1 I2)"),
        Quantity("ω² equal case", lambda s: _descending([sp.simplify(v.subs(EQUAL)) for v in _lin(s).squared_frequencies()]),
                 [3 * k / I, k / I], description="equal case ω² = 3k/I, k/I"),
        Quantity("T = ½(g1'² + g2'²)", lambda s: _quad(s, _lin(s).a, [th1.diff(t), th2.diff(t)]),
                 (G1.diff(t) ** 2 + G2.diff(t) ** 2) / 2, description="T in normal coordinates"),
        Quantity("V = ½(k/I g1² + 3k/I g2²)", lambda s: _quad(s, _lin(s).c, [th1, th2]),
                 (k / I * G1**2 + 3 * k / I * G2**2) / 2, description="V in normal coordinates"),
    ],
    simulation=Simulation(params={I1: 2.0, I2: 1.0, k1: 3.0, k2: 1.0, k3: 2.0},
                          initial={th1: 0.3, th2: 0.0, th1.diff(t): 0.0, th2.diff(t): 0.0}, t_end=10.0),
    correction="The book lists g1 = (θ1+θ2)(I/2)^½ and g2 = (θ2−θ1)(I/2)^½ opposite to its ω1, ω2 order: "
               "(θ1+θ2) is the k/I mode and (θ2−θ1) the 3k/I mode (catalog note); V is checked with that pairing.",
)
