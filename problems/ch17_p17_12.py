"""Wells, Problem 17.12 — the equations of motion of a particle relative to the rotating earth, (14.15), from
Hamilton's principle: δ∫T dt + ∫ Σ F_q δq dt = 0 gives d/dt(∂T/∂q̇) − ∂T/∂q = F_q for the T (14.14) of Sec. 14.4.

The system is Sec. 14.4's (``ch14_eq14_14``); this variant checks the Euler–Lagrange equations of the action.
"""

from lagrange_problems import ch14_eq14_14 as sec14_4
from lagrange_problems._common import variant
from sympy.calculus.euler import euler_equations

from lagrange import t
from lagrange.corpus import Quantity

x, y, z = sec14_4.x, sec14_4.y, sec14_4.z
m, w, R, s, c = sec14_4.m, sec14_4.w, sec14_4.R, sec14_4.s, sec14_4.c
Fx, Fy, Fz = sec14_4.Fx, sec14_4.Fy, sec14_4.Fz
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

# (14.15), each written as residual = m(...) − F
book = [
    m * (x.diff(t, 2) + 2 * w * (zd * c - yd * s) - w**2 * x) - Fx,
    m * (y.diff(t, 2) + 2 * w * xd * s + w**2 * s * ((R + z) * c - y * s)) - Fy,
    m * (z.diff(t, 2) - 2 * w * xd * c - w**2 * c * ((R + z) * c - y * s)) - Fz,
]


def _action_equations(system):
    """Euler–Lagrange equations of ∫T dt (sympy's ``euler_equations`` gives ∂L/∂q − d/dt ∂L/∂q̇ = 0, unsimplified:
    the library's ``euler_lagrange`` simplifies each and takes seconds here) with the virtual work of the applied
    forces added: d/dt ∂T/∂q̇ − ∂T/∂q − F_q."""
    el = euler_equations(system.T, list(system.coordinates), t)
    return [-e.lhs - system.forces[q] for e, q in zip(el, system.coordinates)]


PROBLEM = variant(
    sec14_4.PROBLEM,
    id="p17.12",
    title="(14.15), the earth-frame equations of motion, from Hamilton's principle",
    chapter=17,
    source="Wells, Problem 17.12 (eqs. (14.14), (14.15))",
    answers=[Quantity("Euler–Lagrange equations of the action with F_q δq", _action_equations, book),
             sec14_4.PROBLEM.answers[1]],  # the same (14.15) through the library's derivation
    correction="",
)
