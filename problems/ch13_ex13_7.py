"""Wells, Example 13.7 — uniform rod (length 2l) resting inside a smooth semicircular wire of radius R, one end
on the wire and leaning on the rim: equilibrium, relative equilibrium with the wire accelerating at a_x, and the
tangential force holding it at a given θ."""

import numpy as np
import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, static_equilibrium, t
from lagrange.corpus import EnergySplit, Problem, Quantity, Simulation

theta = coordinates("theta")
M, I, R, l, g = parameters("M I R l g")
x0, vx, ax = parameters("x0 v_x a_x")
f = sp.Symbol("f", real=True)

# c.m. (Y measured downward from the rim): x̄ = (2R cosθ − l) cosθ, ȳ = (2R cosθ − l) sinθ
xb = (2 * R * sp.cos(theta) - l) * sp.cos(theta)
yb = (2 * R * sp.cos(theta) - l) * sp.sin(theta)
fixed = System([theta], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (xb, yb))], V=-M * g * yb,
               name="rod in a semicircular wire")
X0 = x0 + vx * t + ax * t**2 / 2
moving = System([theta], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (X0 + xb, yb))], V=-M * g * yb,
                name="rod in an accelerating semicircular wire")
# lower end at R(1 + cos2θ, sin2θ) from the rim point: a tangential force f does 2R f δθ
held = System([theta], T=I * theta.diff(t) ** 2 / 2, bodies=[Particle(M, (X0 + xb, yb))], V=-M * g * yb,
              forces=2 * R * f * delta(theta), name="rod held by a tangential force at its lower end")
TH = sp.Symbol("theta", real=True)


def _cos_equilibria(s):
    """cosθ of the symbolic equilibria with 0 < θ < π/2 (l/R ≤ 2)."""
    sols = static_equilibrium(s, [theta])
    vals = {sp.simplify(sp.cos(sol[theta])) for sol in sols}
    pt = {l: 1.3, R: 1.7}
    good = [v for v in vals if 0 < float(v.subs(pt)) < 1 and float(sp.sin(sp.acos(v.subs(pt)))) > 0]
    return good[0]


NUM = {"M": 1.0, "I": 0.1, "R": 1.0, "l": 0.8, "g": 981.0, "a_x": 300.0, "x0": 0.0, "v_x": 0.0}


def _moving_root_residual(s):
    """Book's relation (a_x sinθ + g cosθ)(4R cosθ − l) − 2gR at the engine's numeric equilibrium."""
    th = static_equilibrium(s, [theta], NUM, {theta: 0.5})[theta]
    res = (300 * np.sin(th) + 981 * np.cos(th)) * (4 * np.cos(th) - 0.8) - 2 * 981 * 1.0
    return sp.Float(round(float(res), 8))  # round-off of the root finder (values ~ 2000) removed


def _condition(s):
    d = s.derived
    return d.forcing[0].subs(d.qd[0], 0)


PROBLEMS = [
    Problem(
        id="ex13.7a",
        title="Rod inside a semicircular wire: equilibrium cosθ = (l + √(l² + 32R²))/(8R)",
        chapter=13,
        source="Wells, Example 13.7",
        system=fixed,
        answers=[
            Quantity("F_θ = −∂V/∂θ", lambda s: _condition(s),
                     M * g * (2 * R * (2 * sp.cos(TH) ** 2 - 1) - l * sp.cos(TH))),
            Quantity("equilibrium cosθ", _cos_equilibria, (l + sp.sqrt(l**2 + 32 * R**2)) / (8 * R)),
        ],
        simulation=Simulation(params={M: 1, I: 0.1, R: 1, l: 0.8, g: 981},
                              initial={theta: 0.5, theta.diff(t): 0}, t_end=1),
        ranges={"l": (0.5, 1.0), "R": (1.0, 2.0)},
    ),
    Problem(
        id="ex13.7b",
        title="Rod in a wire accelerating at a_x: (a_x sinθ + g cosθ)(4R cosθ − l) = 2gR",
        chapter=13,
        source="Wells, Example 13.7",
        system=moving,
        answers=[
            EnergySplit(B=[M * (vx + ax * t) * (l * sp.sin(theta) - 4 * R * sp.sin(theta) * sp.cos(theta))],
                        C=M * (vx + ax * t) ** 2 / 2),
            Quantity("relative-equilibrium condition ∂B/∂t − ∂C/∂θ − F_θ, as −M[...]",
                     lambda s: -_condition(s),
                     -M * ((ax * sp.sin(TH) + g * sp.cos(TH)) * (4 * R * sp.cos(TH) - l) - 2 * g * R)),
            Quantity("book relation at the numeric root (R = 1, l = 0.8, g = 981, a_x = 300)",
                     _moving_root_residual, 0),
        ],
        simulation=Simulation(params={M: 1, I: 0.1, R: 1, l: 0.8, g: 981, vx: 0, ax: 300},
                              initial={theta: 0.5, theta.diff(t): 0}, t_end=1),
        correction="Book's Ch. 13 split T = ΣA q̇q̇ + ΣB q̇ + C (no ½ on A); B and C as derived in the catalog.",
    ),
    Problem(
        id="ex13.7c",
        title="Rod in the accelerating wire held at θ by a tangential force f at its lower end",
        chapter=13,
        source="Wells, Example 13.7",
        system=held,
        answers=[
            Quantity("f from M(a_x sinθ + g cosθ)(l − 4R cosθ) + 2MgR = 2Rf",
                     lambda s: static_equilibrium(s, [f])[0][f],
                     (M * (ax * sp.sin(theta) + g * sp.cos(theta)) * (l - 4 * R * sp.cos(theta)) + 2 * M * g * R)
                     / (2 * R)),
        ],
        simulation=Simulation(params={M: 1, I: 0.1, R: 1, l: 0.8, g: 981, vx: 0, ax: 300, f: 0},
                              initial={theta: 0.5, theta.diff(t): 0}, t_end=1),
    ),
]
