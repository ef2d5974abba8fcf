"""Wells, Example 10.6 — three bars hung by cords (Fig. 10-4) treated as a triple pendulum: m1 on cord r1,
m2 and m3 hanging from m1 on cords r2, r3. Determinant, frequencies and mode ratios."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, normal_modes, parameters, t
from lagrange.corpus import PotentialEnergy, Problem, Quantity, Simulation

th1, th2, th3 = coordinates("theta1 theta2 theta3")
m1, m2, m3, r1, r2, r3, g = parameters("m1 m2 m3 r1 r2 r3 g")
w = sp.Symbol("omega", positive=True)

X1, Y1 = r1 * sp.sin(th1), -r1 * sp.cos(th1)
system = System(
    [th1, th2, th3],
    bodies=[Particle(m1, (X1, Y1), name="m1"),
            Particle(m2, (X1 + r2 * sp.sin(th2), Y1 - r2 * sp.cos(th2)), name="m2"),
            Particle(m3, (X1 + r3 * sp.sin(th3), Y1 - r3 * sp.cos(th3)), name="m3")],
    V=g * (m1 * Y1 + m2 * (Y1 - r2 * sp.cos(th2)) + m3 * (Y1 - r3 * sp.cos(th3))),
    name="triple pendulum (three bars on cords)",
)
# Figure values are not in the text: reconstructed in the catalog from the book's normal-coordinate matrix
# (Ex. 10.10), CGS.
NUM = {m1: 250, m2: 200, m3: 300, r1: 15, r2: 12, r3: 20, g: 980}

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s, about={th1: 0, th2: 0, th3: 0})
    return _CACHE[id(s)]


def _monic_coefficients(s):
    x = sp.Symbol("x")  # x = ω²
    D = sp.expand(_lin(s).frequency_equation(w).subs(NUM)).subs(w, sp.sqrt(x))
    c = sp.Poly(D, x).all_coeffs()
    return [ci / c[0] for ci in c]


def _omegas_desc(s):
    return [sp.Float(v, 15) for v in normal_modes(_lin(s), NUM).omega[::-1]]


def _ratios(s):
    R = normal_modes(_lin(s), NUM).ratios(0)[:, ::-1]  # columns ω1 > ω2 > ω3, θ1 component = 1
    return [sp.Float(R[i, j], 15) for j in range(3) for i in (1, 2)]


qd = [th1.diff(t), th2.diff(t), th3.diff(t)]
BOOK_A = sp.Matrix([[(m1 + m2 + m3) * r1**2, m2 * r1 * r2, m3 * r1 * r3],
                    [m2 * r1 * r2, m2 * r2**2, 0],
                    [m3 * r1 * r3, 0, m3 * r3**2]])
BOOK_D = sp.Matrix([[(m1 + m2 + m3) * (r1 * w**2 - g) * r1, m2 * r1 * r2 * w**2, m3 * r1 * r3 * w**2],
                    [m2 * r1 * r2 * w**2, m2 * r2 * (r2 * w**2 - g), 0],
                    [m3 * r1 * r3 * w**2, 0, m3 * r3 * (r3 * w**2 - g)]]).det()
# book's cofactor columns (θ1, θ2, θ3) for ω = 18.71, 8.21, 5.72, as ratios to the θ1 entry
COF = [("2.78", "-4.54", "-2.43"), ("-0.88", "-5.70", "2.34"), ("2.75", "2.30", "4.16")]
BOOK_RATIOS = [sp.Rational(c[i]) / sp.Rational(c[0]) for c in COF for i in (1, 2)]

PROBLEM = Problem(
    id="ex10.6",
    title="Triple pendulum (three bars on cords): T, V, |a ω² − c|, ω = 18.71, 8.21, 5.72 and cofactor ratios",
    chapter=10,
    source="Wells, Example 10.6 (Fig. 10-4)",
    system=system,
    answers=[
        Quantity("a (T_approx)", lambda s: _lin(s).a, BOOK_A, description="T_approx (a matrix)"),
        PotentialEnergy(m1 * g * r1 * (1 - sp.cos(th1)) + m2 * g * (r1 * (1 - sp.cos(th1)) + r2 * (1 - sp.cos(th2)))
                        + m3 * g * (r1 * (1 - sp.cos(th1)) + r3 * (1 - sp.cos(th3)))),
        Quantity("c (V_approx)", lambda s: _lin(s).c,
                 sp.diag((m1 + m2 + m3) * g * r1, m2 * g * r2, m3 * g * r3), description="V_approx (c matrix)"),
        Quantity("|a ω² − c|", lambda s: _lin(s).frequency_equation(w), BOOK_D, description="frequency determinant"),
        Quantity("ω⁶ − 451 ω⁴ + 37616 ω² − 784327 (monic coefficients)", _monic_coefficients,
                 [1, -451, 37616, -784327], rtol=2e-3, description="numeric frequency equation (book rounding)"),
        Quantity("ω1, ω2, ω3", _omegas_desc, [sp.Float("18.71"), sp.Float("8.21"), sp.Float("5.72")], rtol=2e-2,
                 description="frequencies 18.71, 8.21, 5.72 rad/s (hand-computed, rtol 2e-2)"),
        Quantity("cofactor ratios θ2/θ1, θ3/θ1 per mode", _ratios, BOOK_RATIOS, rtol=2e-2,
                 description="mode ratios from the book's cofactor columns (rtol 2e-2)"),
    ],
    simulation=Simulation(params=NUM, initial={th1: 0.05, th2: -0.05, th3: 0.08, qd[0]: 0.0, qd[1]: 0.0, qd[2]: 0.0},
                          t_end=3.0),
    units="CGS (g, cm, s)",
    correction="Figure values are not printed; m = 250, 200, 300 g, r = 15, 12, 20 cm (g = 980) are the catalog's "
               "reconstruction from the book's normal-coordinate matrix (Ex. 10.10): they give ω⁶ − 450.8 ω⁴ + "
               "37615.67 ω² − 784326.67 (book rounds to integers: rtol 2e-3) and exact roots 18.698, 8.267, 5.729; "
               "the book's hand (Graeffe) value 8.21 is 0.7 % low and its cofactor ratio 6.48 vs exact 6.416 is 1 % "
               "off, hence rtol 2e-2 for the printed roots and ratios.",
)
