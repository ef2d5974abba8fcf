"""Wells, Problem 15.9 — equilibrium of the rotor capacitor of Problem 15.3 (Fig. 15-11):
C = C0 (1 - theta/pi), torsion rod k undistorted at theta1, battery E.

dV/dQ = 0 gives Q0 = C(theta0) E; dV/dtheta = 0 then gives the rod's twist, theta0 = theta1 - C0 E^2/(2 pi k)."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

Q, th = coordinates("Q theta")
m, I, C0, k, th1, E, R = parameters("m I C_0 k theta_1 E R")
half = sp.Rational(1, 2)

system = System(
    [Q, th],
    T=half * m * Q.diff(t) ** 2 + half * I * th.diff(t) ** 2,
    V=-E * Q + Q**2 / (2 * C0 * (1 - th / sp.pi)) + half * k * (th1 - th) ** 2,
    P=-half * R * Q.diff(t) ** 2,
    name="rotor capacitor on a torsion rod, Fig. 15-11",
)

_q, _th = sp.symbols("_q _th", real=True)


def _equilibrium(sys_):
    """Solve dV/dQ = 0 for Q (linear), then dV/dtheta = 0 for theta."""
    v = sys_.V.subs({Q: _q, th: _th})
    (q0,) = sp.solve(sp.diff(v, _q), _q)
    (th0,) = sp.solve(sp.simplify(sp.diff(v, _th).subs(_q, q0)), _th)
    return [th0, q0.subs(_th, th0)]


TH0 = th1 - C0 * E**2 / (2 * sp.pi * k)

PROBLEM = Problem(
    id="p15.9",
    title="Rotor capacitor of P15.3: equilibrium twist theta0 and charge Q0",
    chapter=15,
    source="Wells, Problem 15.9",
    system=system,
    answers=[
        Quantity("[theta0, Q0]", _equilibrium, [TH0, C0 * (1 - TH0 / sp.pi) * E],
                 description="equilibrium theta0, Q0"),
    ],
    simulation=Simulation(
        # starts at the equilibrium theta0 = 1.5 - 1/(4 pi), Q0 = (1 - theta0/pi): stays there
        params={m: 1.0, I: 1.0, C0: 1.0, k: 2.0, th1: 1.5, E: 1.0, R: 0.3},
        initial={Q: 1 - (1.5 - 1 / (4 * 3.141592653589793)) / 3.141592653589793,
                 th: 1.5 - 1 / (4 * 3.141592653589793), Q.diff(t): 0.0, th.diff(t): 0.0},
        t_end=10,
    ),
    correction="The small-oscillation equations in theta - theta0, Q - Q0 are left to the reader (no printed form).",
)
