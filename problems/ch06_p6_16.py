"""Wells, Problem 6.16 — the sheet of Problem 6.7 (Fig. 6-14) with quadratic drag a'|v|v at the three gaps."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

y1, y2 = coordinates("y1 y2")
M1, M2, b1, b2, b3 = parameters("M1 M2 a1p a2p a3p")  # a1', a2', a3'

gaps = (2 * y1.diff(t), 2 * y1.diff(t) - y2.diff(t), 2 * y1.diff(t) + y2.diff(t))
T = M1 * y1.diff(t) ** 2 / 2 + M2 * y2.diff(t) ** 2 / 2
# Drag a'|u|u opposite the gap velocity u: P = -sum a' |u|^3 / 3 (6.14 with n = 2).
system = System([y1, y2], T=T, P=-sum(b * sp.Abs(u) ** 3 for b, u in zip((b1, b2, b3), gaps, strict=True)) / 3,
                name="sheet, quadratic drag")

y1d, y2d = y1.diff(t), y2.diff(t)
u2, u3 = 2 * y1d - y2d, 2 * y1d + y2d
PROBLEM = Problem(
    id="p6.16",
    title="Problem 6.7 with quadratic drag a'|v|v: F_y1, F_y2",
    chapter=6,
    source="Wells, Problem 6.16",
    system=system,
    answers=[GeneralizedForces({
        y1: -8 * b1 * sp.Abs(y1d) * y1d - 2 * b2 * sp.Abs(u2) * u2 - 2 * b3 * sp.Abs(u3) * u3,
        y2: b2 * sp.Abs(u2) * u2 - b3 * sp.Abs(u3) * u3,
    })],
    simulation=Simulation(params={M1: 1, M2: 1, b1: 0.2, b2: 0.3, b3: 0.1},
                          initial={y1: 0, y2: 0, y1.diff(t): 1, y2.diff(t): -0.5}, t_end=5),
    ranges={"y1_dot": (-0.9, 0.9), "y2_dot": (-0.9, 0.9)},
    correction="Figure 6-14 is not available; the gap velocities 2 y1d, 2 y1d - y2d, 2 y1d + y2d are the catalog's "
    "inference from Problem 6.7. M1, M2 in T are assumed for simulation.",
)
