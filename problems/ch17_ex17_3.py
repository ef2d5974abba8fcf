"""Wells, Example 17.3 — projectile: Euler–Lagrange equations of the action ∫ L dt give the parabola."""

import sympy as sp

from lagrange import Particle, System, coordinates, euler_lagrange, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x, y = coordinates("x y")
m, g, vx, vy = parameters("m g v_x v_y")

system = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y, name="projectile")


def _el(s):
    """Wells (17.1) form d/dt dL/dqdot - dL/dq (euler_lagrange returns its negative)."""
    return [-e.lhs for e in euler_lagrange(s.T - s.V, s.coordinates, t)]


def _on_book_path(s):
    path = {x: vx * t, y: vy * t - g * t**2 / 2}
    return [sp.simplify(e.subs(path).doit()) for e in _el(s)]


PROBLEM = Problem(
    id="ex17.3",
    title="Projectile by Hamilton's principle: m xdd = 0, m ydd + mg = 0; x = vx t, y = vy t - g t^2/2",
    chapter=17,
    source="Wells, Example 17.3",
    system=system,
    answers=[
        Quantity("Euler-Lagrange equations of the action", _el, [m * x.diff(t, 2), m * y.diff(t, 2) + m * g]),
        Quantity("x = vx t, y = vy t - g t^2/2 satisfy them", _on_book_path, [0, 0]),
        EquationsOfMotion([sp.Eq(m * x.diff(t, 2), 0), sp.Eq(m * y.diff(t, 2) + m * g, 0)], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, g: 9.81}, initial={x: 0, y: 0, x.diff(t): 3, y.diff(t): 4}, t_end=0.8),
)
