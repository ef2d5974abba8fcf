"""Wells, eqs. (2.13), (2.26), (2.42) — planar double pendulum with elastic strings (4 DOF)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

r1, theta, r2, phi = coordinates("r1 theta r2 phi")
m1, m2, x0, y0 = parameters("m1 m2 x0 y0")

X1 = x0 + r1 * sp.sin(theta)
Y1 = y0 - r1 * sp.cos(theta)
X2 = X1 + r2 * sp.sin(phi)
Y2 = Y1 - r2 * sp.cos(phi)
system = System(
    [r1, theta, r2, phi],
    bodies=[Particle(m1, (X1, Y1), name="m1"), Particle(m2, (X2, Y2), name="m2")],
    name="double pendulum with elastic strings",
)

rd, thd, r2d, phd = r1.diff(t), theta.diff(t), r2.diff(t), phi.diff(t)
v2_sq = (rd**2 + r1**2 * thd**2 + r2d**2 + r2**2 * phd**2
         + 2 * (rd * r2d + r1 * r2 * thd * phd) * sp.cos(phi - theta)
         + 2 * (r1 * r2d * thd - r2 * rd * phd) * sp.sin(phi - theta))

PROBLEM = Problem(
    id="eq2.42",
    title="Planar double pendulum with elastic strings: T in (r1, θ, r2, φ)",
    chapter=2,
    source="Wells, Sec. 2.9, eqs. (2.13), (2.26), (2.42)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m1 * (rd**2 + r1**2 * thd**2) + sp.Rational(1, 2) * m2 * v2_sq),
        Quantity("v2^2 = 2 T_2/m2 (2.26)", lambda s: 2 * s.bodies[1].kinetic_energy() / m2, v2_sq),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 1},
        initial={r1: 1.0, theta: 0.3, r2: 1.0, phi: -0.2,
                 r1.diff(t): 0.0, theta.diff(t): 0.5, r2.diff(t): 0.1, phi.diff(t): -0.4},
        t_end=2.0,
    ),
    correction="Only T is given (no forces): the simulation is the force-free motion of this T. "
    "The moving-support variant (2.15) has no printed answer and is not included.",
)
