"""Wells, Example 13.1 — m1 on a rope over a pulley with a spring to m2: driving forces f1 (on m1) and f2 (on
m2) for a prescribed motion, in coordinates (y1, y2) and again in (y1, y3)."""

import sympy as sp

from lagrange import System, actuator_forces, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, Problem, Quantity, Simulation

y1, y2 = coordinates("y1 y2")
y3 = coordinates("y3")
m1, m2, I, R, k, l0, g, b = parameters("m_1 m_2 I R k l_0 g b")
y0, v, A, w, dl = parameters("y0 v A omega delta")
f1, f2 = sp.symbols("f1 f2", real=True)

sys_a = System([y1, y2],
               T=(m1 + I / R**2) * y1.diff(t) ** 2 / 2 + m2 * (y1.diff(t) - y2.diff(t)) ** 2 / 2,
               V=-m1 * g * y1 + m2 * g * (y1 - y2 - b) + k * (y2 - l0) ** 2 / 2,
               name="pulley, rope and spring in (y1, y2)")
# y1 − y2 − y3 = b
sys_b = System([y1, y3],
               T=(m1 + I / R**2) * y1.diff(t) ** 2 / 2 + m2 * y3.diff(t) ** 2 / 2,
               V=-m1 * g * y1 + m2 * g * y3 + k * (y1 - y3 - b - l0) ** 2 / 2,
               name="pulley, rope and spring in (y1, y3)")

motion_y1 = y0 + v * t
motion_y2 = l0 + A * sp.sin(w * t + dl)
F1 = m2 * A * w**2 * sp.sin(w * t + dl) + (m2 - m1) * g
F2 = A * (k - m2 * w**2) * sp.sin(w * t + dl) - m2 * g


def _forces_a(s):
    f = actuator_forces(s, f1 * delta(y1) + f2 * delta(y2), [f1, f2], motion={y1: motion_y1, y2: motion_y2})
    return [f[f1], f[f2]]


def _forces_b(s):
    # f2 acts on m2 along y2 = y1 − y3 − b: δy2 = δy1 − δy3, so F'_y1 = f1 + f2, F'_y3 = −f2
    f = actuator_forces(s, f1 * delta(y1) + f2 * delta(y1 - y3), [f1, f2],
                        motion={y1: motion_y1, y3: motion_y1 - motion_y2 - b})
    return [f[f1], f[f2]]


c = b + l0
SIM = dict(params={m1: 2, m2: 1, I: 0.5, R: 0.3, k: 40, l0: 1, g: 9.81, b: 2}, t_end=3)
PROBLEMS = [
    Problem(
        id="ex13.1a",
        title="Pulley, rope and spring: driving forces f1, f2 for y1 = y0 + vt, y2 = l0 + A sin(ωt + δ)",
        chapter=13,
        source="Wells, Example 13.1 (equations (1), (2))",
        system=sys_a,
        answers=[
            EquationsOfMotion([
                sp.Eq((m1 + m2 + I / R**2) * y1.diff(t, 2) - m2 * y2.diff(t, 2) + (m2 - m1) * g, 0),
                sp.Eq(m2 * (y2.diff(t, 2) - y1.diff(t, 2)) - m2 * g + k * (y2 - l0), 0)], per_equation=True),
            Quantity("f1, f2 as functions of t", _forces_a, [F1, F2]),
        ],
        simulation=Simulation(initial={y1: 0, y2: 1.2, y1.diff(t): 0, y2.diff(t): 0}, **SIM),
    ),
    Problem(
        id="ex13.1b",
        title="Same system in (y1, y3): the same driving forces (coordinate invariance)",
        chapter=13,
        source="Wells, Example 13.1 (equations (3), (4))",
        system=sys_b,
        answers=[
            EquationsOfMotion([
                sp.Eq((m1 + I / R**2) * y1.diff(t, 2) - m1 * g + k * (y1 - y3 - c), 0),
                sp.Eq(m2 * y3.diff(t, 2) + m2 * g - k * (y1 - y3 - c), 0)], per_equation=True),
            Quantity("f1, f2 as functions of t (same as in (y1, y2))", _forces_b, [F1, F2]),
        ],
        simulation=Simulation(initial={y1: 0, y3: -3.2, y1.diff(t): 0, y3.diff(t): 0}, **SIM),
        correction="c = b + l0 (implied by the book's equations (3), (4)).",
    ),
]
