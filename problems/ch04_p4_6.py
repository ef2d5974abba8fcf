"""Wells, Problem 4.6 — two rods on a shaft coupled by a clock spring k; coordinates θ1 and the relative angle α."""

import sympy as sp

from lagrange import System, coordinates, delta, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, GeneralizedForces, Problem, Simulation

theta1, alpha, th1, th2 = coordinates("theta1 alpha th1 th2")
I1, I2, k = parameters("I1 I2 k")

# Rod B's absolute angle is θ1 − α (inferred in the catalog); the spring torque is −k α.
relative = System(
    [theta1, alpha],
    T=sp.Rational(1, 2) * I1 * theta1.diff(t) ** 2 + sp.Rational(1, 2) * I2 * (theta1.diff(t) - alpha.diff(t)) ** 2,
    forces=-k * alpha * delta(alpha),
    name="clock-spring coupled rods (theta1, alpha)",
)
# Angles measured in opposite senses: the spring twist is θ1 + θ2.
opposite = System(
    [th1, th2],
    T=sp.Rational(1, 2) * I1 * th1.diff(t) ** 2 + sp.Rational(1, 2) * I2 * th2.diff(t) ** 2,
    forces=-k * (th1 + th2) * delta(th1 + th2),
    name="clock-spring coupled rods (opposite-sense angles)",
)

PROBLEMS = [
    Problem(
        id="p4.6",
        title="Rods coupled by a clock spring: relative oscillation and conserved momentum of theta1",
        chapter=4,
        source="Wells, Problem 4.6",
        system=relative,
        answers=[
            EquationsOfMotion([
                sp.Eq((I1 + I2) * theta1.diff(t, 2) - I2 * alpha.diff(t, 2), 0),
                sp.Eq(I1 * I2 / (I1 + I2) * alpha.diff(t, 2), -k * alpha),
            ]),
            ConservedMomenta({theta1: (I1 + I2) * theta1.diff(t) - I2 * alpha.diff(t)}),
        ],
        simulation=Simulation(params={I1: 1, I2: 2, k: 5},
                              initial={theta1: 0, alpha: 0.3, theta1.diff(t): 1, alpha.diff(t): 0}, t_end=5),
        correction="Absolute angle of rod B taken as theta1 − alpha (inferred in the catalog; figure not available). "
                   "The book's alpha equation is the combination that eliminates theta1''.",
    ),
    Problem(
        id="p4.6-opposite",
        title="Rods coupled by a clock spring, angles in opposite senses: F_theta1 = F_theta2 = -k(theta1 + theta2)",
        chapter=4,
        source="Wells, Problem 4.6",
        system=opposite,
        answers=[GeneralizedForces({th1: -k * (th1 + th2), th2: -k * (th1 + th2)})],
        simulation=Simulation(params={I1: 1, I2: 2, k: 5},
                              initial={th1: 0.1, th2: 0.2, th1.diff(t): 0, th2.diff(t): 0}, t_end=5),
    ),
]
