"""Wells, Example 13.8 and Problem 13.10 — particle in a smooth hemispherical bowl carried on an arm l turning
at α̇ = ω about a vertical axis: relative equilibrium and the forces holding m at any (θ, φ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, static_equilibrium, t
from lagrange.corpus import EnergySplit, Problem, Quantity, Simulation

theta, phi = coordinates("theta phi")
m, R, l, g, w = parameters("m R l g omega")
f_th, f_ph = sp.symbols("f_theta f_phi", real=True)

al = w * t
pos = (l * sp.cos(al) + R * sp.sin(theta) * sp.cos(al + phi), l * sp.sin(al) + R * sp.sin(theta) * sp.sin(al + phi),
       R - R * sp.cos(theta))
system = System([theta, phi], bodies=[Particle(m, pos)], V=m * g * R * (1 - sp.cos(theta)),
                name="particle in a bowl on a rotating arm")
# P13.10: F'_θ = R f_θ, F'_φ = R sinθ f_φ
held = System([theta, phi], bodies=[Particle(m, pos)], V=m * g * R * (1 - sp.cos(theta)),
              forces=R * f_th * delta(theta) + R * sp.sin(theta) * f_ph * delta(phi),
              name="particle held in a bowl on a rotating arm")
TH, PH = sp.Symbol("theta", real=True), sp.Symbol("phi", real=True)


def _conditions(s):
    d = s.derived
    rest = {v: 0 for v in d.qd}
    return [d.forcing[0].subs(rest), d.forcing[1].subs(rest)]


def _tan_relation(s):
    """With φ = 0 (from the φ condition) the θ condition gives g tanθ − ω²(R sinθ + l) = 0: returned / (m R cosθ)."""
    c = _conditions(s)
    return sp.simplify(c[0].subs(PH, 0) / (m * R * sp.cos(TH)))


def _phi_roots(s):
    c = _conditions(s)[1]
    return sorted(sp.solve(c.subs(TH, sp.pi / 4), PH), key=lambda v: float(v))


def _holding(s):
    sol = static_equilibrium(s, [f_th, f_ph])[0]
    return [sol[f_th], sol[f_ph]]


PROBLEMS = [
    Problem(
        id="ex13.8",
        title="Particle in a bowl on a rotating arm: relative equilibrium φ = 0, g tanθ = ω²(R sinθ + l)",
        chapter=13,
        source="Wells, Example 13.8",
        system=system,
        answers=[
            EnergySplit(B=[m * l * R * w * sp.cos(theta) * sp.sin(phi),
                           m * R * w * (R * sp.sin(theta) ** 2 + l * sp.sin(theta) * sp.cos(phi))],
                        C=m * (l**2 + R**2 * sp.sin(theta) ** 2 + 2 * l * R * sp.sin(theta) * sp.cos(phi)) * w**2 / 2),
            Quantity("equilibrium equations (2), (3) (right minus left side)", _conditions, [
                m * (R**2 * sp.sin(TH) * sp.cos(TH) + l * R * sp.cos(TH) * sp.cos(PH)) * w**2 - m * g * R * sp.sin(TH),
                -m * l * R * sp.sin(TH) * sp.sin(PH) * w**2]),
            Quantity("sinφ = 0: roots φ in [−π, π) at θ = 45°", _phi_roots, [0, sp.pi]),
            Quantity("θ relation at φ = 0", _tan_relation, -(g * sp.tan(TH) - w**2 * (R * sp.sin(TH) + l))),
        ],
        simulation=Simulation(params={m: 1, R: 0.3, l: 0.5, g: 9.81, w: 3.0},
                              initial={theta: 0.5, phi: 0.1, theta.diff(t): 0, phi.diff(t): 0}, t_end=2),
        correction="Equation (2) is printed as −m(...)α̇² = −mgR sinθ; it is compared as the engine's "
                   "(∂C/∂θ − ∂B_θ/∂t + F_θ) = m(...)ω² − mgR sinθ, the same relation.",
        ranges={"theta": (0.2, 1.2)},
    ),
    Problem(
        id="p13.10",
        title="Particle in a bowl on a rotating arm: forces f_θ, f_φ holding it at any (θ, φ)",
        chapter=13,
        source="Wells, Problem 13.10",
        system=held,
        answers=[
            Quantity("f_θ, f_φ", _holding, [
                m * g * sp.sin(theta) - m * (R * sp.sin(theta) * sp.cos(theta)
                                             + l * sp.cos(theta) * sp.cos(phi)) * w**2,
                m * l * w**2 * sp.sin(phi)]),
        ],
        simulation=Simulation(params={m: 1, R: 0.3, l: 0.5, g: 9.81, w: 3.0, f_th: 0, f_ph: 0},
                              initial={theta: 0.5, phi: 0.1, theta.diff(t): 0, phi.diff(t): 0}, t_end=2),
    ),
]
