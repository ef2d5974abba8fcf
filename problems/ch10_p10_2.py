"""Wells, Problem 10.2 — double pendulum: frequencies, the equal case and its normal coordinates; the linear
solution is compared with the nonlinear motion at small amplitude."""

import math

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation, TrajectoryValues

th, ph = coordinates("theta phi")
m1, m2, r1, r2, g = parameters("m1 m2 r1 r2 g")
m, r = parameters("m r")

X1, Y1 = r1 * sp.sin(th), -r1 * sp.cos(th)
X2, Y2 = X1 + r2 * sp.sin(ph), Y1 - r2 * sp.cos(ph)
system = System(
    [th, ph],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    V=m1 * g * Y1 + m2 * g * Y2,
    name="double pendulum",
)
EQUAL = {m1: m, m2: m, r1: r, r2: r}


def _descending(values):
    """Sort symbolic roots by their value at a fixed sample point (the order of ± roots never changes)."""
    syms = sorted(set().union(*[sp.sympify(v).free_symbols for v in values]), key=lambda s: s.name)
    pt = {s: 1.3 + 0.17 * i for i, s in enumerate(syms)}
    return sorted(values, key=lambda v: -float(sp.sympify(v).subs(pt)))


_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s, about={th: 0, ph: 0})
    return _CACHE[id(s)]


def _omegas(s):
    return _descending([sp.sqrt(w2) for w2 in _lin(s).squared_frequencies()])


def _omega2_equal(s):
    return _descending([sp.simplify(w2.subs(EQUAL)) for w2 in _lin(s).squared_frequencies()])


def _T_equal(s):
    qd = sp.Matrix(s.coordinates).diff(t)
    return (qd.T * _lin(s).a.subs(EQUAL) * qd)[0] / 2


def _V_equal(s):
    q = sp.Matrix(s.coordinates)
    return (q.T * _lin(s).c.subs(EQUAL) * q)[0] / 2


root = sp.sqrt((m1 + m2) * (m2 * (r1 + r2) ** 2 + m1 * (r2 - r1) ** 2))
BOOK_OMEGA = [sp.sqrt((g * (m1 + m2) * (r1 + r2) + sgn * g * root) / (2 * m1 * r1 * r2)) for sgn in (1, -1)]
W1SQ, W2SQ = (2 + sp.sqrt(2)) * g / r, (2 - sp.sqrt(2)) * g / r
# book's normal coordinates, equal case (g1: ω1 mode with φ = −√2 θ; g2: ω2 mode with φ = +√2 θ)
G1 = sp.Rational(1, 2) * (sp.sqrt(4 - 2 * sp.sqrt(2)) * th - sp.sqrt(2 - sp.sqrt(2)) * ph) * sp.sqrt(m * r**2)
G2 = -sp.Rational(1, 2) * (sp.sqrt(4 + 2 * sp.sqrt(2)) * th + sp.sqrt(2 + sp.sqrt(2)) * ph) * sp.sqrt(m * r**2)

# Small-amplitude check: release in the book's slow mode φ = √2 θ (equal case, m = 1, r = 1, g = 9.8).
EPS = 1e-3
NUM = {m1: 1.0, m2: 1.0, r1: 1.0, r2: 1.0, g: 9.8}
W2 = math.sqrt((2 - math.sqrt(2)) * 9.8)
TIMES = [0.5, 1.0, 2.0, 3.0, 4.0]

PROBLEM = Problem(
    id="p10.2",
    title="Double pendulum: ω1,2, equal case ω² = (2 ± √2) g/r, normal coordinates; linear vs nonlinear motion",
    chapter=10,
    source="Wells, Problem 10.2",
    system=system,
    answers=[
        Quantity("ω1, ω2", _omegas, BOOK_OMEGA, description="frequencies ω1 > ω2"),
        Quantity("ω² (m1 = m2, r1 = r2)", _omega2_equal, [W1SQ, W2SQ],
                 description="equal case ω² = (2 ± √2) g/r"),
        Quantity("ω/(g/r)^½ equal case", lambda s: [sp.sqrt(v / (g / r)).evalf(30) for v in _omega2_equal(s)],
                 [sp.Float("1.85"), sp.Float("0.77")], rtol=1e-2,
                 description="printed ω1 = 1.85 (g/r)^½, ω2 = 0.77 (g/r)^½ (2-digit rounding)"),
        Quantity("T_approx = ½(g1'² + g2'²)", _T_equal, (G1.diff(t) ** 2 + G2.diff(t) ** 2) / 2,
                 description="normal coordinates diagonalize T (10.22)"),
        Quantity("V_approx = ½(ω1² g1² + ω2² g2²)", _V_equal, (W1SQ * G1**2 + W2SQ * G2**2) / 2,
                 description="normal coordinates diagonalize V (10.22)"),
        TrajectoryValues(
            NUM, {th: EPS, ph: math.sqrt(2) * EPS, th.diff(t): 0.0, ph.diff(t): 0.0}, TIMES,
            {th: [EPS * math.cos(W2 * tt) for tt in TIMES], ph: [math.sqrt(2) * EPS * math.cos(W2 * tt) for tt in TIMES]},
            tolerance=2e-8,
            description="nonlinear motion at 1e-3 rad follows the book's slow mode θ = ε cos ω2 t, φ = √2 θ",
        ),
    ],
    simulation=Simulation(params=NUM, initial={th: 0.3, ph: 0.0, th.diff(t): 0.0, ph.diff(t): 0.0}, t_end=10.0),
    correction="Overall sign of g2 is arbitrary (the book's choice kept). The small-amplitude trajectory values "
               "are the book's linear mode solution; tolerance 2e-8 rad = 2e-5 of the amplitude (the nonlinear "
               "frequency shift is O(ε²) ~ 1e-7 relative; a 1e-4 error in ω2 would already exceed it).",
)
