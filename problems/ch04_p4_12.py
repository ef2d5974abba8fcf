"""Wells, Problem 4.12 — motor-driven disk D1 carrying a second motor that drives disk D2 (internal torque pair)."""

import sympy as sp

from lagrange import System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

theta1, theta2, al = coordinates("theta1 theta2 alpha")
I1, I2, M2, r, tau1, tau2 = parameters("I1 I2 M2 r tau1 tau2")

# θ1: D1 (from the frame); θ2: D2 relative to D1. Motor 1 (on the frame) applies τ1 to D1. Motor 2 sits on D1:
# it applies τ2 to D2 and the reaction −τ2 to D1. D2's absolute angle is θ1 + θ2.
T12 = (sp.Rational(1, 2) * I1 * theta1.diff(t) ** 2 + sp.Rational(1, 2) * I2 * (theta1.diff(t) + theta2.diff(t)) ** 2
       + sp.Rational(1, 2) * M2 * r**2 * theta1.diff(t) ** 2)
relative = System(
    [theta1, theta2],
    T=T12,
    forces=tau1 * delta(theta1) + tau2 * delta(theta1 + theta2) - tau2 * delta(theta1),
    name="motor on a motor-driven disk (theta1, theta2)",
)
# Coordinates (θ1, α = θ1 + θ2), α D2's absolute angle.
absolute = System(
    [theta1, al],
    T=T12.subs(theta2, al - theta1).doit(),
    forces=tau1 * delta(theta1) + tau2 * delta(al) - tau2 * delta(theta1),
    name="motor on a motor-driven disk (theta1, alpha)",
)

sim = Simulation(params={I1: 1, I2: 0.5, M2: 2, r: 0.5, tau1: 1, tau2: 0.2},
                 initial={theta1: 0, theta2: 0, theta1.diff(t): 0, theta2.diff(t): 0}, t_end=2)
PROBLEMS = [
    Problem(
        id="p4.12",
        title="Disk driven by a motor carrying a second motor and disk: internal torque pair",
        chapter=4,
        source="Wells, Problem 4.12",
        system=relative,
        answers=[
            KineticEnergy(T12),
            GeneralizedForces({theta1: tau1, theta2: tau2}),
            EquationsOfMotion([
                sp.Eq(I2 * theta2.diff(t, 2) + theta1.diff(t, 2) * (I1 + M2 * r**2 + I2), tau1),
                sp.Eq(I2 * (theta1.diff(t, 2) + theta2.diff(t, 2)), tau2),
            ], per_equation=True),
        ],
        simulation=sim,
        correction="The OCR prints θ̇1 (a velocity) in the first equation; d/dt ∂T/∂θ̇1 gives θ̈1 (catalog, sym ✓).",
    ),
    Problem(
        id="p4.12-alpha",
        title="Disk with a motor-driven second disk in (theta1, alpha = theta1 + theta2): F_theta1 = tau1 - tau2",
        chapter=4,
        source="Wells, Problem 4.12",
        system=absolute,
        answers=[GeneralizedForces({theta1: tau1 - tau2, al: tau2})],
        simulation=Simulation(params=sim.params, initial={theta1: 0, al: 0, theta1.diff(t): 0, al.diff(t): 0}, t_end=2),
    ),
]
