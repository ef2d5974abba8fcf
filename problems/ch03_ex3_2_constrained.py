"""Wells, Example 3.2 with the superfluous coordinate kept — bead on the wire y − b x² = 0, Y vertical.

Multiplier form: coordinates (x, y), the wire as ``Holonomic(y − b x²)``. Its Jacobian row is
A = (−2 b x, 1), so λ is the vertical component N_y of the wire's normal force on the bead (the
generalized reaction in +y) and −2 b x λ = N_x its horizontal component: the engine's λ·A_kr is Wells'
𝓕_qr (the reaction in the direction of +δq_r). The book gives no reaction force for this example: the
expected values below are the Cartesian Newton balances m ÿ = −m g + N_y, m ẍ = N_x (derived), evaluated
on the simulated motion. Eliminating y = b x² gives back the book's equation of motion.
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, delta, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

x, y = coordinates("x y")
m, g, b = parameters("m g b")

system = System(
    [x, y],
    bodies=[Particle(m, (x, y), name="bead")],
    forces=-m * g * delta(y),  # gravity on the free pair (x, y): F_x = 0, F_y = −m g
    constraints=[Holonomic(y - b * x**2, name="wire")],
    name="bead on a parabolic wire (multipliers)",
)
reduced = eliminate(system, {y: b * x**2})

PARAMS = {m: 1, g: 9.81, b: 0.5}
INITIAL = {x: 1.0, y: 0.5, x.diff(t): 0.3, y.diff(t): 0.3}  # consistent: y = b x², ẏ = 2 b x ẋ

PROBLEMS = [
    Problem(
        id="ex3.2-multipliers",
        title="Bead on the wire y = b x^2 kept in (x, y) with a multiplier; normal force of the wire",
        chapter=3,
        source="Wells, Example 3.2 (constraints y = b x^2, z = C)",
        system=system,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * m * (x.diff(t) ** 2 + y.diff(t) ** 2)),
            # λ = N_y (wire's push in +y): m ÿ = −m g + λ  (derived)
            ConstraintForce("wire", m * y.diff(t, 2) + m * g, PARAMS, INITIAL, t_end=3),
            # generalized reaction on x: λ·A_wire,x = −2 b x λ = N_x = m ẍ  (derived)
            ConstraintForce("wire", m * x.diff(t, 2), PARAMS, INITIAL, t_end=3, coordinate=x),
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=10),
        correction="The book eliminates y; it states no normal force. Expected reactions are the Newton balances "
        "of the bead (derived), sign: λ is the wire's force in the +y direction.",
    ),
    Problem(
        id="ex3.2-multipliers-reduced",
        title="Bead on the wire y = b x^2: y eliminated from the multiplier form gives the book's equation",
        chapter=3,
        source="Wells, Example 3.2",
        system=reduced,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * m * x.diff(t) ** 2 * (1 + 4 * b**2 * x**2)),
            GeneralizedForces({x: -2 * m * g * b * x}),
            EquationsOfMotion(
                [sp.Eq(m * x.diff(t, 2) * (1 + 4 * b**2 * x**2) + 4 * m * x.diff(t) ** 2 * x * b**2, -2 * m * g * b * x)],
                per_equation=True,
            ),
        ],
        simulation=Simulation(params=PARAMS, initial={x: 1.0, x.diff(t): 0.3}, t_end=10),
    ),
]
