"""Wells, Example 11.2 (and Problem 11.2) — heavy symmetric top: Routhian, two steady precession rates,
nutation about steady precession."""

import functools

import sympy as sp

from lagrange import (
    EulerAngles,
    RigidBody,
    System,
    coordinates,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    steady_motion_conditions,
    t,
)
from lagrange.corpus import ConservedMomenta, Problem, Quantity, Simulation

psi, theta, phi = coordinates("psi theta phi")
M, g, r, Ix, Iz = parameters("M g r I_x I_z")
theta0, w0 = parameters("theta0 psidot0")  # steady tilt θ0 and precession rate ψ̇0

# Wells' Euler angles (ψ precession, θ nutation from the vertical Z, φ spin); c.m. at distance r on the axis.
top = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, theta, phi), com=(0, 0, r))
system = System([psi, theta, phi], bodies=[top], V=M * g * top.centre_of_mass[2], name="heavy symmetric top")

TH = sp.Symbol("theta", real=True)
THD = sp.Symbol("theta_dot", real=True)
THDD = sp.Symbol("theta_ddot", real=True)
c1 = sp.Symbol("p_phi", real=True)  # Wells' c1 = p_φ
c2 = sp.Symbol("p_psi", real=True)  # Wells' c2 = p_ψ


@functools.cache
def _R(s):
    return routhian(s)


@functools.cache
def _steady(s):
    """(∂R/∂θ)0 = 0 with c2 = I_x ψ̇0 sin²θ0 + c1 cosθ0 (definition of p_ψ at the steady state)."""
    cond = steady_motion_conditions(_R(s))[0].subs(theta, theta0)
    return sp.factor(sp.simplify(cond.subs(c2, Ix * w0 * sp.sin(theta0) ** 2 + c1 * sp.cos(theta0))))


def _two_rates(s):
    """Both roots ψ̇0 of the steady condition: returned as (sum, product, count)."""
    roots = sp.solve(_steady(s), w0)
    return [roots[0] + roots[1], roots[0] * roots[1], len(roots)]


def _rates(s):
    R = _R(s)
    d = dict(zip(R.ignorable, R.ignorable_rates))
    return [d[psi], d[phi]]


def _lin_c_over_a(s):
    """c/a about the steady state, with c2 from p_ψ and c1 from the steady condition."""
    lin = oscillations_about_steady_motion(_R(s), {theta: theta0})
    w2 = lin.c[0, 0] / lin.a[0, 0]
    c1_steady = sp.solve(_steady(s), c1)[0]
    w2 = w2.subs(c2, Ix * w0 * sp.sin(theta0) ** 2 + c1 * sp.cos(theta0)).subs(c1, c1_steady)
    return w2


def _phidot_coefficient(s):
    """φ̇ = φ̇0 + (∂φ̇/∂θ)0 α (Wells Ex. 11.2, linearized spin rate)."""
    return sp.diff(_rates(s)[1], TH).subs(TH, theta0)


ROUTHIAN = (Ix * THD**2 / 2 - (c2 - c1 * sp.cos(TH)) ** 2 / (2 * Ix * sp.sin(TH) ** 2) - M * g * r * sp.cos(TH)
            - c1**2 / (2 * Iz))
PSIDOT = (c2 - c1 * sp.cos(TH)) / (Ix * sp.sin(TH) ** 2)
disc = sp.sqrt(c1**2 - 4 * Ix * M * g * r * sp.cos(theta0))
root_p = (c1 + disc) / (2 * Ix * sp.cos(theta0))
root_m = (c1 - disc) / (2 * Ix * sp.cos(theta0))
RANGES = {"theta0": (0.2, 1.2), "p_phi": (12.0, 16.0), "psidot0": (0.3, 2.0)}
SIM = Simulation(params={M: 1, g: 9.81, r: 0.2, Ix: 0.05, Iz: 0.02},
                 initial={psi: 0, theta: 0.5, phi: 0, psi.diff(t): 2.0, theta.diff(t): 0.1, phi.diff(t): 40.0},
                 t_end=2)

