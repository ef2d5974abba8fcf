"""Wells, Problem 13.5 (system of Example 13.5, Fig. 2-21) — particle m on disk D2 pivoted on disk D1: the forces
keeping r, α̇, θ̇1, θ̇2 constant."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

th1, th2, r, al = coordinates("theta1 theta2 r alpha")
m, s, r0, w1, w2, w3 = parameters("m s r_0 omega_1 omega_2 omega_3")
ang = th1 + th2 + al
system = System([th1, th2, r, al],
                bodies=[Particle(m, (s * sp.cos(th1) + r * sp.cos(ang), s * sp.sin(th1) + r * sp.sin(ang)))],
                name="particle on a disk carried by a turning disk")


def _forces(sys_):
    """Wells (13.1): the prescribed motion substituted into the derived equations (lhs − rhs = F'_q)."""
    motion = {th1: w1 * t, th2: w2 * t, r: r0 + 0 * t, al: w3 * t}
    sub = {c.diff(t, 2): v.diff(t, 2) for c, v in motion.items()}
    sub.update({c.diff(t): v.diff(t) for c, v in motion.items()})
    eqs = dict(zip(sys_.coordinates, sys_.equations()))
    return [(eqs[c].lhs - eqs[c].rhs).subs(sub).subs(motion) for c in (r, al)]

PROBLEM = Problem(
    id="p13.5",
    title="Particle on D2 with r constant and α̇, θ̇1, θ̇2 constant: f_r and F_α",
    chapter=13,
    source="Wells, Problem 13.5",
    system=system,
    answers=[
        Quantity("f_r, F_α = r f_α", _forces, [
            -m * r0 * (w1 + w2 + w3) ** 2 - m * s * w1**2 * sp.cos((w2 + w3) * t),
            m * s * r0 * w1**2 * sp.sin((w2 + w3) * t)]),
    ],
    correction="The book prints f_α = m s r ω1² sin(ω2+ω3)t, which has units of force×length: it is the "
               "generalized force F_α = r f_α (δW = f_α r δα); the tangential force is m s ω1² sin(ω2+ω3)t. "
               "Compared here as F_α (catalog, verified).",
)
