"""Wells, Problem 6.7 — sheet carrying a bar magnet over poles (Fig. 6-14), vertical motion y1, y2, viscous drag."""

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

y1, y2 = coordinates("y1 y2")
M1, M2, a1, a2, a3 = parameters("M1 M2 a1 a2 a3")

# Relative velocities at the three damping gaps (kinematics inferred from the answers, see correction).
gaps = (2 * y1.diff(t), 2 * y1.diff(t) - y2.diff(t), 2 * y1.diff(t) + y2.diff(t))
T = M1 * y1.diff(t) ** 2 / 2 + M2 * y2.diff(t) ** 2 / 2
system = System([y1, y2], T=T, P=-sum(a * u**2 for a, u in zip((a1, a2, a3), gaps, strict=True)) / 2, name="sheet, viscous")

y1d, y2d = y1.diff(t), y2.diff(t)
PROBLEM = Problem(
    id="p6.7",
    title="Sheet with bar magnet, viscous eddy-current drag: F_y1, F_y2",
    chapter=6,
    source="Wells, Problem 6.7",
    system=system,
    answers=[GeneralizedForces({y1: -4 * (a1 + a2 + a3) * y1d + 2 * (a2 - a3) * y2d,
                                y2: 2 * (a2 - a3) * y1d - (a2 + a3) * y2d})],
    simulation=Simulation(params={M1: 1, M2: 1, a1: 0.2, a2: 0.3, a3: 0.1},
                          initial={y1: 0, y2: 0, y1.diff(t): 1, y2.diff(t): -0.5}, t_end=5),
    ranges={"y1_dot": (-0.9, 0.9), "y2_dot": (-0.9, 0.9)},
    correction="Figure 6-14 is not available; the gap velocities 2 y1d, 2 y1d - y2d, 2 y1d + y2d are the catalog's "
    "inference (P = -[a1(2y1d)^2 + a2(2y1d - y2d)^2 + a3(2y1d + y2d)^2]/2), which reproduces both 6.7 and 6.16. "
    "M1, M2 in T are assumed for simulation.",
)
