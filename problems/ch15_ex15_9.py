"""Wells, Example 15.9 — electrical-mechanical analog: a mass m on a spring k in a viscous liquid (drag
coefficient a) and a series circuit with inductance M, capacitance C, resistance R and battery E (Fig. 15-7).

Mechanical: y measured down from the unstretched-spring rest position shifted by the static stretch y0,
L_Me = 1/2 m y'^2 - 1/2 k (y + y0)^2 + m g y with m g = k y0 (here y0 = m g/k), drag P = -1/2 a y'^2.
Electrical: L_El = 1/2 M Q'^2 - 1/2 Q^2/C + E Q, P = -1/2 R Q'^2.
The equations have the same form under m <-> M, a <-> R, k <-> 1/C (and y <-> the charge measured from its
static value C E).
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, PotentialEnergy, PowerFunction, Problem, Quantity, Simulation

y, Q = coordinates("y Q")
m, k, g, a = parameters("m k g a")
M, C, R, E = parameters("M C R E")
half = sp.Rational(1, 2)
y0 = m * g / k  # static stretch: m g = k y0

mech = System([y], T=half * m * y.diff(t) ** 2, V=half * k * (y + y0) ** 2 - m * g * y, P=-half * a * y.diff(t) ** 2,
              name="mass on a spring in a viscous liquid")
elec = System([Q], T=half * M * Q.diff(t) ** 2, V=half * Q**2 / C - E * Q, P=-half * R * Q.diff(t) ** 2,
              name="series L-R-C circuit with a battery")


def analog_acceleration(sys_):
    """The circuit's Q'' with the charge counted from its static value C E (Q -> Q + C E)."""
    return sys_.accelerations()[0].subs(Q, Q + C * E).doit()


PROBLEMS = [
    Problem(
        id="ex15.9-mechanical",
        title="Mass on a spring in a viscous liquid (mechanical side of the analog)",
        chapter=15,
        source="Wells, Example 15.9",
        system=mech,
        answers=[
            PotentialEnergy(half * k * (y + y0) ** 2 - m * g * y),
            PowerFunction(-half * a * y.diff(t) ** 2),
            EquationsOfMotion([sp.Eq(m * y.diff(t, 2) + k * y, -a * y.diff(t))], per_equation=True),
        ],
        simulation=Simulation(params={m: 1.0, k: 4.0, g: 9.81, a: 0.3}, initial={y: 0.1, y.diff(t): 0.0},
                              t_end=20),
    ),
    Problem(
        id="ex15.9-electrical",
        title="Series L-R-C circuit with a battery (electrical side of the analog)",
        chapter=15,
        source="Wells, Example 15.9",
        system=elec,
        answers=[
            PotentialEnergy(half * Q**2 / C - E * Q),
            PowerFunction(-half * R * Q.diff(t) ** 2),
            EquationsOfMotion([sp.Eq(M * Q.diff(t, 2) + Q / C - E, -R * Q.diff(t))], per_equation=True),
            # the analog: the mechanical m y'' + k y = -a y' under m -> M, k -> 1/C, a -> R, y -> Q - C E
            Quantity("analog Q''", analog_acceleration, (-R * Q.diff(t) - Q / C) / M,
                     description="analog of m y'' + k y = -a y'"),
        ],
        simulation=Simulation(params={M: 1.0, C: 0.25, R: 0.3, E: 1.0}, initial={Q: 0.0, Q.diff(t): 0.0}, t_end=20),
        correction="The book prints the circuit equation as M Q'' + Q/C = -R Q', dropping the battery although E Q is "
                   "in its L_El; with E kept the equation is M Q'' + Q/C - E = -R Q', which becomes the printed form "
                   "(the exact analog of m y'' + k y = -a y') when Q is counted from its static value C E.",
    ),
]
