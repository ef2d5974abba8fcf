"""Wells, Problem 11.9 — two masses joined by a spring in a smooth horizontal tube turning with a free shaft
(inertia I): steady motion r1 = 0, stable s2 oscillation and unstable s1 motion."""

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
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

r1, r2, psi = coordinates("r1 r2 psi")
m1, m2, k, l0, I = parameters("m_1 m_2 k l_0 I")
r0 = parameters("r0")
mu = m1 * m2 / (m1 + m2)
x1 = r1 - m2 * r2 / (m1 + m2)  # r1: c.m. from the axis, r2: separation
x2 = r1 + m1 * r2 / (m1 + m2)
system = System(
    [r1, r2, psi],
    T=I * psi.diff(t) ** 2 / 2,
    bodies=[Particle(m1, (x1 * sp.cos(psi), x1 * sp.sin(psi))), Particle(m2, (x2 * sp.cos(psi), x2 * sp.sin(psi)))],
    V=k * (r2 - l0) ** 2 / 2,
    name="two masses and a spring in a rotating tube",
)
c = sp.Symbol("p_psi", real=True)
J0 = I + mu * r0**2
w0sq = k * (r0 - l0) / (mu * r0)  # steady μ r0 ψ̇0² = k(r0 − l0)


@functools.cache
def _R(s):
    return routhian(s)


def _steady(s):
    return [cnd.subs({r1: 0, r2: r0}).subs(c, J0 * sp.sqrt(w0sq)) for cnd in steady_motion_conditions(_R(s))]


def _w2(s):
    lin = oscillations_about_steady_motion(_R(s), {r1: 0, r2: r0})
    w2 = [lin.c[i, i] / lin.a[i, i] for i in range(2)]
    return [e.subs(c, J0 * sp.sqrt(w0sq)) for e in [*w2, lin.c[0, 1], lin.b[0, 1]]]


NUM = {"m_1": 1.0, "m_2": 2.0, "k": 50.0, "l_0": 1.0, "I": 3.0}


def _growth(s):
    """Largest real root at r0 = 1.5 (c = J0ψ̇0): the s1 motion grows like e^{ψ̇0 t}."""
    mu_v = 2.0 / 3.0
    w0 = np.sqrt(50.0 * 0.5 / (mu_v * 1.5))
    lin = oscillations_about_steady_motion(_R(s), {r1: 0, r2: 1.5})
    lam = characteristic_roots(lin, {**NUM, "p_psi": (3.0 + mu_v * 1.5**2) * w0})
    return sp.Float(float(np.max(lam.real)))


PROBLEM = Problem(
    id="p11.9",
    title="Two masses on a spring in a rotating tube: steady motion, s2 oscillation, unstable s1",
    chapter=11,
    source="Wells, Problem 11.9",
    system=system,
    answers=[
        KineticEnergy((m1 + m2) * (r1.diff(t) ** 2 + r1**2 * psi.diff(t) ** 2) / 2
                      + mu * (r2.diff(t) ** 2 + r2**2 * psi.diff(t) ** 2) / 2 + I * psi.diff(t) ** 2 / 2),
        Quantity("steady conditions at r1 = 0, μr0ψ̇0² = k(r0 − l0)", _steady, [0, 0]),
        Quantity("s1, s2 coefficients c/a, coupling, gyroscopic", _w2, [
            -k / (mu * r0) * (r0 - l0),
            k * (r0 - l0) / (mu * r0) * (3 * mu * r0**2 - I) / (mu * r0**2 + I) + k / mu,
            0, 0]),
        Quantity("growth rate of s1 = ψ̇0 (unstable), m1 = 1, m2 = 2, k = 50, l0 = 1, I = 3, r0 = 1.5",
                 _growth, sp.sqrt(50.0 * 0.5 / (2.0 / 3.0 * 1.5)), rtol=1e-9),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, k: 50, l0: 1, I: 3},
                          initial={r1: 0, r2: 1.5, psi: 0, r1.diff(t): 0, r2.diff(t): 0, psi.diff(t): 5.0},
                          t_end=2),
    correction="The book states r1 = 0 and the two linear equations; instability of s1 (growth e^{ψ̇0 t}) follows "
               "from s̈1 − ψ̇0² s1 = 0 (catalog).",
    ranges={"r0": (1.5, 2.5), "l_0": (0.5, 1.2)},
)
