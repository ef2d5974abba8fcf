"""Wells, Example 12.3 — rigid bent pendulum: m_1 at r_1 from the pivot p, m_2 at r_2 beyond m_1 at the
fixed relative angle beta; beta freed as a superfluous coordinate gives the bending moment F_beta."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, Problem, Simulation

th, be = coordinates("theta beta")
m1, m2, r1, r2, g, b0 = parameters("m_1 m_2 r_1 r_2 g beta_0")

# theta: angle of r_1 from the downward vertical; r_2 makes the angle beta with the extension of r_1. Y up.
p1 = (r1 * sp.sin(th), -r1 * sp.cos(th))
p2 = (p1[0] + r2 * sp.sin(th + be), p1[1] - r2 * sp.cos(th + be))
system = System(
    [th, be],
    bodies=[Particle(m1, p1, name="m1"), Particle(m2, p2, name="m2")],
    V=m1 * g * p1[1] + m2 * g * p2[1],
    constraints=[Holonomic(be - b0, name="rigid joint")],
    name="rigid bent pendulum, joint angle freed",
)

PARAMS = {m1: 1.0, m2: 0.6, r1: 1.0, r2: 0.5, g: 9.81, b0: 0.7}
INIT = {th: 0.5, be: 0.7, th.diff(t): 1.5, be.diff(t): 0.0}

PROBLEM = Problem(
    id="ex12.3",
    title="Rigid bent pendulum: the reaction moment F_beta at the joint (beta superfluous)",
    chapter=12,
    source="Wells, Example 12.3 (Fig. 12-3)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (m1 + m2) * r1**2 * th.diff(t) ** 2
                      + sp.Rational(1, 2) * m2 * (r2**2 * (th.diff(t) + be.diff(t)) ** 2
                                                  + 2 * r1 * r2 * sp.cos(be) * (th.diff(t) ** 2
                                                                                + th.diff(t) * be.diff(t)))),
        # phi = beta - beta_0, A = 1: lambda is Wells' generalized force of constraint F_beta itself.
        ConstraintForce("rigid joint",
                        m2 * (r2**2 + r1 * r2 * sp.cos(be)) * th.diff(t, 2)
                        + m2 * r1 * r2 * th.diff(t) ** 2 * sp.sin(be) + m2 * g * r2 * sp.sin(th + be),
                        PARAMS, INIT, 2.0, description="F_beta"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=10),
)
