"""Wells, Example 1.1 — ball in a railroad car with constant acceleration a_x (and an oscillating-car variant)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Quantity, Simulation

x2, y2 = coordinates("x2 y2")
m, g, a_x, v1, h, A, omega, s0 = parameters("m g a_x v1 h A omega s0")
F_x, F_y = parameters("F_x F_y", real=True)

# Car frame (x2, y2); inertial X1 = x2 + v1 t + a_x t^2/2, Y1 = y2 + h. Applied force (F_x, F_y) plus gravity.
X1 = x2 + v1 * t + sp.Rational(1, 2) * a_x * t**2
Y1 = y2 + h
system = System(
    [x2, y2],
    bodies=[Particle(m, (X1, Y1), name="ball")],
    forces=F_x * delta(X1) + F_y * delta(Y1) - m * g * delta(Y1),
    name="ball in an accelerating railroad car",
)


def _effective_gravity(s):
    # |acceleration| of the ball relative to the car when no applied force acts (only gravity).
    acc = s.accelerations().subs({F_x: 0, F_y: 0})
    return sp.sqrt(acc[0] ** 2 + acc[1] ** 2)


def _tilt_tangent(s):
    # tan of the angle between the apparent plumb line and the vertical.
    acc = s.accelerations().subs({F_x: 0, F_y: 0})
    return acc[0] / acc[1]


# Variant: the car oscillates, X1 = x2 + s0 + A sin(ωt).
X1o = x2 + s0 + A * sp.sin(omega * t)
system_osc = System(
    [x2, y2],
    bodies=[Particle(m, (X1o, Y1), name="ball")],
    forces=F_x * delta(X1o) + F_y * delta(Y1) - m * g * delta(Y1),
    name="ball in an oscillating railroad car",
)

PROBLEMS = [
    Problem(
        id="ex1.1",
        title="Ball in a railroad car with constant acceleration a_x (non-inertial car axes)",
        chapter=1,
        source="Wells, Example 1.1 (Fig. 1-1)",
        system=system,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * m * ((x2.diff(t) + v1 + a_x * t) ** 2 + y2.diff(t) ** 2)),
            GeneralizedForces({x2: F_x, y2: F_y - m * g}, which="applied"),
            EquationsOfMotion(
                [sp.Eq(m * x2.diff(t, 2), F_x - m * a_x), sp.Eq(m * y2.diff(t, 2), F_y - m * g)],
                per_equation=True,
            ),
            Quantity("effective gravity", _effective_gravity, sp.sqrt(a_x**2 + g**2)),
            Quantity("tan of plumb-line angle from the vertical", _tilt_tangent, a_x / g),
        ],
        simulation=Simulation(
            params={m: 1, g: 9.81, a_x: 2.0, v1: 1.0, F_x: 0.0, F_y: 0.0},
            initial={x2: 0, y2: 0, x2.diff(t): 0, y2.diff(t): 5.0},
            t_end=1.0,
        ),
        ranges={"F_x": (-2, 2), "F_y": (-2, 2)},
        correction="The weight of a man of mass M in the car, M(a_x^2+g^2)^(1/2), is implied by the effective "
        "gravity and is checked as that quantity per unit mass.",
    ),
    Problem(
        id="ex1.1-oscillating",
        title="Ball in a railroad car whose position oscillates, s = s0 + A sin(ωt)",
        chapter=1,
        source="Wells, Example 1.1 (extension in the text)",
        system=system_osc,
        answers=[
            EquationsOfMotion(
                [
                    sp.Eq(m * x2.diff(t, 2), m * A * omega**2 * sp.sin(omega * t) + F_x),
                    sp.Eq(m * y2.diff(t, 2), F_y - m * g),
                ],
                per_equation=True,
            ),
        ],
        simulation=Simulation(
            params={m: 1, g: 9.81, A: 0.2, omega: 3.0, F_x: 0.0, F_y: 9.81},
            initial={x2: 0, y2: 0, x2.diff(t): 0, y2.diff(t): 0},
            t_end=3.0,
        ),
        ranges={"F_x": (-2, 2), "F_y": (-2, 2)},
    ),
]
