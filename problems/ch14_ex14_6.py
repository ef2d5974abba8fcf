"""Wells, Example 14.6 — pendulum (m2, length r) hanging from m1, which slides freely along X1 (east) in the earth
frame of Fig. 14-2; motion in the X1Z1 plane.

m1 at (x1, 0, 0); m2 at (x1 + r sin(theta), 0, -r cos(theta)). Gravity by the true g (EarthFrame).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.frames import EarthFrame

x, th = coordinates("x1 theta")
m1, m2, r, gp, w, R, Phi = parameters("m1 m2 r g_prime omega_e R Phi")
cF = sp.cos(Phi)
xd, thd = x.diff(t), th.diff(t)
st, ct = sp.sin(th), sp.cos(th)

E = EarthFrame(Phi, w, R)
slider = Particle(m1, E.point((x, 0, 0)), name="m1")
bob = Particle(m2, E.point((x + r * st, 0, -r * ct)), name="m2")
system = System([x, th], bodies=[slider, bob],
                forces=[Force(slider, E.gravity_force(m1, gp)), Force(bob, E.gravity_force(m2, gp))],
                name="pendulum on a slider on the rotating earth")

T_book = (sp.Rational(1, 2) * m1 * (xd**2 + 2 * w * xd * R * cF + w**2 * x**2)
          + sp.Rational(1, 2) * m2 * (xd**2 + r**2 * thd**2 + 2 * xd * thd * r * ct)
          + m2 * w * ((R - r * ct) * (xd + r * thd * ct) - (x + r * st) * r * thd * st) * cF
          + sp.Rational(1, 2) * m2 * w**2 * ((x + r * st) ** 2 + (R - r * ct) ** 2 * cF**2))
T_book += sp.Rational(1, 2) * m1 * w**2 * R**2 * cF**2  # constant of m1 dropped in the book (see correction)

F_theta = -m2 * gp * r * st - m2 * w**2 * R * r * st * cF**2

PROBLEM = Problem(
    id="ex14.6",
    title="Pendulum hanging from a mass sliding east on the rotating earth: T (14.26) and EOM",
    chapter=14,
    source="Wells, Example 14.6, eq. (14.26)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        GeneralizedForces({x: 0, th: F_theta}),
        EquationsOfMotion(
            [
                sp.Eq((m1 + m2) * x.diff(t, 2) + m2 * r * th.diff(t, 2) * ct - m2 * r * thd**2 * st
                      - m1 * w**2 * x + 2 * m2 * w * r * thd * st * cF - m2 * w**2 * (x + r * st), 0),
                sp.Eq(m2 * x.diff(t, 2) * r * ct + m2 * r**2 * th.diff(t, 2) - 2 * m2 * w * xd * r * st * cF
                      - m2 * w**2 * (x + r * st) * r * ct - m2 * w**2 * (R - r * ct) * r * st * cF**2, F_theta),
            ],
            per_equation=True,
        ),
    ],
    simulation=Simulation(
        params={m1: 2.0, m2: 1.0, r: 100.0, gp: 980.0, w: 7.29211e-5, R: 6.378e8, Phi: 0.7854},
        initial={x: 0.0, th: 0.3, xd: 0.0, thd: 0.0},
        t_end=10,
    ),
    units="cgs in the simulation",
    correction="The book drops the constant 1/2 m1 omega_e^2 R^2 cos^2 Phi from T (14.26); it is restored for "
    "the T comparison.",
)
