"""Wells, Problem 2.15 — acceleration components a_r, a_α for x1 = x0 + r cos(α+θ), y1 = y0 + r sin(α+θ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

x0, y0, r, alpha, theta = coordinates("x0 y0 r alpha theta")
m = parameters("m")

u = alpha + theta
system = System(
    [x0, y0, r, alpha, theta],
    bodies=[Particle(m, (x0 + r * sp.cos(u), y0 + r * sp.sin(u)))],
    name="particle about a moving point",
)


def _components(s):
    # (3.24): a_q = (1/h_q)[d/dt ∂T'/∂q̇ − ∂T'/∂q] with T' = T/m; no forces, so that bracket is the left
    # side of Lagrange's equation divided by m.
    pos = s.bodies[0].position_vectors()[0]
    eqs = dict(zip(s.coordinates, s.equations(), strict=True))
    out = []
    for q in (r, alpha):
        h = sp.sqrt(sp.trigsimp(sum(sp.diff(c, q) ** 2 for c in pos)))
        out.append((eqs[q].lhs - eqs[q].rhs) / (m * h))
    return out


ud = alpha.diff(t) + theta.diff(t)
udd = alpha.diff(t, 2) + theta.diff(t, 2)
PROBLEM = Problem(
    id="p2.15",
    title="Acceleration components along r and α for a particle about a moving point",
    chapter=2,
    source="Wells, Problem 2.15",
    system=system,
    answers=[
        Quantity(
            "(a_r, a_alpha)",
            _components,
            [
                x0.diff(t, 2) * sp.cos(u) + y0.diff(t, 2) * sp.sin(u) + r.diff(t, 2) - r * ud**2,
                y0.diff(t, 2) * sp.cos(u) - x0.diff(t, 2) * sp.sin(u) + 2 * r.diff(t) * ud + r * udd,
            ],
        ),
    ],
    correction="The text prints (α̈+θ̈)² in a_r and 2ṙ(α̈+θ̈) in a_α; both are misprints (dimensionally the "
    "centripetal term is r(α̇+θ̇)² and the Coriolis term 2ṙ(α̇+θ̇)); corrected forms re-derived in the catalog "
    "(sym ✓). Singular mass matrix (superfluous coordinates), no simulation.",
)
