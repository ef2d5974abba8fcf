"""Wells, Problem 10.18 — m1 and m2 on tracks, two wheels (I, r) rolling on m1, m3 on springs (Fig. 10-14):
a double zero root and one oscillation frequency."""

import sympy as sp

from lagrange import System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x1, q2, x3 = coordinates("x1 q2 x3")  # q2 = const − x2
m1, m2, m3, I, r, k = parameters("m1 m2 m3 I r k")
w = sp.Symbol("omega", positive=True)
# The figure is not in the text: T and V as printed in the book (catalog: verified).
system = System(
    [x1, q2, x3],
    T=sp.Rational(1, 2) * ((m1 + m2) * x1.diff(t) ** 2 + (m2 + 2 * I / r**2) * q2.diff(t) ** 2
                           + m3 * x3.diff(t) ** 2 - 2 * m2 * x1.diff(t) * q2.diff(t)),
    V=sp.Rational(1, 2) * k * (x1**2 + q2**2 + x3**2 - 2 * x1 * x3 + 2 * x3 * q2 - 2 * x1 * q2),
    name="carts, rolling wheels and a spring-held mass",
)

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s)
    return _CACHE[id(s)]


def _zero_multiplicity(s):
    """Multiplicity of the root ω² = 0 of |a ω² − c| (lowest power of ω² present)."""
    x = sp.Symbol("x")
    D = sp.Poly(sp.expand((_lin(s).a * x - _lin(s).c).det()), x)
    return sp.Integer(min(mon[0] for mon in D.monoms()))


def _nonzero(s):
    return [v for v in _lin(s).squared_frequencies() if sp.simplify(v) != 0]


C2 = 2 * I / r**2
PROBLEM = Problem(
    id="p10.18",
    title="Carts and rolling wheels: double zero root; m3[m1m2 + (m1+m2)2I/r²] ω² = k[m1m2 + m1m3 + (m1+m2+m3)2I/r²]",
    chapter=10,
    source="Wells, Problem 10.18 (Fig. 10-14)",
    system=system,
    answers=[
        Quantity("multiplicity of ω² = 0", _zero_multiplicity, sp.Integer(2), description="D has a double zero root"),
        Quantity("non-zero ω²", _nonzero, [k * (m1 * m2 + m1 * m3 + (m1 + m2 + m3) * C2) / (m3 * (m1 * m2 + (m1 + m2) * C2))],
                 description="the oscillation frequency"),
    ],
    simulation=Simulation(params={m1: 2.0, m2: 1.0, m3: 1.5, I: 0.1, r: 0.2, k: 20.0},
                          initial={x1: 0.0, q2: 0.0, x3: 0.1, x1.diff(t): 0.0, q2.diff(t): 0.0, x3.diff(t): 0.0},
                          t_end=5.0),
    correction="Fig. 10-14 is not in the text; the book's T and V (q2 = const − x2) are used as the model.",
)
