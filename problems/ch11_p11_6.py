"""Wells, Problem 11.6 — rigid pendulum hinged on an arm at distance l from a free shaft of inertia I
(Fig. 11-10): steady motion and the expanded Routhian; free versus driven shaft."""

import functools

import numpy as np
import sympy as sp

from lagrange import (
    Particle,
    System,
    characteristic_roots,
    coordinates,
    linearize,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    steady_motion_conditions,
    t,
)
from lagrange.corpus import Problem, Quantity, Simulation

theta, psi = coordinates("theta psi")
m, g, r, l, I = parameters("m g r l I")
theta0, w0, w = parameters("theta0 psidot0 omega")

rho = l + r * sp.sin(theta)
system = System([theta, psi], T=I * psi.diff(t) ** 2 / 2,
                bodies=[Particle(m, (rho * sp.cos(psi), rho * sp.sin(psi), -r * sp.cos(theta)))],
                V=-m * g * r * sp.cos(theta), name="pendulum on an arm of a free shaft")
# (c) the shaft driven at constant ω
driven = System([theta], bodies=[Particle(m, (rho * sp.cos(w * t), rho * sp.sin(w * t), -r * sp.cos(theta)))],
                V=-m * g * r * sp.cos(theta), name="pendulum on an arm of a driven shaft")

TH = sp.Symbol("theta", real=True)
THD = sp.Symbol("theta_dot", real=True)
C = sp.Symbol("p_psi", real=True)
J0 = I + m * (l + r * sp.sin(theta0)) ** 2
NUM = {"m": 300.0, "g": 980.0, "r": 50.0, "l": 20.0, "I": 2e4}
TH0 = np.pi / 4


@functools.cache
def _R(s):
    return routhian(s)


def _steady(s):
    """(∂R/∂θ)0 with c = J0 ψ̇0, divided by −m r J... : compared with the book's condition times m r."""
    cond = steady_motion_conditions(_R(s))[0].subs(theta, theta0).subs(C, J0 * w0)
    return sp.simplify(cond)


def _coefficients(s):
    """R_approx = ½ a α̇² + K α² + ...: [a, K] from the second derivatives of R at θ0."""
    R = _R(s).R
    return [sp.diff(R, THD, 2).subs(TH, theta0), sp.diff(R, TH, 2).subs(TH, theta0) / 2]


def _numbers(s):
    """θ0 = 45°: ψ̇0 from the steady condition, then ω of the free-shaft oscillation."""
    R = _R(s)
    W = sp.Symbol("W", positive=True)
    J = NUM["I"] + NUM["m"] * (NUM["l"] + NUM["r"] * np.sin(TH0)) ** 2
    cond = steady_motion_conditions(R)[0].subs(theta, TH0).subs(C, J * W).subs(
        {sp.Symbol(k, positive=True): v for k, v in NUM.items()})
    wv = float(sp.nsolve(cond, W, 4.0))
    lam = characteristic_roots(oscillations_about_steady_motion(R, {theta: TH0}), {**NUM, "p_psi": J * wv})
    return [sp.Float(wv), sp.Float(float(np.max(lam.imag)))]


def _driven_omega(_s):
    lam = characteristic_roots(linearize(driven, about={theta: TH0}), {**NUM, "omega": _numbers(system)[0]})
    return sp.Float(float(np.max(lam.imag)))


PROBLEM = Problem(
    id="p11.6",
    title="Pendulum on the arm of a free shaft: steady motion, expanded Routhian, free vs driven frequencies",
    chapter=11,
    source="Wells, Problem 11.6",
    system=system,
    answers=[
        Quantity("steady condition (∂R/∂θ)0 with c = J0ψ̇0", _steady,
                 m * r * ((l + r * sp.sin(theta0)) * w0**2 * sp.cos(theta0) - g * sp.sin(theta0))),
        Quantity("R_approx coefficients of α̇² (×2) and α²", _coefficients, [
            m * r**2,
            -m * r * C**2 / 2 * (4 * m * r * (l + r * sp.sin(theta0)) ** 2 * sp.cos(theta0) ** 2 / J0**3
                                 + (l * sp.sin(theta0) + r * (sp.sin(theta0) ** 2 - sp.cos(theta0) ** 2)) / J0**2)
            - m * g * r * sp.cos(theta0) / 2]),
        Quantity("θ0 = 45° numbers: ψ̇0 and ω (free shaft; derived)", _numbers,
                 [sp.Float("4.2076"), sp.Float("7.316")], rtol=2e-4),
        Quantity("ω with the shaft driven at ψ̇0 (derived)", _driven_omega, sp.Float("4.344"), rtol=2e-4),
    ],
    simulation=Simulation(params={m: 300, g: 980, r: 50, l: 20, I: 2e4},
                          initial={theta: 0.8, psi: 0, theta.diff(t): 0, psi.diff(t): 4.2076}, t_end=3),
    correction="OCR prints '+[mgr cosθ0]α²' in R_approx; the catalog verified −½ mgr cosθ0 α². The numbers "
               "(ψ̇0 = 4.2076, ω = 7.316 free, 4.344 driven) are asked for but not printed: derived in the catalog.",
    units="CGS",
    ranges={"theta0": (0.2, 1.3)},
)
