"""Wells, Problem 6.27 — magnet over a grill that rotates about the origin at the rate alphad."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y = coordinates("x y")
m, C, a0, W = parameters("m C alpha0 Omega")
alpha = a0 + W * t  # grill angle, turning at alphad = Omega
alphad = alpha.diff(t)

magnet = Particle(m, (x, y))
# Velocity relative to the grill point beneath the magnet: v - alphad k x r.
v_rel = (x.diff(t) + alphad * y, y.diff(t) - alphad * x)
n = (sp.sin(alpha), -sp.cos(alpha))
v_n = v_rel[0] * n[0] + v_rel[1] * n[1]
by_force = System([x, y], bodies=[magnet], forces=[Force(at=magnet, vector=(-C * v_n * n[0], -C * v_n * n[1], 0))],
                  name="magnet over a rotating grill (force)")
by_power = System([x, y], bodies=[magnet], P=-C * v_n**2 / 2, name="magnet over a rotating grill (P)")

xd, yd = x.diff(t), y.diff(t)
u = yd * sp.cos(alpha) - xd * sp.sin(alpha) - (x * sp.cos(alpha) + y * sp.sin(alpha)) * alphad
F_book = {x: C * u * sp.sin(alpha), y: -C * u * sp.cos(alpha)}
sim = Simulation(params={m: 1, C: 0.5, a0: 0.2, W: 0.5}, initial={x: 0.5, y: 0, x.diff(t): 1, y.diff(t): 0.5},
                 t_end=5)
PROBLEMS = [
    Problem(
        id="p6.27",
        title="Rotating grill: f_x = C[yd cos a - xd sin a - (x cos a + y sin a) ad] sin a, f_y = -C[...] cos a",
        chapter=6,
        source="Wells, Problem 6.27",
        system=by_force,
        answers=[GeneralizedForces(F_book, which="applied")],
        simulation=sim,
    ),
    Problem(
        id="p6.27-P",
        title="Rotating grill: P = -C[yd cos a - xd sin a - ad(x cos a + y sin a)]^2 / 2",
        chapter=6,
        source="Wells, Problem 6.27",
        system=by_power,
        answers=[PowerFunction(-C * u**2 / 2), GeneralizedForces(F_book)],
        simulation=sim,
        correction="OCR drops the square in P; P = -(1/2) C [...]^2 (catalog) is the form whose dP/dqd gives the "
        "printed f_x, f_y.",
    ),
]
