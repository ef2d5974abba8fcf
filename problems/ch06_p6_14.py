"""Wells, Problem 6.14 — board resting on n equally spaced tacks on a circle of radius R, dry friction f at each
tack: δW = −f Σ (1/v_i)[ẋ − Rθ̇ sin(β_i+θ)][δx − R δθ sin(β_i+θ)] − f Σ (1/v_i)[ẏ + Rθ̇ cos(β_i+θ)][δy + R δθ cos(β_i+θ)]."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, I, R, f = parameters("M I R f")
xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
N = 3  # number of tacks for the check (β_i = (i − 1) 2π/N)
betas = [sp.Rational(2 * i, N) * sp.pi for i in range(N)]

# The engine's model: Wells' power function P = −f Σ |v_i| with the tack positions on the board.
P = 0
for bi in betas:
    X = x + R * sp.cos(bi + theta)
    Y = y + R * sp.sin(bi + theta)
    P += -f * sp.sqrt(X.diff(t) ** 2 + Y.diff(t) ** 2)
system = System([x, y, theta], T=I * thd**2 / 2, bodies=[Particle(M, (x, y))], P=P, name="board on n tacks")

Fx = Fy = Fth = 0
for bi in betas:
    ux, uy = xd - R * thd * sp.sin(bi + theta), yd + R * thd * sp.cos(bi + theta)
    v = sp.sqrt(ux**2 + uy**2)
    Fx += -f * ux / v
    Fy += -f * uy / v
    Fth += -f * ux * (-R * sp.sin(bi + theta)) / v - f * uy * R * sp.cos(bi + theta) / v

PROBLEM = Problem(
    id="p6.14",
    title="Board on n equally spaced tacks on a circle (n = 3): dry-friction coefficients of δx, δy, δθ",
    chapter=6,
    source="Wells, Problem 6.14",
    system=system,
    answers=[GeneralizedForces({x: Fx, y: Fy, theta: Fth})],
    simulation=Simulation(params={M: 1, I: 0.3, R: 0.5, f: 0.2},
                          initial={x: 0, y: 0, theta: 0, xd: 1, yd: 0.5, thd: 1}, t_end=0.5),
    correction="The book's sum is over general n; it is checked for n = 3 (α = 2π/3).",
)
