"""Wells, Problem 13.3 — the carts of Fig. 6-5 (Ex. 6.14) with viscous dashpots a1, a2 and floor drag b1, b2
(springs neglected): equations of motion and the driving forces f1, f2, f3."""

import sympy as sp

from lagrange import System, actuator_forces, coordinates, delta, driving_forces, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

x1, x2, q2 = coordinates("x1 x2 q2")
m1, m2, m3, a1, a2, b1, b2 = parameters("m_1 m_2 m_3 a_1 a_2 b_1 b_2")
v, A, B, w, X1, X2 = parameters("v A B omega X_1 X_2")
f1, f2, f3 = sp.symbols("f1 f2 f3", real=True)
x1d, x2d, q2d = x1.diff(t), x2.diff(t), q2.diff(t)
system = System(
    [x1, x2, q2],
    T=m1 * x1d**2 / 2 + m2 * x2d**2 / 2 + m3 * (x1d + q2d) ** 2 / 2,
    rayleigh=(b1 * x1d**2 + b2 * x2d**2 + a1 * q2d**2 + a2 * (x1d + q2d - x2d) ** 2) / 2,
    name="carts with viscous dashpots and floor drag",
)
motion = {x1: X1 + v * t, x2: X2 + v * t, q2: A + B * sp.sin(w * t)}
F1 = -m3 * w**2 * B * sp.sin(w * t) + a2 * w * B * sp.cos(w * t) + b1 * v
F2 = -a2 * w * B * sp.cos(w * t) + b2 * v
F3 = -m3 * w**2 * B * sp.sin(w * t) + (a1 + a2) * w * B * sp.cos(w * t)


def _forces(s):
    f = driving_forces(s, motion)
    return [f[x1], f[x2], f[q2]]


def _forces_c(s):
    """(c) f2's mechanism fixed to m1: δW = f1 δx1 + f2 δ(x2 − x1) + f3 δq2; returns f1 − f2, f2, f3."""
    f = actuator_forces(s, f1 * delta(x1) + f2 * delta(x2 - x1) + f3 * delta(q2), [f1, f2, f3], motion=motion)
    return [f[f1] - f[f2], f[f2], f[f3]]


PROBLEM = Problem(
    id="p13.3",
    title="Carts with viscous dashpots: f1, f2, f3 for ẋ1 = ẋ2 = v, q2 = A + B sin ωt",
    chapter=13,
    source="Wells, Problem 13.3 (Fig. 6-5)",
    system=system,
    answers=[
        EquationsOfMotion([
            sp.Eq((m1 + m3) * x1.diff(t, 2) + m3 * q2.diff(t, 2) + b1 * x1d + a2 * (x1d + q2d - x2d), 0),
            sp.Eq(m2 * x2.diff(t, 2) + b2 * x2d + a2 * (x2d - x1d - q2d), 0),
            sp.Eq(m3 * (x1.diff(t, 2) + q2.diff(t, 2)) + a1 * q2d + a2 * (x1d + q2d - x2d), 0)],
            per_equation=True),
        Quantity("(b) f1, f2, f3", _forces, [F1, F2, F3]),
        Quantity("(c) f2 mounted on m1: f1 replaced by f1 − f2 in the first equation", _forces_c, [F1, F2, F3]),
    ],
    simulation=Simulation(params={m1: 2, m2: 1, m3: 0.5, a1: 0.3, a2: 0.4, b1: 0.2, b2: 0.1},
                          initial={x1: 0, x2: 1, q2: 0, x1d: 1, x2d: 1, q2d: 0}, t_end=5),
    correction="T and the dissipation function are implied by the book's equations (verified in the catalog); "
               "the drag is a Rayleigh function D (Wells' P = −D).",
)
