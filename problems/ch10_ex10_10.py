"""Wells, Example 10.10 — normal coordinates of the triple pendulum of Example 10.6 (Fig. 10-4)."""

import sympy as sp

from lagrange import Particle, System, coordinates, linearize, normal_modes, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th1, th2, th3 = coordinates("theta1 theta2 theta3")
m1, m2, m3, r1, r2, r3, g = parameters("m1 m2 m3 r1 r2 r3 g")

X1, Y1 = r1 * sp.sin(th1), -r1 * sp.cos(th1)
system = System(
    [th1, th2, th3],
    bodies=[Particle(m1, (X1, Y1), name="m1"),
            Particle(m2, (X1 + r2 * sp.sin(th2), Y1 - r2 * sp.cos(th2)), name="m2"),
            Particle(m3, (X1 + r3 * sp.sin(th3), Y1 - r3 * sp.cos(th3)), name="m3")],
    V=g * (m1 * Y1 + m2 * (Y1 - r2 * sp.cos(th2)) + m3 * (Y1 - r3 * sp.cos(th3))),
    name="triple pendulum (three bars on cords)",
)
NUM = {m1: 250, m2: 200, m3: 300, r1: 15, r2: 12, r3: 20, g: 980}  # catalog reconstruction (see Ex. 10.6)
# book's cofactor columns d_rs (θ1, θ2, θ3) for ω = 18.71, 8.21, 5.72
COF = [("2.78", "-4.54", "-2.43"), ("-0.88", "-5.70", "2.34"), ("2.75", "2.30", "4.16")]
BOOK_G = [("126.29", "-43.82", "-59.26"), ("-108.88", "-149.41", "154.58"), ("379.42", "67.70", "307.59")]
# each normal coordinate's overall sign is arbitrary: the book's choice is + , − , + for the θ1 coefficient
BOOK_SIGN = [1, -1, 1]

_CACHE = {}


def _lin(s):
    if id(s) not in _CACHE:
        _CACHE[id(s)] = linearize(s, about={th1: 0, th2: 0, th3: 0})
    return _CACHE[id(s)]


def _inverse_c(s):
    """c_s^{-1} = [Σ a_rl d_rs d_ls]^{1/2} (10.21) with the library's a and the book's cofactor columns."""
    a = _lin(s).a.subs(NUM)
    return [sp.sqrt((sp.Matrix([sp.Rational(x) for x in col]).T * a * sp.Matrix([sp.Rational(x) for x in col]))[0])
            for col in COF]


def _G(s):
    modes = normal_modes(_lin(s), NUM)
    G = modes.shapes.T @ modes.a  # g = Φᵀ a s (10.25), rows ascending in ω
    out = []
    for row, sign in zip(G[::-1], BOOK_SIGN):
        row = row * sign * (1 if row[0] > 0 else -1)  # θ1 coefficient gets the book's sign
        out += [sp.Float(v, 15) for v in row]
    return out


def _TV_diagonal(s):
    """T = ½Σġ², V = ½Σω²g²: Φᵀ a Φ = 1 and Φᵀ c Φ = diag(ω²) (10.22); returns the largest deviation."""
    import numpy as np
    mo = normal_modes(_lin(s), NUM)
    e1 = np.abs(mo.shapes.T @ mo.a @ mo.shapes - np.eye(3)).max()
    e2 = np.abs(mo.shapes.T @ mo.c @ mo.shapes - np.diag(mo.omega**2)).max() / mo.omega.max() ** 2
    return sp.Integer(int(max(e1, e2) < 1e-9))


PROBLEM = Problem(
    id="ex10.10",
    title="Triple pendulum: normalizing factors c_s^{-1} and normal coordinates g1, g2, g3",
    chapter=10,
    source="Wells, Example 10.10 (system of Example 10.6)",
    system=system,
    answers=[
        Quantity("c_s^{-1}", _inverse_c, [sp.Float("694.03"), sp.Float("1309.18"), sp.Float("2478.69")], rtol=2e-2,
                 description="normalizing factors c_s^{-1} (10.21) from the book's cofactors (rtol 2e-2)"),
        Quantity("g_s coefficients of θ1, θ2, θ3", _G, [sp.Float(x) for row in BOOK_G for x in row], rtol=2e-2,
                 description="normal coordinates g_s = c_s Σ a_rl d_ls θ_r (10.25), rtol 2e-2"),
        Quantity("T = ½Σġ², V = ½Σω²g²", _TV_diagonal, sp.Integer(1), description="(10.22) diagonal T and V"),
    ],
    simulation=Simulation(params=NUM, initial={th1: 0.05, th2: -0.05, th3: 0.08, th1.diff(t): 0.0,
                                               th2.diff(t): 0.0, th3.diff(t): 0.0}, t_end=3.0),
    units="CGS (g, cm, s)",
    correction="Parameters are the catalog's reconstruction (m = 250, 200, 300 g; r = 15, 12, 20 cm). With them "
               "c_1^{-1}, c_2^{-1} agree to all printed digits but the book's c_3^{-1} = 2478.69 is ~1 % off "
               "(exact 2453.5), and the g rows agree within ~1 % (Graeffe roots, ω2 = 8.21 vs 8.267): rtol 2e-2. "
               "The sign of each g_s is arbitrary; the book's signs are imposed on the θ1 coefficients.",
)
