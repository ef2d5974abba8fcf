"""Wells, Example 14.2 — bead on a smooth parabolic wire z1 = b x1^2 in the X1Z1 plane (y1 = 0) of the earth frame.

Earth frame of Fig. 14-2; gravity by the true g (EarthFrame.gravity_force). The Coriolis terms linear in the
velocity drop out of the single equation and the R omega_e^2 terms cancel against the true gravity.
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation
from lagrange.model.frames import EarthFrame

x = coordinates("x1")
m, gp, w, R, Phi, b = parameters("m g_prime omega_e R Phi b")
c = sp.cos(Phi)

E = EarthFrame(Phi, w, R)
bead = Particle(m, E.point((x, 0, b * x**2)), name="bead")
system = System([x], bodies=[bead], forces=[Force(bead, E.gravity_force(m, gp))],
                name="bead on a parabolic wire on the rotating earth")

PROBLEM = Problem(
    id="ex14.2",
    title="Bead on a smooth parabolic wire z1 = b x1^2 fixed on the rotating earth",
    chapter=14,
    source="Wells, Example 14.2",
    system=system,
    answers=[
        # F_x1 = m g_z1 * 2 b x1 with the true g_z1 = -(g' + omega_e^2 R cos^2 Phi)
        GeneralizedForces({x: -2 * m * b * x * (gp + w**2 * R * c**2)}),
        EquationsOfMotion(
            [sp.Eq(m * (1 + 4 * b**2 * x**2) * x.diff(t, 2) + 4 * m * b**2 * x * x.diff(t) ** 2
                   - m * w**2 * (2 * b**2 * x**3 * c**2 + x), -2 * m * gp * x * b)],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854, b: 0.01},
        initial={x: 10.0, x.diff(t): 0.0},
        t_end=10,
    ),
    units="cgs in the simulation",
    correction="The book writes F_x1 = m g_z1 2 b x1 with g_z1 the true-gravity component; written out here with "
    "(14.11), g cos(alpha) = g' + omega_e^2 R cos^2 Phi.",
)
