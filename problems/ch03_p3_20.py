"""Wells, Problem 3.20 — string wound on a motor-driven disk (angle α(t)); m hangs on the free end at angle θ."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

theta = coordinates("theta")
m, g, R, r0, w, c = parameters("m g R r_0 omega c")

# The motor drive is prescribed; any α(t) will do — here α = ω t + c t²/2 (book: general α(t)).
alpha = w * t + c * t**2 / 2
rho = r0 + R * theta - R * alpha  # free length of string
# String leaves the disk (radius R, centre O) at R(cosθ, sinθ) and hangs along (sinθ, −cosθ).
X = R * sp.cos(theta) + rho * sp.sin(theta)
Y = R * sp.sin(theta) - rho * sp.cos(theta)
system = System([theta], bodies=[Particle(m, (X, Y), name="m")], forces=-m * g * delta(Y),
                name="mass on a string unwinding from a driven disk")

ad = alpha.diff(t)
PROBLEM = Problem(
    id="p3.20",
    title="Mass on a string wound on a motor-driven disk: T, F_theta and equation of motion",
    chapter=3,
    source="Wells, Problem 3.20",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (R**2 * ad**2 + rho**2 * theta.diff(t) ** 2)),
        GeneralizedForces({theta: -m * g * rho * sp.sin(theta)}),
        EquationsOfMotion([
            sp.Eq(m * rho * theta.diff(t, 2) - 2 * m * R * theta.diff(t) * ad + m * R * theta.diff(t) ** 2,
                  -m * g * sp.sin(theta))
        ]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, R: 0.1, r0: 1.0, w: 0.5, c: 0.0},
                          initial={theta: 0.3, theta.diff(t): 0}, t_end=3),
    ranges={"R": (0.1, 0.3)},
    correction="The book's equation is the derived one divided by the free length rho = r0 + R theta - R alpha "
               "(not a constant factor, so it is compared through the accelerations). Geometry of the tangent "
               "point reconstructed (figure not available); it reproduces the printed T and F_theta.",
)
