"""Wells, Problem 11.13 — top pivoted at its c.m. on a rotating table (Example 11.7, Fig. 11-7): Routhian in θ,
steady condition and small oscillations about a steady motion."""

import functools

import sympy as sp

from lagrange import (
    System,
    coordinates,
    parameters,
    routhian,
    steady_motion_conditions,
    t,
)
from lagrange.corpus import Problem, Quantity, Simulation

psi1, theta, phi, psi = coordinates("psi1 theta phi psi")
I, M, R1, Ix, Iz = parameters("I M R_1 I_x I_z")
theta0 = parameters("theta0")
W = psi1.diff(t) + psi.diff(t)
L = ((I + M * R1**2) * psi1.diff(t) ** 2 / 2
     + (Ix * (theta.diff(t) ** 2 + W**2 * sp.sin(theta) ** 2) + Iz * (phi.diff(t) + W * sp.cos(theta)) ** 2) / 2)
system = System([psi1, theta, phi, psi], T=L, name="top on a rotating table")

TH, THD = sp.Symbol("theta", real=True), sp.Symbol("theta_dot", real=True)
c2, c3 = sp.Symbol("p_phi", real=True), sp.Symbol("p_psi", real=True)
R_book = Ix * THD**2 / 2 - (c3 - c2 * sp.cos(TH)) ** 2 / (2 * Ix * sp.sin(TH) ** 2)


@functools.cache
def _R(s):
    return routhian(s, ignorable=(psi1, phi, psi))


def _R_gradient(s):
    """∂R/∂θ̇ and ∂R/∂θ (the book drops constants in R)."""
    R = _R(s).R
    return [sp.diff(R, THD), sp.diff(R, TH)]


def _steady(s):
    """(∂R/∂θ)_0 times −I_x sin³θ."""
    return -Ix * sp.sin(theta) ** 3 * steady_motion_conditions(_R(s))[0]


def _lin(s):
    """a = ∂²R/∂θ̇², c = −∂²R/∂θ² at θ = θ0 (Wells 11.11; same as oscillations_about_steady_motion, unsimplified)."""
    R = _R(s).R
    at = {TH: theta0, THD: 0}
    return [sp.diff(R, THD, 2).subs(at), -sp.diff(R, TH, 2).subs(at)]


u = c3 - c2 * sp.cos(theta0)
PROBLEM = Problem(
    id="p11.13",
    title="Top on a rotating table: Routhian in θ, steady condition, oscillation about steady motion",
    chapter=11,
    source="Wells, Problem 11.13 (Example 11.7, Fig. 11-7)",
    system=system,
    answers=[
        Quantity("ψ1, φ, ψ ignorable: ∂T/∂q = 0", lambda s: [sp.diff(s.T, q) for q in (psi1, phi, psi)], [0, 0, 0]),
        Quantity("c2 = p_φ, c3 = p_ψ", lambda s: [sp.diff(s.T, phi.diff(t)), sp.diff(s.T, psi.diff(t))],
                 [Iz * (phi.diff(t) + W * sp.cos(theta)),
                  Ix * W * sp.sin(theta) ** 2 + Iz * (phi.diff(t) + W * sp.cos(theta)) * sp.cos(theta)]),
        Quantity("∂R/∂θ̇, ∂R/∂θ of R = ½I_xθ̇² − ½(c3 − c2 cosθ)²/(I_x sin²θ)", _R_gradient,
                 [sp.diff(R_book, THD), sp.diff(R_book, TH)]),
        Quantity("steady condition (c3 − c2 cosθ0)(c2 − c3 cosθ0) = 0", _steady,
                 (c3 - c2 * sp.cos(theta)) * (c2 - c3 * sp.cos(theta))),
        Quantity("I_x α̈ + (1/I_x){...} α = 0: a and c", _lin, [
            Ix, (c2**2 + u / sp.sin(theta0) ** 4 * (c3 * (1 + 2 * sp.cos(theta0) ** 2)
                                                    - c2 * (3 + sp.sin(theta0) ** 2) * sp.cos(theta0))) / Ix]),
    ],
    simulation=Simulation(params={I: 1, M: 1, R1: 0.5, Ix: 0.2, Iz: 0.3},
                          initial={psi1: 0, theta: 0.7, phi: 0, psi: 0, psi1.diff(t): 1.0, theta.diff(t): 0,
                                   phi.diff(t): 5.0, psi.diff(t): 0.5}, t_end=3),
    correction="Example 11.7's L is printed with I_x in the last term; I_z is right (catalog). c2 = p_φ, c3 = p_ψ; "
               "the constant term in p_ψ1 is dropped from R as in the book.",
    ranges={"theta0": (0.2, 1.3), "p_phi": (-1, 1), "p_psi": (-1, 1)},
)
