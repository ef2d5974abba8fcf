"""Wells, Problem 15.9 — equilibrium of the rotor capacitor of Problem 15.3 (Fig. 15-11):
C = C0 (1 - theta/pi), torsion rod k undistorted at theta1, battery E.

The system is Problem 15.3's (``ch15_p15_3``). dV/dQ = 0 gives Q0 = C(theta0) E; dV/dtheta = 0 then gives the
rod's twist, theta0 = theta1 - C0 E^2/(2 pi k)."""

import math

import sympy as sp
from lagrange_problems import ch15_p15_3 as p15_3
from lagrange_problems._common import variant

from lagrange import t
from lagrange.corpus import Quantity, Simulation

Q, th = p15_3.Q, p15_3.th
m, I, C0, k, th1, E, R = p15_3.m, p15_3.I, p15_3.C0, p15_3.k, p15_3.th1, p15_3.E, p15_3.R
_q, _th = sp.symbols("_q _th", real=True)


def _equilibrium(sys_):
    """Solve dV/dQ = 0 for Q (linear), then dV/dtheta = 0 for theta."""
    v = sys_.V.subs({Q: _q, th: _th})
    (q0,) = sp.solve(sp.diff(v, _q), _q)
    (th0,) = sp.solve(sp.simplify(sp.diff(v, _th).subs(_q, q0)), _th)
    return [th0, q0.subs(_th, th0)]


TH0 = th1 - C0 * E**2 / (2 * sp.pi * k)
_th0 = 1.5 - 1 / (4 * math.pi)  # theta0 with the numbers below

PROBLEM = variant(
    p15_3.PROBLEM,
    id="p15.9",
    title="Rotor capacitor of P15.3: equilibrium twist theta0 and charge Q0",
    source="Wells, Problem 15.9",
    answers=[
        Quantity("[theta0, Q0]", _equilibrium, [TH0, C0 * (1 - TH0 / sp.pi) * E],
                 description="equilibrium theta0, Q0"),
    ],
    simulation=Simulation(  # starts at the equilibrium theta0 = 1.5 - 1/(4 pi), Q0 = 1 - theta0/pi: stays there
        params={m: 1.0, I: 1.0, C0: 1.0, k: 2.0, th1: 1.5, E: 1.0, R: 0.3},
        initial={Q: 1 - _th0 / math.pi, th: _th0, Q.diff(t): 0.0, th.diff(t): 0.0},
        t_end=10,
    ),
    correction="The small-oscillation equations in theta - theta0, Q - Q0 are left to the reader (no printed form).",
)
