"""Wells, Example 11.6 — frame rotating about a vertical axis, hinged rod at θ with a spinning disk on a sliding
collar at r: ignorable φ and ψ, steady-motion conditions."""

import functools

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, Problem, Quantity, Simulation

psi, theta, r, phi = coordinates("psi theta r phi")
M, I1, Ix, Iz, k1, k2, l, l0, g = parameters("M I_1 I_x I_z k_1 k_2 l l_0 g")
r0, th0, wpsi, wphi = parameters("r0 theta0 psidot0 phidot0")

psd, thd, rd, phd = psi.diff(t), theta.diff(t), r.diff(t), phi.diff(t)
# The book's L (Fig. 11-6), with the catalog's correction I_z in the spin term.
T = (M * (rd**2 + r**2 * thd**2 + r**2 * psd**2 * sp.cos(theta) ** 2) / 2 + I1 * psd**2 / 2
     + Ix * (psd**2 * sp.cos(theta) ** 2 + thd**2) / 2 + Iz * (phd + psd * sp.sin(theta)) ** 2 / 2)
V = k1 * (r - l0) ** 2 / 2 + k2 * l**2 * theta**2 / 2 + M * g * r * sp.sin(theta)
system = System([psi, theta, r, phi], T=T, V=V, name="rotating frame with hinged rod and spinning disk")

@functools.cache
def _steady(s):
    """Wells (11.10) in its (∂L/∂q)0 = 0 form: the θ and r equations with q̇, q̈ = 0 except the steady rates
    ψ̇0, φ̇0 (the Routhian form (∂R/∂q)0 is equivalent; routhian() takes ~20 s on this system)."""
    d = s.derived
    at = {d.q[1]: th0, d.q[2]: r0, d.qd[0]: wpsi, d.qd[1]: 0, d.qd[2]: 0, d.qd[3]: wphi}
    return {theta: d.forcing[1].subs(at), r: d.forcing[2].subs(at)}


PROBLEM = Problem(
    id="ex11.6",
    title="Rotating frame, hinged rod and spinning disk on a collar: momenta and steady-motion conditions",
    chapter=11,
    source="Wells, Example 11.6",
    system=system,
    answers=[
        ConservedMomenta({
            phi: Iz * (phd + psd * sp.sin(theta)),
            psi: (M * r**2 * sp.cos(theta) ** 2 + I1 + Ix * sp.cos(theta) ** 2) * psd
            + Iz * (phd + psd * sp.sin(theta)) * sp.sin(theta),
        }),
        Quantity("steady condition in θ (= −(∂L/∂θ)0)", lambda s: -_steady(s)[theta],
                 (M * r0**2 + Ix - Iz) * wpsi**2 * sp.sin(th0) * sp.cos(th0) - Iz * wpsi * wphi * sp.cos(th0)
                 + k2 * l**2 * th0 + M * g * r0 * sp.cos(th0)),
        Quantity("steady condition in r (= (∂L/∂r)0)", lambda s: _steady(s)[r],
                 M * r0 * wpsi**2 * sp.cos(th0) ** 2 - k1 * (r0 - l0) - M * g * sp.sin(th0)),
    ],
    simulation=Simulation(params={M: 1, I1: 0.5, Ix: 0.1, Iz: 0.2, k1: 50, k2: 10, l: 0.5, l0: 0.4, g: 9.81},
                          initial={psi: 0, theta: 0.1, r: 0.5, phi: 0, psi.diff(t): 2.0, theta.diff(t): 0,
                                   r.diff(t): 0, phi.diff(t): 30.0}, t_end=3),
    correction="OCR prints p_φ = I_x(...) and the θ condition as '(Mr0² − I_x + I_x)ψ̇0² sinθ0 cosθ0 − I_xψ̇0φ̇0 "
               "cosθ0 + ...'; the catalog re-derived I_z in both places: (Mr0² + I_x − I_z) and −I_zψ̇0φ̇0cosθ0. "
               "The spin term of L is taken as ½I_z(φ̇ + ψ̇ sinθ)² accordingly.",
)
