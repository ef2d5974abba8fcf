"""Wells, Example 3.4 — pendulum bob on a rubber band (free length r0), θ from the downward vertical."""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

r, theta = coordinates("r theta")
m, g, k, r0 = parameters("m g k r0")

# Y downward: bob at (r sinθ, r cosθ).
bob = Particle(m, (r * sp.sin(theta), r * sp.cos(theta)), name="bob")
Fr = -k * (r - r0) + m * g * sp.cos(theta)
Fth = -m * g * r * sp.sin(theta)
eom_rows = (
    [
        sp.Eq(m * r.diff(t, 2) - m * r * theta.diff(t) ** 2, -k * (r - r0) + m * g * sp.cos(theta)),
        sp.Eq(m * r**2 * theta.diff(t, 2) + 2 * m * r * r.diff(t) * theta.diff(t), -m * g * r * sp.sin(theta)),
    ]
)
T_book = m / 2 * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2)
sim = Simulation(params={m: 1, g: 9.81, k: 40, r0: 1}, initial={r: 1.2, theta: 0.5, r.diff(t): 0, theta.diff(t): 0},
                 t_end=5)
corr = ("Book prints the θ equation's Coriolis term as '2 m r θ̇' (ṙ lost in the OCR); the correct term "
        "2 m r ṙ θ̇ follows from d/dt(m r² θ̇) (sym ✓ in the catalog).")

# Variant 1: Cartesian force components at the bob, Wells (3.17): F_x = −k(r−r0) sinθ, F_y = mg − k(r−r0) cosθ.
by_components = System(
    [r, theta],
    bodies=[bob],
    forces=[Force(bob, (-k * (r - r0) * sp.sin(theta), m * g - k * (r - r0) * sp.cos(theta)))],
    name="pendulum on a rubber band (force components)",
)
# Variant 2: total virtual work δW = −k(r−r0) δr + m g δ(r cosθ).
by_virtual_work = System(
    [r, theta],
    bodies=[bob],
    forces=-k * (r - r0) * delta(r) + m * g * delta(r * sp.cos(theta)),
    name="pendulum on a rubber band (virtual work)",
)

PROBLEMS = [
    Problem(
        id="ex3.4",
        title="Pendulum on a rubber band: F_q from Cartesian force components (3.17)",
        chapter=3,
        source="Wells, Example 3.4",
        system=by_components,
        answers=[KineticEnergy(T_book), GeneralizedForces({r: Fr, theta: Fth}),
                 EquationsOfMotion(eom_rows, per_equation=True)],
        simulation=sim,
        correction=corr,
    ),
    Problem(
        id="ex3.4-virtual-work",
        title="Pendulum on a rubber band: F_q from the total virtual work",
        chapter=3,
        source="Wells, Example 3.4",
        system=by_virtual_work,
        answers=[KineticEnergy(T_book), GeneralizedForces({r: Fr, theta: Fth}),
                 EquationsOfMotion(eom_rows, per_equation=True)],
        simulation=sim,
        correction=corr,
    ),
]
