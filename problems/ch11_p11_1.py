"""Wells, Problem 11.1 — Example 11.1 (conical pendulum) by expanding the Routhian about steady motion."""

import functools

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, routhian, steady_motion_conditions, t
from lagrange.corpus import Problem, Quantity, Simulation

theta, psi = coordinates("theta psi")
m, g, r = parameters("m g r")
theta0 = parameters("theta0")
system = System(
    [theta, psi],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(psi), r * sp.sin(theta) * sp.sin(psi), -r * sp.cos(theta)))],
    V=-m * g * r * sp.cos(theta),
    name="conical pendulum",
)
TH = sp.Symbol("theta", real=True)
THD = sp.Symbol("theta_dot", real=True)
C0 = sp.Symbol("p_psi", real=True)
al, ald = sp.symbols("alpha alpha_dot", real=True)


@functools.cache
def _R(s):
    return routhian(s)


def _R_approx(s):
    """Second-order Taylor part of R(θ0 + α, α̇) (terms of order two in α, α̇)."""
    R = _R(s).R.subs({TH: theta0 + al, THD: ald})
    eps = sp.Symbol("eps")
    ser = sp.series(R.subs({al: eps * al, ald: eps * ald}), eps, 0, 3).removeO()
    return ser.coeff(eps, 2)


def _first_order(s):
    """Coefficient of α in R_approx at a steady motion (c0² from the steady condition)."""
    R = _R(s)
    cond = steady_motion_conditions(R)[0].subs(theta, theta0)
    c0sq = sp.solve(cond, C0**2)[0] if cond.has(C0**2) else sp.solve(cond.subs(C0, sp.sqrt(sp.Symbol("P"))),
                                                                     sp.Symbol("P"))[0]
    return sp.diff(R.R, TH).subs(TH, theta0).subs(C0**2, c0sq)


PROBLEM = Problem(
    id="p11.1",
    title="Conical pendulum: Routhian expanded to second order about steady motion",
    chapter=11,
    source="Wells, Problem 11.1",
    system=system,
    answers=[
        Quantity("R_approx (second-order part)", _R_approx,
                 m * r**2 * ald**2 / 2 - (C0**2 / (m * r**2) * (1 + 2 * sp.cos(theta0) ** 2) / sp.sin(theta0) ** 4
                                          + m * g * r * sp.cos(theta0)) * al**2 / 2),
        Quantity("first-order term vanishes at steady motion", _first_order, 0),
    ],
    simulation=Simulation(params={m: 1, g: 980, r: 100},
                          initial={theta: 0.9115, psi: 0, theta.diff(t): 0.05, psi.diff(t): 4.0}, t_end=3),
    ranges={"theta0": (0.2, 1.3), "alpha": (-0.5, 0.5), "alpha_dot": (-0.5, 0.5)},
)
