"""Wells, eqs. (2.31), (2.46) — particle on table D2 mounted on the rotating table D1 (Fig. 2-21)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity

theta1, theta2, r, alpha = coordinates("theta1 theta2 r alpha")
m, s = parameters("m s")

beta = theta1 + theta2 + alpha
system = System(
    [theta1, theta2, r, alpha],
    bodies=[Particle(m, (s * sp.cos(theta1) + r * sp.cos(beta), s * sp.sin(theta1) + r * sp.sin(beta)))],
    name="particle on a table on a rotating table",
)

th1d, rd = theta1.diff(t), r.diff(t)
betad = beta.diff(t)
v2 = (s**2 * th1d**2 + 2 * s * th1d * rd * sp.sin(theta2 + alpha) + r**2 * betad**2 + rd**2
      + 2 * s * th1d * betad * r * sp.cos(theta2 + alpha))

PROBLEM = Problem(
    id="eq2.46",
    title="Particle on table D2 carried by rotating table D1: v^2 and T",
    chapter=2,
    source="Wells, Sec. 2.9, eqs. (2.31), (2.46) (Fig. 2-21)",
    system=system,
    answers=[
        Quantity("v^2 = 2T/m", lambda sys_: 2 * sys_.T / m, v2),
        KineticEnergy(sp.Rational(1, 2) * m * v2),
    ],
    correction="θ1, θ2, r, α are all free here, so the particle (2 DOF in the plane) has 4 coordinates and a "
    "singular mass matrix; no simulation. The driven variants (θ̇1 = ω1, θ̈2 = C; θ1 = A sin at, "
    "θ2 = B sin bt) have no printed answer and are not included.",
)
