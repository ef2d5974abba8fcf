"""Wells, Problem 17.3 — harmonic oscillator: action along x = A sin ωt and along x + ε sin 2ωt over [0, π/2ω]."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x = coordinates("x")
m, k, A, eps = parameters("m k A epsilon")
w = sp.sqrt(k / m)

system = System([x], bodies=[Particle(m, (x,))], V=k * x**2 / 2, name="harmonic oscillator")

true_path = A * sp.sin(w * t)
variation = sp.sin(2 * w * t)


def _J(s, path):
    L = (s.T - s.V).subs(x, path).doit()
    return sp.integrate(sp.expand(L), (t, 0, sp.pi / (2 * w)))


def _difference(s):
    return sp.simplify(_J(s, true_path + eps * variation) - _J(s, true_path))


def _first_variation(s):
    e = sp.Symbol("e")
    L = (s.T - s.V).subs(x, true_path + e * variation).doit()
    return sp.simplify(sp.integrate(sp.expand(sp.diff(L, e).subs(e, 0)), (t, 0, sp.pi / (2 * w))))


PROBLEM = Problem(
    id="p17.3",
    title="Harmonic oscillator: J_v - J = (3/8) pi m omega eps^2 for the varied path A sin wt + eps sin 2wt",
    chapter=17,
    source="Wells, Problem 17.3",
    system=system,
    answers=[
        Quantity("first-order variation of the action", _first_variation, 0),
        Quantity("J_v - J", _difference, sp.Rational(3, 8) * sp.pi * m * w * eps**2),
    ],
    simulation=Simulation(params={m: 1, k: 4}, initial={x: 0, x.diff(t): 2}, t_end=5),
    correction="The book prints J_v - J = (8/3) m pi omega eps^2; direct integration gives (3/8) pi m omega eps^2 "
    "(catalog, verified: the eps^2 term is (m/2) eps^2 ∫(4w^2 cos^2 2wt - w^2 sin^2 2wt) dt = (m/2) eps^2 "
    "(3 w^2)(pi/4w)).",
)
