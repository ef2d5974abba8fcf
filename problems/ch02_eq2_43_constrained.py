"""Wells, (2.27)/(2.43) with the rope constraints kept — four masses and two massless pulleys (Fig. 2-9).

Multiplier form: all four heights y1..y4 (measured upward, gravity −m_i g δy_i) with the ropes
``y1 + y3 − C1 = 0`` (over the fixed pulley) and ``(y3 − y4) + (y3 − y2) − C2 = 0`` (over the pulley that
moves with y3). Rows A1 = (1, 0, 1, 0) and A2 = (0, −1, 2, −1). With the engine's rule (λ_k A_kr added to the
applied force on coordinate r): the upper rope pulls m1 up with its tension τ1, so λ1 = τ1; the lower rope
pulls m2 and m4 up with τ2 and the pulley down with 2 τ2, so λ2 = −τ2 (and 𝓕_y3 = τ1 − 2 τ2).
The book does not compute tensions; expected values are the Newton balances τ1 = m1(ÿ1 + g),
τ2 = m2(ÿ2 + g), m3(ÿ3 + g) = τ1 − 2 τ2 (derived), on the simulated motion.
Eliminating y3 = C1 − y1 and y4 = 2 y3 − y2 − C2 gives the book's T (2.43) and, by virtual work with the
tensions cancelling, the generalized forces of Sec. 2.14(ii) (2.66)–(2.68).
"""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, delta, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, GeneralizedForces, KineticEnergy, Problem, Simulation

y1, y2, y3, y4 = coordinates("y1 y2 y3 y4")
m1, m2, m3, m4, g, C1, C2 = parameters("m1 m2 m3 m4 g C1 C2")

system = System(
    [y1, y2, y3, y4],
    bodies=[Particle(m, (0, y), name=f"m{i + 1}") for i, (m, y) in enumerate(zip((m1, m2, m3, m4), (y1, y2, y3, y4)))],
    forces=-g * (m1 * delta(y1) + m2 * delta(y2) + m3 * delta(y3) + m4 * delta(y4)),
    constraints=[Holonomic(y1 + y3 - C1, name="rope1"), Holonomic((y3 - y4) + (y3 - y2) - C2, name="rope2")],
    name="four-mass pulley system (multipliers)",
)
reduced = eliminate(system, {y3: C1 - y1, y4: 2 * (C1 - y1) - y2 - C2})

PARAMS = {m1: 3.0, m2: 1.0, m3: 1.5, m4: 2.0, g: 9.81, C1: 4.0, C2: 1.0}
INITIAL = {y1: 2.0, y2: 0.0, y3: 2.0, y4: 3.0, y1.diff(t): 0.1, y2.diff(t): 0.2, y3.diff(t): -0.1, y4.diff(t): -0.4}

PROBLEMS = [
    Problem(
        id="eq2.43-multipliers",
        title="Four-mass pulley system with both rope constraints as multipliers; rope tensions",
        chapter=2,
        source="Wells, Sec. 2.9, eqs. (2.27)/(2.43), Fig. 2-9",
        system=system,
        answers=[
            ConstraintForce("rope1", m1 * (y1.diff(t, 2) + g), PARAMS, INITIAL, t_end=1),  # λ1 = τ1
            ConstraintForce("rope2", -m2 * (y2.diff(t, 2) + g), PARAMS, INITIAL, t_end=1),  # λ2 = −τ2
            ConstraintForce("rope2", m4 * (y4.diff(t, 2) + g), PARAMS, INITIAL, t_end=1, coordinate=y4),  # 𝓕_y4 = τ2
            ConstraintForce("rope1", m3 * (y3.diff(t, 2) + g) + 2 * m2 * (y2.diff(t, 2) + g), PARAMS, INITIAL,
                            t_end=1, coordinate=y3),  # 𝓕_y3 from rope1 = τ1 = m3(ÿ3 + g) + 2 τ2
        ],
        simulation=Simulation(params=PARAMS, initial=INITIAL, t_end=1),
        correction="The book gives the constraints, T and the virtual work with cancelling tensions, not the "
        "tensions themselves: the expected tensions are Newton balances (derived). y is measured upward here; "
        "the book's s1 in (2.66)–(2.68) is downward (s1 = −y1 + const).",
    ),
    Problem(
        id="eq2.43-multipliers-reduced",
        title="Four-mass pulley system: y3, y4 eliminated give the book's T (2.43) and F (2.66)-(2.68)",
        chapter=2,
        source="Wells, eq. (2.43) and Sec. 2.14(ii)",
        system=reduced,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * (m1 + m3 + 4 * m4) * y1.diff(t) ** 2
                          + sp.Rational(1, 2) * (m2 + m4) * y2.diff(t) ** 2 + 2 * m4 * y1.diff(t) * y2.diff(t)),
            # book: F_s1 = (m1 − m3 − 2 m4) g with s1 downward, so F_y1 = −F_s1; F_y2 = (m4 − m2) g
            GeneralizedForces({y1: -(m1 - m3 - 2 * m4) * g, y2: (m4 - m2) * g}),
        ],
        simulation=Simulation(params={k: v for k, v in PARAMS.items() if k not in (C1, C2)},
                              initial={y1: 2.0, y2: 0.0, y1.diff(t): 0.1, y2.diff(t): 0.2}, t_end=1),
        correction="The book's (2.66)–(2.68) use s1 downward; with y1 upward F_y1 = −F_s1.",
    ),
]
