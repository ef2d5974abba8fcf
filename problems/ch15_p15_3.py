"""Wells, Problem 15.3 — half-cylinder rotor capacitor of Fig. 15-11: C = C0 (1 - theta/pi) for 0 <= theta < pi,
the rotor on a torsion rod of stiffness k (undistorted at theta = theta1), moment of inertia I; the circuit has
inductance m, resistance R and a battery E. The electrical torque Q^2/(2 pi C0 (1 - theta/pi)^2) comes from the
position-dependent elastance in V."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, PowerFunction, Problem, Simulation

Q, th = coordinates("Q theta")
m, I, C0, k, th1, E, R = parameters("m I C_0 k theta_1 E R")
half = sp.Rational(1, 2)
Cth = C0 * (1 - th / sp.pi)

system = System(
    [Q, th],
    T=half * m * Q.diff(t) ** 2 + half * I * th.diff(t) ** 2,
    V=-E * Q + Q**2 / (2 * Cth) + half * k * (th1 - th) ** 2,
    P=-half * R * Q.diff(t) ** 2,
    name="rotor capacitor on a torsion rod, Fig. 15-11",
)

PROBLEM = Problem(
    id="p15.3",
    title="Half-cylinder rotor capacitor C = C0(1 - theta/pi) on a torsion rod, in an L-R circuit with battery E",
    chapter=15,
    source="Wells, Problem 15.3",
    system=system,
    answers=[
        KineticEnergy(half * m * Q.diff(t) ** 2 + half * I * th.diff(t) ** 2),
        PotentialEnergy(-E * Q + Q**2 / (2 * C0 * (1 - th / sp.pi)) + half * k * (th1 - th) ** 2),
        PowerFunction(-half * R * Q.diff(t) ** 2),
        EquationsOfMotion(
            [
                sp.Eq(m * Q.diff(t, 2) + Q / (C0 * (1 - th / sp.pi)) - E, -R * Q.diff(t)),
                sp.Eq(I * th.diff(t, 2) + Q**2 / (2 * sp.pi * C0 * (1 - th / sp.pi) ** 2) - k * (th1 - th), 0),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1.0, I: 1.0, C0: 1.0, k: 2.0, th1: 1.5, E: 1.0, R: 0.3},
        initial={Q: 0.0, th: 1.5, Q.diff(t): 0.0, th.diff(t): 0.0},
        t_end=20,
    ),
    correction="The charge equation is printed with theta'' as its first term ('theta'' + Q/C(theta) - E = -R Q''); "
               "the inductance term of the Q equation is m Q'' (from 1/2 m Q'^2 in L; theta'' cannot appear in a "
               "voltage balance of the circuit), catalog-verified.",
)
