"""Wells, Problem 3.16 — particle moving in the face of a disk that rolls down an incline (explicit t)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

r, theta, beta = coordinates("r theta beta")
m, a, R = parameters("m a R")

# Disk centre moves down the incline with X = a t²/2 (a = 2/3 g sinα); the disk turns by β with β̇ = (a/R) t.
# Particle at polar (r, θ) relative to axes fixed in the disk; its inertial offset is r(sin(β−θ), cos(β−θ)).
beta_t = a * t**2 / (2 * R)
system = System(
    [r, theta],
    bodies=[Particle(m, (a * t**2 / 2 + r * sp.sin(beta - theta), r * sp.cos(beta - theta)), name="particle")],
    prescribed={beta: beta_t},
    name="particle on the face of a rolling disk",
)

bd = beta.diff(t)
T_book = sp.Rational(1, 2) * m * (
    a**2 * t**2 + r.diff(t) ** 2 + r**2 * (bd - theta.diff(t)) ** 2
    + 2 * a * t * r.diff(t) * sp.sin(beta - theta) + 2 * a * t * r * (bd - theta.diff(t)) * sp.cos(beta - theta)
)

PROBLEM = Problem(
    id="p3.16",
    title="Particle on the face of a disk rolling down an incline: T in disk-fixed polar coordinates",
    chapter=3,
    source="Wells, Problem 3.16",
    system=system,
    answers=[KineticEnergy(T_book.subs(beta, beta_t).doit())],
    simulation=Simulation(params={m: 1, a: 2, R: 1}, initial={r: 0.5, theta: 0, r.diff(t): 0, theta.diff(t): 0},
                          t_end=1),
    correction="Printed '2 a ṙ sin(β−θ)' has lost the factor t: the centre's speed is a t, so the cross term is "
               "2 a t ṙ sin(β−θ) (catalog, sym ✓; dimensional check: every term of T must be m·velocity²). "
               "β is prescribed by β̇ = (a/R) t, i.e. β = a t²/(2R).",
)
