"""Wells, Example 13.3 — cart (body M1, four wheels M, I, r) carrying a mass m on its incline (angle θ) held by a
spring k: driving forces f (on the cart) and f_q (on m along the incline) for a prescribed motion."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Quantity, Simulation

x, q = coordinates("x q")
M1, M, I, r, m, k, q0, g, th = parameters("M_1 M I r m k q_0 g theta")
x0, A, B, w1, w2, d1, d2 = parameters("x_0 A B omega_1 omega_2 delta_1 delta_2")

Mt = M1 + 4 * M + 4 * I / r**2 + m
T = Mt * x.diff(t) ** 2 / 2 + m * (q.diff(t) ** 2 - 2 * x.diff(t) * q.diff(t) * sp.cos(th)) / 2
system = System([x, q], T=T, V=k * (q - q0) ** 2 / 2 - m * g * q * sp.sin(th),
                name="cart with a spring-held mass on its incline")

xm = x0 + A * sp.sin(w1 * t + d1)
qm = q0 + B * sp.sin(w2 * t + d2)


def _forces(s):
    """Wells (13.1): substitute the prescribed motion into the derived equations (lhs − rhs = F'_q)."""
    sub = {x.diff(t, 2): xm.diff(t, 2), q.diff(t, 2): qm.diff(t, 2), x.diff(t): xm.diff(t), q.diff(t): qm.diff(t)}
    return [(e.lhs - e.rhs).subs(sub).subs({x: xm, q: qm}) for e in s.equations()]


# Book: f = −ω1²(M1+4M+4I/r²+m) x + m ω2² q cosθ, f_q = m(ω1² x cosθ − ω2² q) + k(q − q0) − mg sinθ,
# with x → x − x0 = A sin(ω1 t + δ1) and q → q − q0 = B sin(ω2 t + δ2) in the inertia terms (see correction).
X, Q = xm - x0, qm - q0
PROBLEM = Problem(
    id="ex13.3",
    title="Cart with a spring-held mass on its incline: driving forces f, f_q for sinusoidal x and q",
    chapter=13,
    source="Wells, Example 13.3 (Fig. 4-11)",
    system=system,
    answers=[
        KineticEnergy(T),
        EquationsOfMotion([
            sp.Eq(Mt * x.diff(t, 2) - m * q.diff(t, 2) * sp.cos(th), 0),
            sp.Eq(m * (q.diff(t, 2) - x.diff(t, 2) * sp.cos(th)) + k * (q - q0) - m * g * sp.sin(th), 0)],
            per_equation=True),
        Quantity("f, f_q for x = x0 + A sin(ω1t+δ1), q = q0 + B sin(ω2t+δ2)", _forces, [
            -w1**2 * Mt * X + m * w2**2 * Q * sp.cos(th),
            m * (w1**2 * X * sp.cos(th) - w2**2 * Q) + k * (qm - q0) - m * g * sp.sin(th)]),
    ],
    simulation=Simulation(params={M1: 5, M: 0.5, I: 0.01, r: 0.2, m: 1, k: 50, q0: 0.5, g: 9.81, th: 0.5},
                          initial={x: 0, q: 0.5, x.diff(t): 0, q.diff(t): 0}, t_end=3),
    correction="The book substitutes ẍ = −ω1² x and q̈ = −ω2² q, exact only for x0 = 0 and q oscillating about 0; "
               "with x = x0 + A sin(ω1t+δ1), q = q0 + B sin(ω2t+δ2) the inertia terms use (x − x0) and (q − q0) "
               "(catalog note). V = k(q − q0)²/2 − mgq sinθ is implied by the book's equations.",
    ranges={"theta": (0.1, 1.4)},
)
