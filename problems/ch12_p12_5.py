"""Wells, Problem 12.5 — two rods rigidly joined at the pivot p, swinging as a pendulum (Fig. 12-8): the
torque tau_alpha that holds rod 2 at the angle beta to rod 1 (relative angle alpha freed)."""

import sympy as sp

from lagrange import Holonomic, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, Problem, Simulation

th, al = coordinates("theta alpha")
I1, I2, M1, M2, r1, r2, g, be = parameters("I_1 I_2 M_1 M_2 r_1 r_2 g beta")

# Rod 1 (moment of inertia I_1 about p, c.m. at r_1 from p) at theta from the downward vertical; rod 2
# (I_2 about p, c.m. at r_2) at theta + alpha; rigidly joined: alpha = beta. Rigid bodies through T directly.
system = System(
    [th, al],
    T=sp.Rational(1, 2) * I1 * th.diff(t) ** 2 + sp.Rational(1, 2) * I2 * (th.diff(t) + al.diff(t)) ** 2,
    V=-M1 * g * r1 * sp.cos(th) - M2 * g * r2 * sp.cos(th + al),
    constraints=[Holonomic(al - be, name="joint")],
    name="two rods joined at the pivot, joint angle freed",
)

PARAMS = {I1: 0.4, I2: 0.3, M1: 1.0, M2: 0.8, r1: 0.5, r2: 0.4, g: 9.81, be: 1.2}
INIT = {th: 0.3, al: 1.2, th.diff(t): 1.0, al.diff(t): 0.0}

PROBLEM = Problem(
    id="p12.5",
    title="Two rods rigidly joined at the pivot: joint torque tau_alpha = I_2 thdd + M_2 g r_2 sin(theta + beta)",
    chapter=12,
    source="Wells, Problem 12.5 (Fig. 12-8)",
    system=system,
    answers=[
        # phi = alpha - beta, A = 1: lambda = tau_alpha, the torque on rod 2 in the +alpha sense.
        ConstraintForce("joint", I2 * th.diff(t, 2) + M2 * g * r2 * sp.sin(th + be), PARAMS, INIT, 2.0,
                        description="tau_alpha"),
    ],
    simulation=Simulation(params=PARAMS, initial=INIT, t_end=10),
    correction="Geometry inferred from the answer (I_2 about p, r_2 from p to the c.m. of rod 2: both rods turn "
               "about the pivot p). The small-motion part of the problem has no printed answer and is omitted.",
)
