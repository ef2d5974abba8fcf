"""Wells, Problem 6.13 — board resting on four tack heads at the corners of a 2a × 2b rectangle, sliding with
dry friction f_i at each tack: the generalized forces −δW = Σ f_i (v_i · δr_i)/|v_i|."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

x, y, theta = coordinates("x y theta")
M, I, a, b = parameters("M I a b")
f = parameters("f_1 f_2 f_3 f_4")
xd, yd, thd = x.diff(t), y.diff(t), theta.diff(t)

# The engine's model: the tacks at the board-fixed corners (∓a, ∓b) (tack 1 at (−a, −b), 2 at (a, −b),
# 3 at (a, b), 4 at (−a, b)), each with friction f_i opposite to its velocity.
corners = [(-a, -b), (a, -b), (a, b), (-a, b)]
forces = []
for fi, (u, w) in zip(f, corners):
    X = x + u * sp.cos(theta) - w * sp.sin(theta)
    Y = y + u * sp.sin(theta) + w * sp.cos(theta)
    speed = sp.sqrt(X.diff(t) ** 2 + Y.diff(t) ** 2)
    forces.append(Force(at=(X, Y, 0), vector=(-fi * X.diff(t) / speed, -fi * Y.diff(t) / speed, 0)))
system = System([x, y, theta], T=I * thd**2 / 2, bodies=[Particle(M, (x, y))], forces=forces,
                name="board on four tack heads")

# The book's form: r² = a² + b², tanβ = b/a; tacks at angles θ+π+β, θ−β, θ+β, θ+π−β from the centre.
r = sp.sqrt(a**2 + b**2)
beta = sp.atan(b / a)
gammas = [theta + sp.pi + beta, theta - beta, theta + beta, theta + sp.pi - beta]
Fx = Fy = Fth = 0
for fi, gm in zip(f, gammas):
    vx, vy = xd - r * thd * sp.sin(gm), yd + r * thd * sp.cos(gm)
    # v_i = {xd² + yd² + r²θd² + 2rθd[yd cos γ − xd sin γ]}^{1/2}; for tack 1 this is the book's
    # {xd² + yd² + r²θd² + 2rθd[xd sin(θ+β) − yd cos(θ+β)]}^{1/2}
    v = sp.sqrt(xd**2 + yd**2 + r**2 * thd**2 + 2 * r * thd * (yd * sp.cos(gm) - xd * sp.sin(gm)))
    Fx += -fi * vx / v
    Fy += -fi * vy / v
    Fth += -fi * (vx * (-r * sp.sin(gm)) + vy * r * sp.cos(gm)) / v

PROBLEM = Problem(
    id="p6.13",
    title="Board on four tack heads at the corners of a 2a × 2b rectangle: dry-friction generalized forces",
    chapter=6,
    source="Wells, Problem 6.13",
    system=system,
    answers=[GeneralizedForces({x: Fx, y: Fy, theta: Fth}, which="applied")],
    simulation=Simulation(params={M: 1, I: 0.3, a: 0.5, b: 0.3, **{fi: 0.2 for fi in f}},
                          initial={x: 0, y: 0, theta: 0, xd: 1, yd: 0.5, thd: 1}, t_end=0.5),
    correction="The book writes tack 1 explicitly (velocity (xd + rθd sin(θ+β), yd − rθd cos(θ+β))) and says the "
               "others are analogous; the same form is used for the tacks at θ − β, θ + β, θ + π − β. "
               "δr_i = (δx − r sinγ_i δθ, δy + r cosγ_i δθ).",
)
