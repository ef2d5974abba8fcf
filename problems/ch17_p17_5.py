"""Wells, Problem 17.5 — projectile of Ex. 17.5 with the varied path y_v = y + ε sin ωt, ω = nπ/t_f."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x, y = coordinates("x y")
m, g, vx, vy, eps = parameters("m g v_x v_y epsilon")
n = sp.Symbol("n", integer=True, positive=True)

system = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y, name="projectile")

tf = 2 * vy / g
w = n * sp.pi / tf
true_path = {x: vx * t, y: vy * t - g * t**2 / 2}


def _J(s, path):
    L = (s.T - s.V).subs(path).doit()
    return sp.integrate(sp.expand(L), (t, 0, tf))


def _difference(s):
    varied = {x: true_path[x], y: true_path[y] + eps * sp.sin(w * t)}
    return sp.simplify(_J(s, varied) - _J(s, true_path))


expected = m * eps**2 * w**2 / 2 * sp.integrate(sp.cos(w * t) ** 2, (t, 0, tf))

PROBLEM = Problem(
    id="p17.5",
    title="Projectile, varied path y + eps sin(n pi t/tf): J_v - J = 1/2 m eps^2 w^2 ∫ cos^2 wt dt > 0",
    chapter=17,
    source="Wells, Problem 17.5",
    system=system,
    answers=[
        Quantity("J_v - J (no first-order term)", _difference, expected),
    ],
    simulation=Simulation(params={m: 1, g: 9.81}, initial={x: 0, y: 0, x.diff(t): 3, y.diff(t): 4}, t_end=0.8),
    correction="n is an integer (the variation vanishes at both ends); the check integrates symbolically with "
    "integer n, so sin(2 n pi) = 0 is used exactly.",
)