PROBLEMS = [
    Problem(
        id="ex11.2",
        title="Heavy symmetric top: Routhian, steady precession (two rates), nutation about it",
        chapter=11,
        source="Wells, Example 11.2",
        system=system,
        answers=[
            ConservedMomenta({
                phi: Iz * (phi.diff(t) + psi.diff(t) * sp.cos(theta)),
                psi: Ix * psi.diff(t) * sp.sin(theta) ** 2
                + Iz * (phi.diff(t) + psi.diff(t) * sp.cos(theta)) * sp.cos(theta),
            }),
            Quantity("Routhian R", lambda s: _R(s).R, ROUTHIAN),
            Quantity("exact θ equation", lambda s: _R(s).equations()[0],
                     Ix * THDD - PSIDOT**2 * Ix * sp.sin(TH) * sp.cos(TH) + PSIDOT * c1 * sp.sin(TH)
                     - M * g * r * sp.sin(TH)),
            Quantity("steady condition / sinθ0", lambda s: _steady(s) / sp.sin(theta0),
                     Ix * w0**2 * sp.cos(theta0) - c1 * w0 + M * g * r),
            Quantity("two steady rates ψ̇0: sum, product, number", _two_rates,
                     [root_p + root_m, root_p * root_m, 2]),
            Quantity("ω² of nutation about steady precession", _lin_c_over_a,
                     w0**2 + (M * g * r / (Ix * w0)) ** 2 - 2 * M * g * r * sp.cos(theta0) / Ix),
            Quantity("ψ̇ and φ̇ from the momenta", _rates,
                     [PSIDOT, c1 / Iz - (c2 - c1 * sp.cos(TH)) * sp.cos(TH) / (Ix * sp.sin(TH) ** 2)]),
            Quantity("∂φ̇/∂θ at θ0", _phidot_coefficient,
                     (c2 + c2 * sp.cos(theta0) ** 2 - 2 * c1 * sp.cos(theta0)) / (Ix * sp.sin(theta0) ** 3)),
            Quantity("no gyroscopic term", lambda s: oscillations_about_steady_motion(_R(s), {theta: theta0}).b[0, 0],
                     0),
        ],
        simulation=SIM,
        correction="Routhian constant: the OCR prints -c1²/(2I_x); p_φ = I_z(φ̇ + ψ̇cosθ) gives -c1²/(2I_z) "
                   "(irrelevant to the equations). The two rates are checked through their sum c1/(I_x cosθ0) and "
                   "product Mgr/(I_x cosθ0) (root order is arbitrary); the ω² check uses c2 = p_ψ at the steady "
                   "state and c1 from the steady condition, as the book does.",
        ranges=RANGES,
    ),
    Problem(
        id="p11.2",
        title="Heavy top: Routhian expanded to second order about steady precession",
        chapter=11,
        source="Wells, Problem 11.2",
        system=system,
        answers=[
            Quantity("coefficient of -α²/2 in R_approx, divided by I_x", _lin_c_over_a,
                     w0**2 * sp.sin(theta0) ** 2 + (w0 * sp.cos(theta0) - M * g * r / (Ix * w0)) ** 2),
            Quantity("coefficient of α̇²/2 in R_approx",
                     lambda s: sp.diff(_R(s).R, THD, 2).subs(TH, theta0), Ix),
            Quantity("first-order term (∂R/∂θ)0 vanishes at steady motion",
                     lambda s: _steady(s).subs(c1, (Ix * w0**2 * sp.cos(theta0) + M * g * r) / w0), 0),
        ],
        simulation=SIM,
        correction="c/a of the expansion is compared with I_x[...] / I_x; c2 from p_ψ and c1 from the steady "
                   "condition are substituted (the book's ψ̇0 form).",
        ranges=RANGES,
    ),
]
