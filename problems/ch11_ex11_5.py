"""Wells, Example 11.5 (and Problem 11.4) — sleeping top/disk with the vertical along Y1 and four springs at
the shaft tip: gyroscopic oscillations about the vertical."""

import functools

import numpy as np
import sympy as sp

from lagrange import (
    RigidBody,
    System,
    characteristic_roots,
    coordinates,
    oscillations_about_steady_motion,
    parameters,
    rot_x,
    rot_z,
    routhian,
    t,
)
from lagrange.corpus import ConservedMomenta, Problem, Quantity, Simulation

alpha, beta, phi = coordinates("alpha beta phi")
M, g, r, Ix, Iz, k, l = parameters("M g r I_x I_z k l")

# Spin axis (body z) along (cosα sinβ, cosα cosβ, sinα), Y1 vertical: start with body z along Y1
# (rot_x(-π/2)), tilt by α, swing by β, then spin by φ.
R_body = rot_z(-beta) * rot_x(alpha) * rot_x(-sp.pi / 2) * rot_z(phi)
disk = RigidBody(M, (Ix, Ix, Iz), orientation=R_body, com=(0, 0, r))
tip_x = l * sp.cos(alpha) * sp.sin(beta)
tip_z = l * sp.sin(alpha)
system = System([alpha, beta, phi], bodies=[disk], V=M * g * disk.centre_of_mass[1] + k * (tip_x**2 + tip_z**2),
                name="sleeping top with four springs at the shaft tip")

A = sp.Symbol("alpha", real=True)
B = sp.Symbol("beta", real=True)
AD = sp.Symbol("alpha_dot", real=True)
BD = sp.Symbol("beta_dot", real=True)
c1 = sp.Symbol("p_phi", real=True)
E = M * g * r - 2 * k * l**2
BOOK_R = (Ix * (AD**2 + BD**2 * sp.cos(A) ** 2) / 2 - c1 * BD * sp.sin(A) - M * g * r * sp.cos(A) * sp.cos(B)
          + k * l**2 * sp.cos(A) ** 2 * sp.cos(B) ** 2)


@functools.cache
def _R(s):
    return routhian(s)


@functools.cache
def _lin(s):
    return oscillations_about_steady_motion(_R(s), {alpha: 0, beta: 0})


def _frequencies(s, vals):
    lam = characteristic_roots(_lin(s), vals)
    return sorted(float(abs(x.imag)) for x in lam if x.imag > 0)


STABLE = {"M": 1.0, "g": 9.81, "r": 0.1, "I_x": 0.02, "I_z": 0.03, "k": 5.0, "l": 0.1, "p_phi": 0.6}
UNSTABLE = {**STABLE, "p_phi": 0.05}


def _book_frequencies(vals):
    v = {sp.Symbol(n, positive=True): x for n, x in vals.items() if n != "p_phi"}
    Ev, Ixv, c = float(E.subs(v)), vals["I_x"], vals["p_phi"]
    d = np.sqrt(c**2 - 4 * Ixv * Ev)
    return sorted([(c - d) / (2 * Ixv), (c + d) / (2 * Ixv)])


def _max_real_part(s, vals):
    return sp.Float(float(np.max(characteristic_roots(_lin(s), vals).real)))


def _stable(s, vals):
    """1 when every root is on the imaginary axis (|Re λ| below round-off), else 0."""
    return int(abs(float(_max_real_part(s, vals))) < 1e-9)


PROBLEM = Problem(
    id="ex11.5",
    title="Sleeping top with tip springs (Y1 vertical): Routhian, gyroscopic linearization, frequencies, stability",
    chapter=11,
    source="Wells, Example 11.5 (Problem 11.4 verifies its equations (3))",
    system=system,
    answers=[
        ConservedMomenta({phi: Iz * (phi.diff(t) - beta.diff(t) * sp.sin(alpha))}),
        Quantity("Routhian R up to constants: ∂R/∂(α, β, α̇, β̇)",
                 lambda s: [sp.diff(_R(s).R, v) for v in (A, B, AD, BD)],
                 [sp.diff(BOOK_R, v) for v in (A, B, AD, BD)]),
        Quantity("a, gyroscopic b, stiffness c about α = β = 0 (book: I_xα̈ + c1β̇ − Eα = 0, I_xβ̈ − c1α̇ − Eβ = 0)",
                 lambda s: [*_lin(s).a, *_lin(s).b, *_lin(s).c],
                 [Ix, 0, 0, Ix, 0, c1, -c1, 0, -E, 0, 0, -E]),
        Quantity("frequencies ω = [c1 ± √(c1² − 4I_xE)]/(2I_x), stable numbers",
                 lambda s: _frequencies(s, STABLE), _book_frequencies(STABLE), rtol=1e-9),
        Quantity("stable (1) when c1² + 8I_xkl² > 4I_xMgr", lambda s: _stable(s, STABLE), 1),
        Quantity("max Re λ > 0 (unstable) when c1² + 8I_xkl² < 4I_xMgr: equals Im-free root √(4I_xE − c1²)/(2I_x)",
                 lambda s: _max_real_part(s, UNSTABLE),
                 sp.sqrt(4 * 0.02 * (9.81 * 0.1 - 2 * 5.0 * 0.01) - 0.05**2) / (2 * 0.02), rtol=1e-8),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, r: 0.1, Ix: 0.02, Iz: 0.03, k: 5.0, l: 0.1},
                          initial={alpha: 0.02, beta: 0.01, phi: 0, alpha.diff(t): 0, beta.diff(t): 0,
                                   phi.diff(t): 20.0}, t_end=2),
    correction="For small ψ̇cosθ the book writes c1 = I_xφ̇; p_φ = I_z(φ̇ + ψ̇cosθ) makes it I_zφ̇ (catalog). "
               "The book's R omits constants (−c1²/(2I_z), −kl²), so R is compared through its derivatives. The unstable-case growth rate is the real part of "
               "the book's ω formula when c1² < 4I_xE (derived from it).",
    ranges={"alpha": (-0.5, 0.5), "beta": (-0.5, 0.5)},
)
