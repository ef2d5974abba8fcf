"""Wells, Problems 6.6 and 6.20 — disk of radius r on an oil film (a per unit area); rectangle 2b x 2c variant."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, PowerFunction, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, I, a, r, b, c = parameters("M I a r b c")
rho, psi, x2, y2 = sp.symbols("rho psi x2 y2", real=True)


def _board_P(u, w, region):
    """-(a/2) times the integral of v^2 over the board; (u, w) are board-fixed element coordinates."""
    X = x + u * sp.cos(theta) - w * sp.sin(theta)
    Y = y + u * sp.sin(theta) + w * sp.cos(theta)
    v2 = sp.expand(X.diff(t) ** 2 + Y.diff(t) ** 2)
    return sp.simplify(-a / 2 * sp.integrate(v2, *region))


P_disk = _board_P(rho * sp.cos(psi), rho * sp.sin(psi), [(psi, 0, 2 * sp.pi)])  # then dA = rho drho dpsi
P_disk = sp.simplify(sp.integrate(P_disk * rho, (rho, 0, r)))
P_rect = _board_P(x2, y2, [(x2, -b, b), (y2, -c, c)])
T = I * theta.diff(t) ** 2 / 2
disk = System([x, y, theta], T=T, bodies=[Particle(M, (x, y))], P=P_disk, name="disk on an oil film")
rect = System([x, y, theta], T=T, bodies=[Particle(M, (x, y))], P=P_rect, name="rectangle on an oil film")

xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)
A = sp.pi * r**2
sim = {M: 1, I: 0.2, a: 0.3}
start = {x: 0, y: 0, theta: 0, x.diff(t): 1, y.diff(t): 0.5, theta.diff(t): 2}
PROBLEMS = [
    Problem(
        id="p6.6",
        title="Disk on an oil film: F_x = -A a xd, F_y = -A a yd, F_theta = -(1/2) A a r^2 thd, A = pi r^2",
        chapter=6,
        source="Wells, Problem 6.6 (P form: Problem 6.20)",
        system=disk,
        answers=[
            GeneralizedForces({x: -A * a * xd, y: -A * a * yd, theta: -A * a * r**2 * thd / 2}),
            PowerFunction(-sp.pi * r**2 * a * (xd**2 + yd**2) / 2 - sp.pi * r**4 * a * thd**2 / 4),
        ],
        simulation=Simulation(params={**sim, r: 0.5}, initial=start, t_end=5),
        correction="The film drag is integrated symbolically over the disk; M and I are assumed for T.",
    ),
    Problem(
        id="p6.6-rectangle",
        title="Rectangle 2b x 2c on an oil film: P = -(1/2) a A (xd^2+yd^2) - (1/6) a A (b^2+c^2) thd^2",
        chapter=6,
        source="Wells, Problem 6.20",
        system=rect,
        answers=[PowerFunction(-a * (4 * b * c) * (xd**2 + yd**2) / 2 - a * (4 * b * c) * (b**2 + c**2) * thd**2 / 6)],
        simulation=Simulation(params={**sim, b: 0.5, c: 0.3}, initial=start, t_end=5),
        correction="A = 4bc for the 2b x 2c rectangle.",
    ),
]
