"""Wells, Problem 11.7 — conical pendulum whose string is a coil spring (k, l0): steady motion and coupled
oscillations about it."""

import functools

import sympy as sp

from lagrange import (
    Particle,
    System,
    coordinates,
    oscillations_about_steady_motion,
    parameters,
    routhian,
    steady_motion_conditions,
    t,
)
from lagrange.corpus import Problem, Quantity, Simulation

r, theta, psi = coordinates("r theta psi")
m, g, k, l0 = parameters("m g k l_0")
r0, th0, w0 = parameters("r0 theta0 psidot0")
system = System(
    [r, theta, psi],
    bodies=[Particle(m, (r * sp.sin(theta) * sp.cos(psi), r * sp.sin(theta) * sp.sin(psi), -r * sp.cos(theta)))],
    V=-m * g * r * sp.cos(theta) + k * (r - l0) ** 2 / 2,
    name="spring conical pendulum",
)
RR, TH, RD, THD = (sp.Symbol(n, real=True) for n in ("r", "theta", "r_dot", "theta_dot"))
c = sp.Symbol("p_psi", real=True)


@functools.cache
def _R(s):
    return routhian(s)


def _lin(s):
    lin = oscillations_about_steady_motion(_R(s), {r: r0, theta: th0})
    return [*lin.a, *lin.b, *lin.c]


def _steady(s):
    conds = steady_motion_conditions(_R(s))
    at = {r: r0, theta: th0}
    return [sp.simplify(cnd.subs(at).subs(c, m * r0**2 * sp.sin(th0) ** 2 * w0)) for cnd in conds]


c_sa = 2 * c**2 * sp.cos(th0) / (m * r0**3 * sp.sin(th0) ** 3) + m * g * sp.sin(th0)
PROBLEM = Problem(
    id="p11.7",
    title="Spring conical pendulum: Routhian, steady motion, coupled oscillation about it",
    chapter=11,
    source="Wells, Problem 11.7",
    system=system,
    answers=[
        Quantity("Routhian R", lambda s: _R(s).R,
                 m * (RD**2 + RR**2 * THD**2) / 2 - c**2 / (2 * m * RR**2 * sp.sin(TH) ** 2)
                 + m * g * RR * sp.cos(TH) - k * (RR - l0) ** 2 / 2),
        Quantity("steady conditions (∂R/∂r)0, (∂R/∂θ)0 with c = m r0² sin²θ0 ψ̇0", _steady, [
            m * r0 * w0**2 * sp.sin(th0) ** 2 + m * g * sp.cos(th0) - k * (r0 - l0),
            m * r0 * sp.sin(th0) * (r0 * w0**2 * sp.cos(th0) - g)]),
        Quantity("a, b, c of the s (= δr), α (= δθ) oscillation", _lin, [
            m, 0, 0, m * r0**2,
            0, 0, 0, 0,
            3 * c**2 / (m * r0**4 * sp.sin(th0) ** 2) + k, c_sa,
            c_sa, c**2 * (3 * sp.cos(th0) ** 2 + sp.sin(th0) ** 2) / (r0**2 * m * sp.sin(th0) ** 4)
            + m * g * r0 * sp.cos(th0)]),
    ],
    simulation=Simulation(params={m: 1, g: 9.81, k: 100, l0: 1},
                          initial={r: 1.1, theta: 0.6, psi: 0, r.diff(t): 0, theta.diff(t): 0, psi.diff(t): 3.5},
                          t_end=3),
    correction="The steady r condition is compared as (∂R/∂r)0 = m r0ψ̇0² sin²θ0 + mg cosθ0 − k(r0 − l0) and the "
               "θ condition as m r0 sinθ0 (r0ψ̇0² cosθ0 − g), the book's two conditions written = 0.",
)
