"""Wells, Example 11.1 — conical pendulum: Routhian, steady motion and oscillation about it."""

import functools

import numpy as np
import sympy as sp

from lagrange import (
    Particle,
    System,
    characteristic_roots,
    coordinates,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    steady_motion_conditions,
    t,
)
from lagrange.corpus import ConservedMomenta, Problem, Quantity, Simulation

theta, psi = coordinates("theta psi")
m, g, r = parameters("m g r")
theta0, psid0 = parameters("theta0 psidot0")  # steady values θ0, ψ̇0

# Bob at polar angle θ from the downward vertical, azimuth ψ (Z up).
system = System(
    [theta, psi],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(psi), r * sp.sin(theta) * sp.sin(psi), -r * sp.cos(theta)))],
    V=-m * g * r * sp.cos(theta),
    name="conical pendulum",
)

TH = sp.Symbol("theta", real=True)
THD = sp.Symbol("theta_dot", real=True)
THDD = sp.Symbol("theta_ddot", real=True)
C0 = sp.Symbol("p_psi", real=True)


@functools.cache
def _R(s):
    return routhian(s)


def _steady_rate_squared(s):
    """Steady condition (∂R/∂θ)0 = 0 with c0 = m r² sin²θ0 ψ̇0, solved for ψ̇0 (both signs: ψ̇0²)."""
    R = _R(s)
    cond = steady_motion_conditions(R)[0].subs(theta, theta0).subs(R.momenta[0], m * r**2 * sp.sin(theta0) ** 2 * psid0)
    roots = {sp.simplify(w**2) for w in sp.solve(cond, psid0) if w != 0}
    assert len(roots) == 1
    return roots.pop()


def _omega2(s):
    lin = oscillations_about_steady_motion(_R(s), {theta: theta0})
    return lin.c[0, 0] / lin.a[0, 0]


def _period(s):
    """2π/ω with c0 from the steady motion (ψ̇0² = g/(r cosθ0))."""
    R = _R(s)
    lin = oscillations_about_steady_motion(R, {theta: theta0})
    w2 = (lin.c[0, 0] / lin.a[0, 0]).subs(R.momenta[0], m * r**2 * sp.sin(theta0) ** 2 * sp.sqrt(_steady_rate_squared(s)))
    return 2 * sp.pi / sp.sqrt(w2)


def _cos_theta0_numeric(s):
    """r = 100 cm, g = 980, ψ̇0 = 4 rad/s: root of the steady condition in (0, π/2)."""
    R = _R(s)
    vals = {m: 1, g: 980, r: 100}
    cond = steady_motion_conditions(R)[0].subs(R.momenta[0], m * r**2 * sp.sin(theta) ** 2 * 4).subs(vals)
    th0 = sp.nsolve(cond.subs(theta, TH), TH, 0.9)
    return sp.cos(th0)


def _period_numeric(s):
    R = _R(s)
    vals = {"m": 1, "g": 980, "r": 100}
    th0 = float(sp.acos(_cos_theta0_numeric(s)))
    c0 = 100**2 * np.sin(th0) ** 2 * 4
    lin = oscillations_about_steady_motion(R, {theta: th0})
    lam = characteristic_roots(lin, {**vals, "p_psi": c0})
    return sp.Float(2 * np.pi / float(np.max(np.abs(lam.imag))))


def _precession_coefficient(s):
    """ψ̇ = ψ̇0 + (∂ψ̇/∂θ)0 α: the first-order change of the precession rate (11.15)."""
    R = _R(s)
    return sp.diff(R.ignorable_rates[0], TH).subs(TH, theta0)


PROBLEM = Problem(
    id="ex11.1",
    title="Conical pendulum: Routhian, steady motion cosθ0 = g/(rψ̇0²), oscillation about it",
    chapter=11,
    source="Wells, Example 11.1",
    system=system,
    answers=[
        ConservedMomenta({psi: m * r**2 * sp.sin(theta) ** 2 * psi.diff(t)}),
        Quantity("Routhian R", lambda s: _R(s).R,
                 m * r**2 * THD**2 / 2 - C0**2 / (2 * m * r**2 * sp.sin(TH) ** 2) + m * g * r * sp.cos(TH)),
        Quantity("reduced θ equation / (m r²)", lambda s: _R(s).equations()[0] / (m * r**2),
                 THDD - C0**2 * sp.cos(TH) / (m**2 * r**4 * sp.sin(TH) ** 3) + g / r * sp.sin(TH)),
        Quantity("steady precession rate ψ̇0² (cosθ0 = g/(rψ̇0²))", _steady_rate_squared, g / (r * sp.cos(theta0))),
        Quantity("ω² of α about steady motion",
                 _omega2, C0**2 / (m**2 * r**4) * (1 + 2 * sp.cos(theta0) ** 2) / sp.sin(theta0) ** 4
                 + g / r * sp.cos(theta0)),
        Quantity("period about steady motion", _period,
                 2 * sp.pi * sp.sqrt(r / g * sp.cos(theta0) / (1 + 3 * sp.cos(theta0) ** 2))),
        Quantity("∂ψ̇/∂θ at θ0 (precession after a disturbance)", _precession_coefficient,
                 -2 * C0 * sp.cos(theta0) / (m * r**2 * sp.sin(theta0) ** 3)),
        Quantity("cosθ0 for r = 100 cm, ψ̇0 = 4 rad/s", _cos_theta0_numeric, sp.Rational(98, 160)),
        Quantity("period for r = 100 cm, ψ̇0 = 4 rad/s (derived)", _period_numeric, sp.Float("1.0774"), rtol=1e-4),
    ],
    simulation=Simulation(params={m: 1, g: 980, r: 100},
                          initial={theta: 0.9115, psi: 0, theta.diff(t): 0.05, psi.diff(t): 4.0}, t_end=3),
    correction="The numeric period 1.0774 s is not printed in the book (derived in the catalog from the book's "
               "formula with r = 100 cm, ψ̇0 = 4 rad/s); the printed cosθ0 = 9.8/16 is.",
    units="CGS",
    ranges={"theta0": (0.2, 1.3)},
)
