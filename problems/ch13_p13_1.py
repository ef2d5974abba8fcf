"""Wells, Problem 13.1 — truck (mass M) on a smooth track carrying a motor whose arm (m, c.m. at r, inertia I)
turns by θ in the vertical plane: driving force f_x and motor torque f_θ."""

import sympy as sp

from lagrange import System, actuator_forces, coordinates, delta, driving_forces, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x, theta = coordinates("x theta")
M, m, r, I, g = parameters("M m r I g")
a, w, A, w1, dl = parameters("a omega A omega_1 delta")
fx, fth = sp.symbols("f_x f_theta", real=True)
system = System([x, theta], T=M * x.diff(t) ** 2 / 2 - m * r * x.diff(t) * theta.diff(t) * sp.sin(theta)
                + I * theta.diff(t) ** 2 / 2, V=m * g * r * sp.sin(theta), name="truck with a motor arm")


def _general(s):
    f = actuator_forces(s, fx * delta(x) + fth * delta(theta), [fx, fth])
    return [f[fx], f[fth]]


def _case(motion):
    def compute(s):
        F = driving_forces(s, motion)
        return [F[x], F[theta]]
    return compute


xdd, thd, thdd = x.diff(t, 2), theta.diff(t), theta.diff(t, 2)
PROBLEM = Problem(
    id="p13.1",
    title="Truck with a motor arm: f_x and motor torque f_θ; θ = ωt with ẍ = a, and x = A sin(ω1 t + δ)",
    chapter=13,
    source="Wells, Problem 13.1",
    system=system,
    answers=[
        Quantity("f_x, f_θ", _general, [
            M * xdd - m * r * thdd * sp.sin(theta) - m * r * thd**2 * sp.cos(theta),
            I * thdd - m * r * xdd * sp.sin(theta) + m * g * r * sp.cos(theta)]),
        Quantity("θ = ωt, x = at²/2 (derived)", _case({x: a * t**2 / 2, theta: w * t}), [
            M * a - m * r * w**2 * sp.cos(w * t), -m * r * a * sp.sin(w * t) + m * g * r * sp.cos(w * t)]),
        Quantity("θ = ωt, x = A sin(ω1t + δ) (derived)", _case({x: A * sp.sin(w1 * t + dl), theta: w * t}), [
            -M * A * w1**2 * sp.sin(w1 * t + dl) - m * r * w**2 * sp.cos(w * t),
            m * r * A * w1**2 * sp.sin(w1 * t + dl) * sp.sin(w * t) + m * g * r * sp.cos(w * t)]),
    ],
    simulation=Simulation(params={M: 5, m: 1, r: 0.3, I: 0.2, g: 9.81},
                          initial={x: 0, theta: 0.3, x.diff(t): 0, theta.diff(t): 0}, t_end=2),
    correction="OCR prints f_x with 'm ṙ θ̈ sinθ' (r is constant: m r θ̈ sinθ) and f_θ with an extra "
               "'− m r ẋ θ̇ cosθ'; Lagrange's equation on the book's T cancels the ẋθ̇ terms (catalog, verified), so "
               "f_θ = Iθ̈ − m r ẍ sinθ + m g r cosθ. The two sub-case formulas are not printed (catalog-derived).",
)
