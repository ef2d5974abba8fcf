"""Wells, Example 17.7 — mass on a spring in a frame moving with s = vt + ½at^2, viscous drag, by (17.8)."""

import sympy as sp

from lagrange import Particle, System, coordinates, euler_lagrange, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Quantity, Simulation

x = coordinates("x")
m, k, b, v, a = parameters("m k b v a")

# x measured from the moving support at s = vt + at^2/2; drag -b xdot through Wells' (negative) P
system = System([x], bodies=[Particle(m, (v * t + a * t**2 / 2 + x,))], V=k * x**2 / 2,
                P=-b * x.diff(t) ** 2 / 2, name="spring-mass in an accelerating frame with drag")


def _hamilton_17_8(s):
    """(17.8): ∫(δT - δV + F_x δx) dt = 0 -> dL/dx - d/dt dL/dxdot + F_x = 0; returned with Wells' sign."""
    el = euler_lagrange(s.T - s.V, s.coordinates, t)[0].lhs
    return -(el + s.generalized_forces()[x])


PROBLEM = Problem(
    id="ex17.7",
    title="Spring-mass in a moving frame with drag via Hamilton's principle (17.8): m(a + xdd) + b xd + kx = 0",
    chapter=17,
    source="Wells, Example 17.7",
    system=system,
    answers=[
        KineticEnergy(m * (v + a * t + x.diff(t)) ** 2 / 2),
        Quantity("equation from (17.8)", _hamilton_17_8, m * (a + x.diff(t, 2)) + b * x.diff(t) + k * x),
        EquationsOfMotion([sp.Eq(m * (a + x.diff(t, 2)) + b * x.diff(t) + k * x, 0)], per_equation=True),
    ],
    simulation=Simulation(params={m: 1, k: 10, b: 0.5, v: 1, a: 2}, initial={x: 0, x.diff(t): 0}, t_end=5),
    correction="The book prints the drag as 'f = -bx'; it is viscous, f = -b xdot (the printed answer has b xdot).",
)
