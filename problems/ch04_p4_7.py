"""Wells, Problem 4.7 — cart (body M1, four wheels M, r, I) with an incline carrying a block m on a spring; force f."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Simulation

x, y, q = coordinates("x y q")
M1, M, r, I, m, k, f, g, th, y0, q0 = parameters("M1 M r I m k f g theta y0 q0")

Mt = M1 + 4 * M + 4 * I / r**2  # body plus four rolling wheels: ½(M + I/r²) x'² each
T_cart_x = sp.Rational(1, 2) * Mt * x.diff(t) ** 2

# (b) q = distance of the block down the incline (spring relaxed at q0); the incline descends towards −X.
Xb, Yb = x - q * sp.cos(th), y0 - q * sp.sin(th)
in_xq = System(
    [x, q],
    T=T_cart_x,
    bodies=[Particle(m, (Xb, Yb), name="block")],
    forces=f * delta(x) - k * (q - q0) * delta(q) - m * g * delta(Yb),
    name="cart with spring-mounted block on an incline (x, q)",
)
# (a) the block height y as coordinate: q = (y0 − y)/sinθ.
qy = (y0 - y) / sp.sin(th)
Xa = x - qy * sp.cos(th)
in_xy = System(
    [x, y],
    T=T_cart_x,
    bodies=[Particle(m, (Xa, y), name="block")],
    forces=f * delta(x) - k * (qy - q0) * delta(qy) - m * g * delta(y),
    name="cart with spring-mounted block on an incline (x, y)",
)

sim = dict(params={M1: 5, M: 0.5, r: 0.2, I: 0.01, m: 1, k: 50, f: 1, g: 9.81, th: 0.5, y0: 1, q0: 0.5}, t_end=2)
rng = {"theta": (0.3, 1.3)}
PROBLEMS = [
    Problem(
        id="p4.7",
        title="Cart with an incline and a spring-mounted block, coordinates (x, y)",
        chapter=4,
        source="Wells, Problem 4.7(a)",
        system=in_xy,
        answers=[
            EquationsOfMotion([
                sp.Eq((M1 + 4 * M + 4 * I / r**2 + m) * x.diff(t, 2) + m / sp.tan(th) * y.diff(t, 2), f),
                sp.Eq(m / sp.sin(th) ** 2 * y.diff(t, 2) + m / sp.tan(th) * x.diff(t, 2),
                      -m * g + k / sp.sin(th) * ((y0 - y) / sp.sin(th) - q0)),
            ], per_equation=True),
        ],
        simulation=Simulation(initial={x: 0, y: 0.7, x.diff(t): 0, y.diff(t): 0}, **sim),
        ranges=rng,
    ),
    Problem(
        id="p4.7-xq",
        title="Cart with an incline and a spring-mounted block, coordinates (x, q)",
        chapter=4,
        source="Wells, Problem 4.7(b)",
        system=in_xq,
        answers=[
            GeneralizedForces({x: f, q: m * g * sp.sin(th) - k * (q - q0)}),
            # Derived in the catalog from the book's F_x, F_q.
            EquationsOfMotion([
                sp.Eq((Mt + m) * x.diff(t, 2) - m * sp.cos(th) * q.diff(t, 2), f),
                sp.Eq(m * q.diff(t, 2) - m * sp.cos(th) * x.diff(t, 2), m * g * sp.sin(th) - k * (q - q0)),
            ], per_equation=True),
        ],
        simulation=Simulation(params={p: v for p, v in sim["params"].items() if p != y0},
                              initial={x: 0, q: 0.6, x.diff(t): 0, q.diff(t): 0}, t_end=sim["t_end"]),
        ranges=rng,
        correction="Book prints F_x and F_q for part (b); those equations of motion are derived in the catalog.",
    ),
]
