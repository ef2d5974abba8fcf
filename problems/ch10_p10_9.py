"""Wells, Problem 10.9 — pulley (I, R) with m1 on one rope end and a spring k carrying m2 on the other
(Fig. 10-7(d), model reconstructed): a zero root and a drift (g/2M)(m1 − m2) t²."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

y, s = coordinates("y s")  # y: m1 down; s: spring extension (m2 hangs below the rising rope end)
m1, m2, I, R, k, g = parameters("m1 m2 I R k g")
system = System(
    [y, s],
    T=sp.Rational(1, 2) * I * (y.diff(t) / R) ** 2,
    bodies=[Particle(m1, (y,), name="m1"), Particle(m2, (s - y,), name="m2")],
    V=sp.Rational(1, 2) * k * s**2 - m1 * g * y - m2 * g * (s - y),
    name="pulley, mass and spring-hung mass",
)
MT = m1 + m2 + I / R**2

_CACHE = {}


def _lin(sy):
    if id(sy) not in _CACHE:
        _CACHE[id(sy)] = linearize(sy, about={y: 0, s: 0})
    return _CACHE[id(sy)]


def _ascending(sy):
    vals = _lin(sy).squared_frequencies()
    pt = {p: 1.3 + 0.17 * i for i, p in enumerate(sorted(set().union(*[sp.sympify(v).free_symbols for v in vals]),
                                                              key=lambda q: q.name))}
    return sorted(vals, key=lambda v: float(sp.sympify(v).subs(pt)))


def _drift(sy):
    """Coefficient of t² of the zero mode: with u the null vector of c, u'a q'' = u'F, so the zero-mode
    coordinate accelerates uniformly at u'F/(u'a u); y's t² coefficient is half of that."""
    lin = _lin(sy)
    u = lin.c.nullspace()[0]
    u = u / u[0]  # normalized to unit y component
    return sp.simplify((u.T * lin.forcing)[0] / (u.T * lin.a * u)[0] / 2)


PROBLEM = Problem(
    id="p10.9",
    title="Pulley and spring system: ω1 = 0, ω2² = k(m1 + m2 + I/R²)/[m2(m1 + I/R²)], drift (g/2M)(m1 − m2) t²",
    chapter=10,
    source="Wells, Problem 10.9 (Fig. 10-7(d))",
    system=system,
    answers=[
        Quantity("ω1², ω2²", _ascending, [sp.Integer(0), k * MT / (m2 * (m1 + I / R**2))],
                 description="ω1 = 0, ω2² = k(m1+m2+I/R²)/(m2(m1+I/R²))"),
        Quantity("t² coefficient of y", _drift, g * (m1 - m2) / (2 * MT),
                 description="y = A cos(ω2 t + φ) + (g/2M)(m1 − m2) t² + Bt + C, M = m1 + m2 + I/R²"),
    ],
    simulation=Simulation(params={m1: 1.0, m2: 0.8, I: 0.02, R: 0.1, k: 50.0, g: 9.8},
                          initial={y: 0.0, s: 0.15, y.diff(t): 0.0, s.diff(t): 0.0}, t_end=3.0),
    correction="Fig. 10-7(d) is not described in the text: the model (m1 on a rope over the pulley, the other "
               "rope end carrying a spring k from which m2 hangs; y = m1 down, s = spring extension) is the "
               "catalog's reconstruction, which reproduces both printed results exactly. The system has no static "
               "equilibrium unless m1 = m2; it is linearized about y = s = 0 with the constant force kept.",
)
