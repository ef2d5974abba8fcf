"""Wells, Example 15.3 — capacitor microphone / electrostatic transducer of Fig. 15-5: the upper plate (mass m)
hangs on a spring k, the capacitance is C = A/(s - x); the circuit has inductance M, resistance R and an applied
EMF E0 sin(wt).

Coordinates: the charge Q and the plate displacement x, measured from the rest position with the capacitor
uncharged (so gravity cancels against the spring's static stretch). The position-dependent elastance
(s - x)/A couples the two: the electrical V = Q^2 (s - x)/(2A) gives the attraction Q^2/(2A) on the plate.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, PowerFunction, Problem, Simulation

Q, x = coordinates("Q x")
M, m, A, s, k, R, E0, w = parameters("M m A s k R E_0 omega")
half = sp.Rational(1, 2)

system = System(
    [Q, x],
    T=half * M * Q.diff(t) ** 2 + half * m * x.diff(t) ** 2,
    V=half * Q**2 * (s - x) / A + half * k * x**2 - Q * E0 * sp.sin(w * t),
    P=-half * R * Q.diff(t) ** 2,
    name="capacitor with a spring-mounted plate, Fig. 15-5",
)

PROBLEM = Problem(
    id="ex15.3",
    title="Capacitor C = A/(s - x) with a spring-mounted plate in an L-R circuit driven by E0 sin wt",
    chapter=15,
    source="Wells, Example 15.3",
    system=system,
    answers=[
        KineticEnergy(half * M * Q.diff(t) ** 2 + half * m * x.diff(t) ** 2),
        # L = T - V as printed: L = 1/2 M Q'^2 + 1/2 m x'^2 + Q E0 sin wt - 1/2 Q^2 (s - x)/A - 1/2 k x^2
        PotentialEnergy(-Q * E0 * sp.sin(w * t) + half * Q**2 * (s - x) / A + half * k * x**2),
        PowerFunction(-half * R * Q.diff(t) ** 2),
        EquationsOfMotion(
            [
                sp.Eq(M * Q.diff(t, 2) + Q * (s - x) / A - E0 * sp.sin(w * t), -R * Q.diff(t)),
                sp.Eq(m * x.diff(t, 2) + k * x - half * Q**2 / A, 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={M: 1.0, m: 1.0, A: 1.0, s: 1.0, k: 4.0, R: 0.2, E0: 0.5, w: 2.0},
        initial={Q: 0.0, x: 0.0, Q.diff(t): 0.0, x.diff(t): 0.0},
        t_end=20,
    ),
)
