"""Wells, Sec. 6.7 — block pulled along a rotating cylinder (Fig. 6-4): dry, viscous and quadratic friction."""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, theta = coordinates("x theta")
m, I, r, A, B, C = parameters("m I r A B C")

# Block sliding axially (x) on a cylinder of radius r turning through theta; the surface under the block moves
# at r thd, so the block slides relative to it at (xd, -r thd), speed v. Friction opposes that velocity.
xd, thd = x.diff(t), theta.diff(t)
v = sp.sqrt(xd**2 + (r * thd) ** 2)
T = m * xd**2 / 2 + I * thd**2 / 2
laws = {
    "dry": (-A * v, A * xd / v),
    "viscous": (-B * v**2 / 2, B * xd),
    "quadratic": (-C * v**3 / 3, C * xd * v),
}
start = {x: 0, theta: 0, x.diff(t): 0.5, theta.diff(t): 2}
PROBLEMS = []
for name, (P, pull) in laws.items():
    PROBLEMS.append(Problem(
        id=f"sec6.7-{name}",
        title=f"Block on a rotating cylinder, {name} friction: force needed to pull it at xd",
        chapter=6,
        source="Wells, Sec. 6.7, Fig. 6-4",
        system=System([x, theta], T=T, P=P, name=f"block on a rotating cylinder ({name})"),
        # The pulling force balances the friction: F_x(friction) = -(force needed).
        answers=[GeneralizedForces({x: -pull})],
        simulation=Simulation(params={m: 1, I: 2, r: 0.5, {"dry": A, "viscous": B, "quadratic": C}[name]: 0.3},
                              initial=start, t_end=2),
        correction="The cylinder's rotation is a free coordinate with inertia I (assumed) so that the friction "
        "also acts on it; the book gives the x force needed, equal and opposite to F_x of the friction.",
    ))
