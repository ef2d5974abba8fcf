"""Wells, Sec. 6.12 — magnet moving over a grill of wires at angle alpha: drag only normal to the wires (6.22)."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y = coordinates("x y")
m, C, alpha = parameters("m C alpha")

magnet = Particle(m, (x, y))
n = (sp.sin(alpha), -sp.cos(alpha))  # unit normal to the wires (wires along (cos alpha, sin alpha))
v_n = x.diff(t) * n[0] + y.diff(t) * n[1]
drag = Force(at=magnet, vector=(-C * v_n * n[0], -C * v_n * n[1], 0))
by_force = System([x, y], bodies=[magnet], forces=[drag], name="magnet over a grill (force)")
by_power = System([x, y], bodies=[magnet], P=-C * v_n**2 / 2, name="magnet over a grill (P)")

xd, yd = x.diff(t), y.diff(t)
F_book = {x: C * sp.sin(alpha) * (yd * sp.cos(alpha) - xd * sp.sin(alpha)),
          y: C * sp.cos(alpha) * (xd * sp.sin(alpha) - yd * sp.cos(alpha))}
sim = Simulation(params={m: 1, C: 0.5, alpha: 0.4}, initial={x: 0, y: 0, x.diff(t): 1, y.diff(t): 0.5}, t_end=5)
PROBLEMS = [
    Problem(
        id="sec6.12",
        title="Grill forces (6.22): f_x = C sin(a)(yd cos a - xd sin a), f_y = C cos(a)(xd sin a - yd cos a)",
        chapter=6,
        source="Wells, Sec. 6.12, eq. (6.22)",
        system=by_force,
        answers=[GeneralizedForces(F_book, which="applied")],
        simulation=sim,
        ranges={"alpha": (0.1, 1.4)},
    ),
    Problem(
        id="sec6.12-P",
        title="Grill forces from the semidefinite power function P = -C (xd sin a - yd cos a)^2 / 2",
        chapter=6,
        source="Wells, Sec. 6.12",
        system=by_power,
        answers=[PowerFunction(-C * (xd * sp.sin(alpha) - yd * sp.cos(alpha)) ** 2 / 2), GeneralizedForces(F_book)],
        simulation=sim,
        ranges={"alpha": (0.1, 1.4)},
    ),
]
