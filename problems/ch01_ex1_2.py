"""Wells, Example 1.2 — particle described in axes rotating at constant ω."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x2, y2 = coordinates("x2 y2")
m, omega = parameters("m omega")
F_x2, F_y2 = parameters("F_x2 F_y2", real=True)

c, s = sp.cos(omega * t), sp.sin(omega * t)
ball = Particle(m, (x2 * c - y2 * s, x2 * s + y2 * c), name="particle")

# (a) The book's statement that the rotating-axis components F_x2, F_y2 are the generalized forces.
system = System([x2, y2], bodies=[ball], forces={x2: F_x2, y2: F_y2}, name="particle in rotating axes")
# (b) The same force given as an inertial vector; F_q = F·∂r/∂q must reproduce F_x2, F_y2.
system_vec = System(
    [x2, y2],
    bodies=[ball],
    forces=[Force(at=ball, vector=(F_x2 * c - F_y2 * s, F_x2 * s + F_y2 * c))],
    name="particle in rotating axes (force as an inertial vector)",
)

T_book = sp.Rational(1, 2) * m * ((x2.diff(t) - omega * y2) ** 2 + (y2.diff(t) + omega * x2) ** 2)
EOM = [
    sp.Eq(F_x2, m * x2.diff(t, 2) - m * x2 * omega**2 - 2 * m * omega * y2.diff(t)),
    sp.Eq(F_y2, m * y2.diff(t, 2) - m * y2 * omega**2 + 2 * m * omega * x2.diff(t)),
]
SIM = Simulation(
    params={m: 1, omega: 1.0, F_x2: 0.0, F_y2: 0.0},
    initial={x2: 1.0, y2: 0, x2.diff(t): 0, y2.diff(t): 0.5},
    t_end=5.0,
)
NOTE = ("T is not printed in the example; the KineticEnergy entry is T = (m/2)(inertial speed)^2 written in "
        "rotating components, (2.37) applied to the example's transformation equations.")

PROBLEMS = [
    Problem(
        id="ex1.2",
        title="Particle in axes rotating at constant ω: Coriolis and centrifugal terms",
        chapter=1,
        source="Wells, Example 1.2 (Fig. 1-2), equations (11), (12)",
        system=system,
        answers=[KineticEnergy(T_book), EquationsOfMotion(EOM, per_equation=True)],
        simulation=SIM,
        ranges={"F_x2": (-2, 2), "F_y2": (-2, 2)},
        correction=NOTE,
    ),
    Problem(
        id="ex1.2-force-vector",
        title="Particle in rotating axes, applied force given by inertial components",
        chapter=1,
        source="Wells, Example 1.2 (Fig. 1-2), equations (11), (12)",
        system=system_vec,
        answers=[
            GeneralizedForces({x2: F_x2, y2: F_y2}, which="applied"),
            EquationsOfMotion(EOM, per_equation=True),
        ],
        simulation=SIM,
        ranges={"F_x2": (-2, 2), "F_y2": (-2, 2)},
        correction="",
    ),
]
