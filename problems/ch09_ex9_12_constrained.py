"""Wells, Example 9.12 by Lagrange multipliers — uniform sphere rolling without slipping on an incline.

Coordinates x̄, ȳ (centre, x̄ down the line of greatest slope, z̄ = r eliminated) and Wells' Euler angles
ψ, θ, φ (z-x-z, ψ precession, φ spin). T = ½ M (ẋ̄² + ẏ̄²) + ½ I (ω_x² + ω_y² + ω_z²) with the body
components (8.11) ω_x = ψ̇ sθ sφ + θ̇ cφ, ω_y = ψ̇ sθ cφ − θ̇ sφ, ω_z = φ̇ + ψ̇ cθ and I = (2/5) M r².
Gravity down the slope: F_x̄ = M g sin ε. The rolling conditions (9.22) in velocity form,
ẋ̄ = r ω_y1 = r(θ̇ sψ − φ̇ sθ cψ) and ẏ̄ = −r ω_x1 = −r(θ̇ cψ + φ̇ sθ sψ), are non-holonomic constraints.
Their rows have A_x̄ = 1 (resp. A_ȳ = 1), so with the engine's rule (λ A_kr added to the applied forces)
λ_x = f_x1 and λ_y = f_y1, the book's contact forces on the sphere (M ẍ̄ = f_x1 + M g sin ε, M ÿ̄ = f_y1).
Book: (I/r² + M) ẍ̄ = M g sin ε, (I/r² + M) ÿ̄ = 0, so ẍ̄ = (5/7) g sin ε, f_x1 = −(2/7) M g sin ε, f_y1 = 0.
"""

import sympy as sp

from lagrange import Nonholonomic, System, coordinates, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, Problem, Quantity, Simulation

xb, yb, psi, th, phi = coordinates("xbar ybar psi theta phi")
M, g, r, eps = parameters("M g r epsilon")
I = sp.Rational(2, 5) * M * r**2  # noqa: E741 - uniform sphere, Wells' I

psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)
wx = psd * sp.sin(th) * sp.sin(phi) + thd * sp.cos(phi)
wy = psd * sp.sin(th) * sp.cos(phi) - thd * sp.sin(phi)
wz = phd + psd * sp.cos(th)
wx1 = thd * sp.cos(psi) + phd * sp.sin(th) * sp.sin(psi)
wy1 = thd * sp.sin(psi) - phd * sp.sin(th) * sp.cos(psi)

T = sp.Rational(1, 2) * M * (xb.diff(t) ** 2 + yb.diff(t) ** 2) + sp.Rational(1, 2) * I * (wx**2 + wy**2 + wz**2)
system = System(
    [xb, yb, psi, th, phi],
    T=T,
    forces={xb: M * g * sp.sin(eps)},
    constraints=[Nonholonomic(xb.diff(t) - r * wy1, name="roll x"), Nonholonomic(yb.diff(t) + r * wx1, name="roll y")],
    name="sphere rolling on an incline (multipliers)",
)


_SOLVED: dict = {}


def _kkt(s):
    """(q̈, λ) from the derived M q̈ = f + Bλ, A q̈ = c (symbolic; cached per system).

    Schur complement: λ = (A M⁻¹ B)⁻¹ (c − A M⁻¹ f), q̈ = M⁻¹ (f + B λ), with each small piece trig-simplified.
    """
    if id(s) not in _SOLVED:
        e = s.derived
        Minv = e.mass_matrix.inv().applyfunc(sp.trigsimp)
        A, B, f = sp.Matrix(e.constraint_matrix), sp.Matrix(e.reaction_matrix), sp.Matrix(e.forcing)
        W = (A * Minv * B).applyfunc(sp.trigsimp)
        lam = W.LUsolve((sp.Matrix(e.constraint_rhs) - A * Minv * f).applyfunc(sp.trigsimp)).applyfunc(sp.simplify)
        qdd = (Minv * (f + B * lam)).applyfunc(sp.simplify)
        _SOLVED[id(s)] = (list(qdd), list(lam))
    return _SOLVED[id(s)]


PARAMS = {M: 1.0, g: 9.81, r: 0.5, eps: 0.4}
_state = {psi: 0.3, th: 1.0, phi: 0.2}
_rates = {psd: 0.4, thd: -0.7, phd: 1.1}
INITIAL = {**_state, xb: 0.0, yb: 0.0, **_rates,
           xb.diff(t): float((r * wy1).subs(_rates).subs(_state).subs(PARAMS)),
           yb.diff(t): float((-r * wx1).subs(_rates).subs(_state).subs(PARAMS))}

PROBLEM = Problem(
    id="ex9.12-multipliers",
    title="Sphere rolling without slipping on an incline: non-holonomic multipliers, x'' = (5/7) g sin(eps)",
    chapter=9,
    source="Wells, Example 9.12",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * M * (xb.diff(t) ** 2 + yb.diff(t) ** 2)
                      + sp.Rational(1, 5) * M * r**2 * (thd**2 + psd**2 + phd**2 + 2 * psd * phd * sp.cos(th))),
        Quantity("acceleration of the centre down the slope", lambda s: _kkt(s)[0][0], sp.Rational(5, 7) * g * sp.sin(eps)),
        Quantity("acceleration of the centre across the slope", lambda s: _kkt(s)[0][1], sp.S.Zero),
        Quantity("contact force f_x1 = lambda_x", lambda s: _kkt(s)[1][0], -sp.Rational(2, 7) * M * g * sp.sin(eps)),
        Quantity("contact force f_y1 = lambda_y", lambda s: _kkt(s)[1][1], sp.S.Zero),
        # along the simulated motion: f_x1 from the book's answer, and from M ẍ̄ = f_x1 + M g sin ε
        ConstraintForce("roll x", -sp.Rational(2, 7) * M * g * sp.sin(eps), PARAMS, INITIAL, t_end=1),
        ConstraintForce("roll x", M * xb.diff(t, 2) - M * g * sp.sin(eps), PARAMS, INITIAL, t_end=1),
        # the book's Euler equation I d/dt(ω_y1) = −f_x1 r with ẋ̄ = r ω_y1: f_x1 = −(I/r²) ẍ̄
        ConstraintForce("roll x", -I / r**2 * xb.diff(t, 2), PARAMS, INITIAL, t_end=1),
    ],
    simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=1),
    ranges={"theta": (0.3, 1.2)},
    correction="f_y1 = 0 is checked symbolically (Quantity): a zero cannot be compared relative to its own size "
    "along a trajectory. The OCR also writes α for the incline angle ε.",
)
