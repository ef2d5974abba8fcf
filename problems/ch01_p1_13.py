"""Wells, Problem 1.13 — pendulum whose support has constant acceleration a_x and constant velocity v_y."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

theta = coordinates("theta")
m, g, r, a_x, v_y = parameters("m g r a_x v_y")

X = sp.Rational(1, 2) * a_x * t**2 + r * sp.sin(theta)
Y = v_y * t - r * sp.cos(theta)
system = System(
    [theta],
    bodies=[Particle(m, (X, Y), name="bob")],
    forces=-m * g * delta(Y),
    name="pendulum on an accelerating support",
)


def _static_acceleration(s):
    return sp.trigsimp(s.accelerations()[0].subs(theta.diff(t), 0))


def _equilibrium(s, acc=None):
    acc = _static_acceleration(s) if acc is None else acc
    # the root with |θe| < π/2 (the bob below the support)
    sols = [e for e in sp.solve(acc, theta) if abs(float(e.subs({a_x: 1, g: 9.8}))) < sp.pi / 2]
    return sols[0]


def _omega_squared(s):
    acc = _static_acceleration(s)
    return -sp.diff(acc, theta).subs(theta, _equilibrium(s, acc))


PROBLEM = Problem(
    id="p1.13",
    title="Pendulum on a support with constant acceleration a_x (X) and constant velocity v_y (Y)",
    chapter=1,
    source="Wells, Problem 1.13",
    system=system,
    answers=[
        EquationsOfMotion([sp.Eq(r * theta.diff(t, 2), -a_x * sp.cos(theta) - g * sp.sin(theta))], per_equation=True),
        Quantity("equilibrium angle", _equilibrium, -sp.atan(a_x / g)),
        Quantity("small-oscillation ω²", _omega_squared, sp.sqrt(g**2 + a_x**2) / r),
    ],
    simulation=Simulation(
        params={m: 1, g: 9.81, r: 1.0, a_x: 2.0, v_y: 1.0},
        initial={theta: 0.1, theta.diff(t): 0.0},
        t_end=5.0,
    ),
    correction="The book states only that the period changes; the equilibrium θe = −atan(a_x/g) and "
    "ω² = (g² + a_x²)^(1/2)/r are derived in the catalog, not printed in the book.",
)
