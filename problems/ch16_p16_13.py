"""Wells, Problem 16.13 — pendulum whose string is drawn in, r = r0 - v t - ½ a t^2 (Fig. 4-19): H != energy."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

th = coordinates("theta")
m, g, r0, v, a = parameters("m g r_0 v a")
ths, pth = sp.Symbol("theta", real=True), sp.Symbol("p_theta", real=True)
r = r0 - v * t - a * t**2 / 2

system = System([th], bodies=[Particle(m, (r * sp.sin(th), -r * sp.cos(th)))], V=-m * g * r * sp.cos(th),
                name="pendulum of varying length")

H_book = pth**2 / (2 * m * (r0 - v * t - a * t**2 / 2) ** 2) - m * (v + a * t) ** 2 / 2 - m * g * r * sp.cos(ths)

PROBLEM = Problem(
    id="p16.13",
    title="Pendulum with string length r0 - vt - at^2/2: H = T1 - T3 + V",
    chapter=16,
    source="Wells, Problem 16.13 (system of Fig. 4-19)",
    system=system,
    answers=[
        Quantity("H", lambda s: hamiltonian(s).H, H_book),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, r0: 2, v: 0.1, a: 0.1}, initial={th: 0.3, th.diff(t): 0}, t_end=3),
    ranges={"t": (0.0, 0.3)},
    correction="The book writes v0 for the initial drawing speed v.",
)
