"""Wells, Sec. 10.8(a) — mass on a smooth horizontal table held by three identical springs at 120° (Fig. 10-6):
a double root ω1 = ω2; the linear motion is compared with the exact spring model at small amplitude."""

import math

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, normal_modes, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation, TrajectoryValues

x, y = coordinates("x y")
m, k, l, l0 = parameters("m k l l0")  # l: equilibrium length, l0 (Wells' l'): unstretched length
w = sp.Symbol("omega", positive=True)

# anchors at distance l from the equilibrium position, at 90°, 210°, 330°; exact spring energy
anchors = [(l * sp.cos(a), l * sp.sin(a)) for a in (sp.pi / 2, sp.pi / 2 + 2 * sp.pi / 3, sp.pi / 2 + 4 * sp.pi / 3)]
V = sum(sp.Rational(1, 2) * k * (sp.sqrt((x - ax) ** 2 + (y - ay) ** 2) - l0) ** 2 for ax, ay in anchors)
system = System([x, y], bodies=[Particle(m, (x, y))], V=V, name="mass held by three springs at 120°")

STIFF = k * (3 - sp.Rational(3, 2) * l0 / l)
NUM = {m: 100.0, k: 2000.0, l: 10.0, l0: 6.0}
OMEGA = math.sqrt(2000.0 * (3 - 1.5 * 6.0 / 10.0) / 100.0)
EPS = 1e-4
TIMES = [0.3, 0.7, 1.5, 2.5]

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s, about={x: 0, y: 0})
    return _CACHE[id(s)]


PROBLEM = Problem(
    id="sec10.8a",
    title="Mass on three springs at 120°: V = ½k(3 − 1.5 l'/l)(x² + y²), ω1 = ω2 = [k(3 − 1.5 l'/l)/m]^½",
    chapter=10,
    source="Wells, Sec. 10.8(a) (Fig. 10-6)",
    system=system,
    answers=[
        Quantity("c (V_approx)", lambda s: _lin(s).c, sp.diag(STIFF, STIFF), description="V_approx (c matrix)"),
        Quantity("|a ω² − c|", lambda s: _lin(s).frequency_equation(w), (m * w**2 - STIFF) ** 2,
                 description="frequency determinant: a double root"),
        Quantity("ω1², ω2² (distinct roots)", lambda s: _lin(s).squared_frequencies(), [STIFF / m],
                 description="one distinct root ω² = k(3 − 1.5 l'/l)/m"),
        Quantity("ω1, ω2 (numeric eigen-solver)", lambda s: [sp.Float(v, 15) for v in normal_modes(_lin(s), NUM).omega],
                 [sp.Float(OMEGA, 15)] * 2, rtol=1e-9, description="ω1 = ω2 from the generalized eigenproblem"),
        TrajectoryValues(
            NUM, {x: EPS, y: 0.5 * EPS, x.diff(t): 0.0, y.diff(t): 0.0}, TIMES,
            {x: [EPS * math.cos(OMEGA * tt) for tt in TIMES], y: [0.5 * EPS * math.cos(OMEGA * tt) for tt in TIMES]},
            tolerance=1e-8,
            description="exact springs at 1e-4 cm amplitude follow x = ε cos ωt, y = ε/2 cos ωt (any direction)",
        ),
    ],
    simulation=Simulation(params=NUM, initial={x: 1.0, y: 0.5, x.diff(t): 0.0, y.diff(t): 2.0}, t_end=5.0),
    ranges={"l": (3.0, 4.0), "l0": (1.0, 2.0)},
    units="CGS in the numeric checks",
    correction="OCR prints 3 − 1.5l/l; l' (unstretched length) over l (equilibrium length) is meant — otherwise "
               "the factor would be the constant 1.5. The trajectory values are the book's linear solution; "
               "tolerance 1e-8 cm = 1e-4 of the amplitude (quadratic spring-geometry terms give ~ε²/l ~ 1e-9).",
)
