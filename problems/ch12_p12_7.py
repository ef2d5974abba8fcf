"""Wells, Problem 12.7 — particle sliding from the top of a smooth sphere (radius r) with initial speed
r thetadot_0: the normal reaction f_r and the angle where the particle leaves the sphere (unilateral contact)."""

import numpy as np
import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Quantity, Simulation

rho, th = coordinates("rho theta")
m, g, r, w0 = parameters("m g r thetadot_0")

# rho: distance from the centre (superfluous, rho = r while in contact); theta from the upward vertical; Y up.
system = System(
    [rho, th],
    bodies=[Particle(m, (rho * sp.sin(th), rho * sp.cos(th)), name="particle")],
    V=m * g * rho * sp.cos(th),
    constraints=[Holonomic(rho - r, name="sphere", unilateral=True)],
    name="particle on a smooth sphere (contact can only push)",
)

# thetadot_0 is an initial condition, not a parameter of the system (the simulator rejects parameters the
# system does not contain), so the book's expressions get its value 6/5, the initial thetadot below.
W0 = sp.Rational(6, 5)
PARAMS = {m: 1.0, g: 9.81, r: 1.0}
INIT = {rho: 1.0, th: 0.0, rho.diff(t): 0.0, th.diff(t): float(W0)}
EXACT = {g: sp.Rational(981, 100), r: 1, w0: W0}  # the same numbers, exact


def lift_off_cos(system):
    """cos(theta) where the simulated contact force reaches zero (terminal event of the unilateral constraint)."""
    sol = system.simulate(5.0, INIT, PARAMS, rtol=1e-12, atol=1e-12)
    if "Contact lost" not in sol.message:
        return sp.nan
    y_event = sol.y_events[-1][0]
    return sp.Float(np.cos(y_event[system.coordinates.index(th)]), 15)


PROBLEM = Problem(
    id="p12.7",
    title="Particle sliding on a smooth sphere: f_r = 3 m g cos(theta) - m r thetadot_0^2 - 2 m g, lift-off angle",
    chapter=12,
    source="Wells, Problem 12.7",
    system=system,
    answers=[
        # phi = rho - r grows away from the surface: lambda is the outward normal push f_r (unilateral: >= 0).
        ConstraintForce("sphere", (3 * m * g * sp.cos(th) - m * r * w0**2 - 2 * m * g).subs(w0, W0), PARAMS, INIT, 5.0,
                        description="f_r (lambda = f_r)"),
        # The particle leaves when f_r = 0: cos(theta) = (2 g + r thetadot_0^2)/(3 g) (book), at these numbers.
        Quantity("cos(theta) at lift-off", lift_off_cos, ((2 * g + r * w0**2) / (3 * g)).subs(EXACT), rtol=1e-8,
                 description="lift-off angle from the contact-lost event"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=5.0),
    units="any consistent units (simulated with g = 9.81, r = 1, thetadot_0 = 1.2)",
)
