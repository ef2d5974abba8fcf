"""Wells, Example 12.4 — bead on a smooth wire z = a r^2 turning with a vertical shaft of inertia I driven by a
torque tau (Problem 2.20, Fig. 2-29): wire reactions f_r, f_theta, f_z and the wire's torque tau' on the shaft,
with theta (bead's azimuth) and z as superfluous coordinates."""

import sympy as sp

from lagrange import Holonomic, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, KineticEnergy, Problem, Simulation

al, r, th, z = coordinates("alpha r theta z")
m, g, a, I, tau = parameters("m g a I tau")

T = (sp.Rational(1, 2) * I * al.diff(t) ** 2
     + sp.Rational(1, 2) * m * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2 + z.diff(t) ** 2))
system = System(
    [al, r, th, z],
    T=T,
    V=m * g * z,
    forces={al: tau},
    constraints=[Holonomic(th - al, name="wire plane"), Holonomic(z - a * r**2, name="wire shape")],
    name="bead on a rotating parabolic wire, theta and z free",
)
reduced = eliminate(system, {th: al, z: a * r**2})

PARAMS = {m: 1.0, g: 9.81, a: 0.8, I: 0.5, tau: 0.3}
INIT = {al: 0.0, r: 0.5, th: 0.0, z: 0.2, al.diff(t): 2.0, r.diff(t): 0.1, th.diff(t): 2.0, z.diff(t): 0.08}
INIT_R = {al: 0.0, r: 0.5, al.diff(t): 2.0, r.diff(t): 0.1}

PROBLEMS = [
    Problem(
        id="ex12.4",
        title="Bead on a wire z = a r^2 turning with a shaft of inertia I: f_r, f_theta, f_z and the torque tau'",
        chapter=12,
        source="Wells, Example 12.4 (Problem 2.20, Fig. 2-29)",
        system=system,
        answers=[
            KineticEnergy(T),
            # "wire plane" phi = theta - alpha: (A^T lambda)_theta = lambda = r f_theta (f_theta: reaction on the bead
            # in the +theta direction), (A^T lambda)_alpha = -lambda = tau' (reaction torque of the wire on the shaft).
            # Book: I alphadd = tau + tau'
            ConstraintForce("wire plane", I * al.diff(t, 2) - tau, PARAMS, INIT, 2.0, coordinate=al,
                            description="tau' = I alphadd - tau"),
            # Book: m r^2 thetadd + 2 m r rd thetad = r f_theta
            ConstraintForce("wire plane", m * r**2 * th.diff(t, 2) + 2 * m * r * r.diff(t) * th.diff(t),
                            PARAMS, INIT, 2.0, coordinate=th, description="r f_theta"),
            # "wire shape" phi = z - a r^2: (A^T lambda)_z = f_z, (A^T lambda)_r = f_r.
            # Book: m rdd - m r thetad^2 = f_r ; m zdd = f_z - m g
            ConstraintForce("wire shape", m * r.diff(t, 2) - m * r * th.diff(t) ** 2, PARAMS, INIT, 2.0,
                            coordinate=r, description="f_r"),
            ConstraintForce("wire shape", m * z.diff(t, 2) + m * g, PARAMS, INIT, 2.0, coordinate=z,
                            description="f_z"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=5),
        correction="Engine sign: (A^T lambda)_q is Wells' generalized force of constraint on q (added to the "
                   "applied forces). The book states tau' = -r f_theta; here that is the two checks on alpha and "
                   "theta of the one multiplier of theta = alpha.",
    ),
    Problem(
        id="ex12.4-reduced",
        title="Bead on a wire z = a r^2 turning with a shaft of inertia I: equations of motion in alpha, r",
        chapter=12,
        source="Wells, Example 12.4 (Problem 2.20)",
        system=reduced,
        answers=[
            EquationsOfMotion(
                [
                    sp.Eq((I + m * r**2) * al.diff(t, 2) + 2 * m * r * r.diff(t) * al.diff(t), tau),
                    sp.Eq(m * (1 + 4 * a**2 * r**2) * r.diff(t, 2) + 4 * m * a**2 * r * r.diff(t) ** 2
                          - m * r * al.diff(t) ** 2 + 2 * m * g * a * r, 0),
                ],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT_R, t_end=5),
        correction="The book gives the four equations with reactions plus z = a r^2, theta = alpha; the two "
                   "equations of motion used here are derived from them in the catalog (no single printed form).",
    ),
]
