"""Wells, Example 15.6 — small oscillations of the capacitor transducer of Ex. 15.3 with a constant EMF E.

Equilibrium (dV/dQ = dV/dx = 0): x0 = Q0^2/(2 A k) and Q0 = A E/(s - x0) (a cubic for x0 when E is given; here
the equilibrium is labelled by Q0, and E = Q0 (s - x0)/A follows). With Q = Q0 + Q1, x = x0 + x1 and V expanded
to second order, Wells' approximate V and linear equations follow.

"ex15.6" checks the equilibrium and the second-order part of V on the full nonlinear system; "ex15.6-linear"
is the system in the deviations Q1, x1 whose V is that second-order expansion of the full V (computed below
from the full system, not typed from the book), checked against Wells' linear equations.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, MassMatrix, PotentialEnergy, Problem, Quantity, Simulation

Q, x, Q1, x1 = coordinates("Q x Q1 x1")
M, m, A, s, k, R, E, Q0 = parameters("M m A s k R E Q_0")
half = sp.Rational(1, 2)

system = System(
    [Q, x],
    T=half * M * Q.diff(t) ** 2 + half * m * x.diff(t) ** 2,
    V=half * Q**2 * (s - x) / A + half * k * x**2 - E * Q,
    P=-half * R * Q.diff(t) ** 2,
    name="capacitor transducer with constant E, Fig. 15-5",
)

_q, _x, _a, _b = sp.symbols("_q _x _a _b", real=True)


def _equilibrium(sys_):
    """Solve grad V = 0 for (x0, E) at the charge Q0."""
    v = sys_.V.subs({Q: _q, x: _x})
    sol = sp.solve([sp.diff(v, _q).subs(_q, Q0), sp.diff(v, _x).subs(_q, Q0)], [_x, E], dict=True)[0]
    return sol[_x], sol[E]


def _quadratic_part(sys_, a, b):
    """Second-order part of V about the equilibrium, in the deviations a (charge) and b (displacement)."""
    x0, E0 = _equilibrium(sys_)
    v = sys_.V.subs({Q: _q, x: _x}).subs(E, E0)
    H = sp.hessian(v, [_q, _x]).subs({_q: Q0, _x: x0})
    d = sp.Matrix([a, b])
    return sp.expand(half * (d.T * H * d)[0])


X0 = Q0**2 / (2 * A * k)  # book: x0 = 1/2 Q0^2/(A k)
BOOK_V = half * ((s - X0) / A * Q1**2 - 2 * Q0 / A * Q1 * x1 + k * x1**2)

linear = System(
    [Q1, x1],
    T=half * M * Q1.diff(t) ** 2 + half * m * x1.diff(t) ** 2,
    V=_quadratic_part(system, Q1, x1),
    P=-half * R * Q1.diff(t) ** 2,
    name="capacitor transducer, small oscillations about (Q0, x0)",
)

RANGES = {"Q_0": (0.2, 0.6), "s": (2.0, 3.0)}  # x0 = Q0^2/(2Ak) < s: plates apart
PARAMS = {M: 1.0, m: 1.0, A: 1.0, s: 1.0, k: 1.0, R: 0.1, Q0: 0.5}

PROBLEMS = [
    Problem(
        id="ex15.6",
        title="Capacitor transducer with constant E: equilibrium and second-order V",
        chapter=15,
        source="Wells, Example 15.6",
        system=system,
        answers=[
            # book: x0 = Q0^2/(2Ak), Q0 = A E/(s - x0)  <=>  E = Q0 (s - x0)/A
            Quantity("[x0, E]", lambda sy: list(_equilibrium(sy)), [X0, Q0 * (s - X0) / A],
                     description="equilibrium x0 and E for the charge Q0"),
            Quantity("V_approx", lambda sy: _quadratic_part(sy, Q1, x1), BOOK_V,
                     description="second-order V about equilibrium"),
        ],
        simulation=Simulation(
            params={M: 1.0, m: 1.0, A: 1.0, s: 1.0, k: 1.0, R: 0.1, E: 0.5 * (1.0 - 0.125)},  # the E whose equilibrium is Q0 = 0.5, x0 = 0.125
            initial={Q: 0.52, x: 0.12, Q.diff(t): 0.0, x.diff(t): 0.0},
            t_end=30,
        ),
        ranges=RANGES,
    ),
    Problem(
        id="ex15.6-linear",
        title="Capacitor transducer: linear equations of the small oscillations about (Q0, x0)",
        chapter=15,
        source="Wells, Example 15.6",
        system=linear,
        answers=[
            PotentialEnergy(BOOK_V),
            MassMatrix(sp.diag(M, m)),
            EquationsOfMotion(
                [
                    sp.Eq(M * Q1.diff(t, 2) + (s - X0) / A * Q1 - Q0 / A * x1, -R * Q1.diff(t)),
                    sp.Eq(m * x1.diff(t, 2) + k * x1 - Q0 / A * Q1, 0),
                ],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params=PARAMS, initial={Q1: 0.02, x1: -0.005, Q1.diff(t): 0.0, x1.diff(t): 0.0},
                              t_end=30),
        ranges=RANGES,
    ),
]
