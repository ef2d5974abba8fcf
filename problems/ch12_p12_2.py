"""Wells, Problem 12.2 — particle m sliding on a smooth rod fixed at the angle theta to a vertical shaft that
is turned arbitrarily, phi = phi(t) (Fig. 3-9): the rod's reactions f_theta, f_phi."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

r, th, ph = coordinates("r theta phi")
m, g, th0, w, A, nu = parameters("m g theta_0 omega A nu")

# Spherical coordinates, theta from the upward vertical (Z up). theta and phi are superfluous: the rod angle
# theta = theta_0 and the shaft's prescribed turning phi = omega t + A sin(nu t) (an arbitrary phi(t))
# are constraints, so their multipliers give the reactions.
pos = (r * sp.sin(th) * sp.cos(ph), r * sp.sin(th) * sp.sin(ph), r * sp.cos(th))
system = System(
    [r, th, ph],
    bodies=[Particle(m, pos, name="m")],
    V=m * g * pos[2],
    constraints=[Holonomic(th - th0, name="rod angle"), Holonomic(ph - w * t - A * sp.sin(nu * t), name="shaft")],
    name="particle on a rod turned by a shaft, theta and phi free",
)

PARAMS = {m: 1.0, g: 9.81, th0: 1.0, w: 2.0, A: 0.5, nu: 3.0}
INIT = {r: 1.0, th: 1.0, ph: 0.0, r.diff(t): 0.0, th.diff(t): 0.0, ph.diff(t): 3.5}

PROBLEM = Problem(
    id="p12.2",
    title="Particle on a rod at a fixed angle to a vertical shaft turned arbitrarily: reactions f_theta, f_phi",
    chapter=12,
    source="Wells, Problem 12.2 (Fig. 3-9)",
    system=system,
    answers=[
        # The generalized force of constraint on theta is r f_theta, on phi it is r sin(theta) f_phi
        # (f: physical components in the +theta, +phi directions), = (A^T lambda) of each constraint.
        # Book: f_theta = -m r phid^2 sin(theta) cos(theta) - m g sin(theta)
        ConstraintForce("rod angle", r * (-m * r * ph.diff(t) ** 2 * sp.sin(th) * sp.cos(th) - m * g * sp.sin(th)),
                        PARAMS, INIT, 1.5, coordinate=th, description="r f_theta"),
        # Book: f_phi = m r sin(theta) phidd + 2 m rd phid sin(theta)
        ConstraintForce("shaft", r * sp.sin(th) * (m * r * sp.sin(th) * ph.diff(t, 2)
                                                   + 2 * m * r.diff(t) * ph.diff(t) * sp.sin(th)),
                        PARAMS, INIT, 1.5, coordinate=ph, description="r sin(theta) f_phi"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=1.5),
    correction="phi(t) is arbitrary in the book; omega t + A sin(nu t) is chosen to simulate. Engine sign: "
               "(A^T lambda)_q is the generalized force of constraint on q, i.e. r f_theta and "
               "r sin(theta) f_phi.",
    ranges={"theta_0": (0.3, 1.4)},
)
