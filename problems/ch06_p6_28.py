"""Wells, Problem 6.28 — pole (x, y) over a free grill-board (x1, y1, theta): forces on both and P = -C u^2/2."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y, x1, y1, theta = coordinates("x y x1 y1 theta")
m, M, I, C = parameters("m M I C")

# Board: reference point (x1, y1) at its c.m., wires along the board direction theta.
# Velocity of the pole relative to the board point beneath it, and its component normal to the wires.
v_rel = (x.diff(t) - x1.diff(t) + (y - y1) * theta.diff(t), y.diff(t) - y1.diff(t) - (x - x1) * theta.diff(t))
n = (sp.sin(theta), -sp.cos(theta))
v_n = v_rel[0] * n[0] + v_rel[1] * n[1]
system = System([x, y, x1, y1, theta], T=I * theta.diff(t) ** 2 / 2,
                bodies=[Particle(m, (x, y)), Particle(M, (x1, y1))], P=-C * v_n**2 / 2, name="pole over a grill-board")

u = ((y.diff(t) - y1.diff(t) - (x - x1) * theta.diff(t)) * sp.cos(theta)
     - (x.diff(t) - x1.diff(t) + (y - y1) * theta.diff(t)) * sp.sin(theta))
fx, fy = C * u * sp.sin(theta), -C * u * sp.cos(theta)
fx1, fy1 = -fx, -fy
PROBLEM = Problem(
    id="p6.28",
    title="Pole over a free grill-board: f_x = C u sin(theta), f_y = -C u cos(theta), reactions on the board",
    chapter=6,
    source="Wells, Problem 6.28",
    system=system,
    answers=[
        PowerFunction(-C * u**2 / 2),
        GeneralizedForces({x: fx, y: fy, x1: fx1, y1: fy1, theta: fy1 * (x - x1) - fx1 * (y - y1)}),
    ],
    simulation=Simulation(params={m: 1, M: 3, I: 1, C: 0.5},
                          initial={x: 0.3, y: 0.2, x1: 0, y1: 0, theta: 0.1, x.diff(t): 1, y.diff(t): 0.5,
                                   x1.diff(t): 0, y1.diff(t): 0, theta.diff(t): 0.2}, t_end=5),
    correction="The board's mass M and moment of inertia I (about its c.m. at (x1, y1)) are assumed for T; "
    "the book's answer concerns the forces only.",
)
