"""Wells, Example 4.9 — the Fig. 4-1 pulley system with m2 driven, s2 = s0 + A sin ωt, written as a moving
constraint on the free coordinate s2: the multiplier is the driving force on m2."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Simulation

y1, s2 = coordinates("y1 s2")
m1, m2, m3, g, s0, A, w = parameters("m1 m2 m3 g s0 A omega")

# Heights (Y up) in the coordinates (y1, s2) of Example 4.1: Y1 = -y1, Y2 = s2, Y3 = 2 y1 - s2.
Y1, Y2, Y3 = -y1, s2, 2 * y1 - s2
system = System(
    [y1, s2],
    bodies=[Particle(m1, (0, Y1), name="m1"), Particle(m2, (0, Y2), name="m2"), Particle(m3, (0, Y3), name="m3")],
    V=g * (m1 * Y1 + m2 * Y2 + m3 * Y3),
    constraints=[Holonomic(s2 - s0 - A * sp.sin(w * t), name="drive")],
    name="Fig. 4-1 with m2 driven (moving constraint)",
)
reduced = eliminate(system, {s2: s0 + A * sp.sin(w * t)})

PARAMS = {m1: 3.0, m2: 1.0, m3: 1.0, g: 9.81, s0: 0.5, A: 0.1, w: 5.0}
INIT = {y1: 0.0, s2: 0.5, y1.diff(t): 0.0, s2.diff(t): 0.5}

# Driving force on m2 in the +s2 (upward) direction: lambda (A = d phi/d s2 = 1). Newton for the lower rope:
# tension tau' = m3 (g + Y3dd) = m3 (g + 2 y1dd - s2dd); for m2: m2 s2dd = tau' - m2 g + F.
F_drive = m2 * (s2.diff(t, 2) + g) - m3 * (g + 2 * y1.diff(t, 2) - s2.diff(t, 2))

PROBLEMS = [
    Problem(
        id="ex4.9-multipliers",
        title="Fig. 4-1 with s2 = s0 + A sin(wt) as a moving constraint: driving force on m2 (derived, Newton)",
        chapter=4,
        source="Wells, Example 4.9",
        system=system,
        answers=[
            ConstraintForce("drive", F_drive, PARAMS, INIT, 2.0,
                            description="driving force F = m2(s2dd + g) - m3(g + 2 y1dd - s2dd) (lambda = F)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=2.0),
        correction=("The book gives no driving force for Example 4.9 (only the one-DOF equation, checked in "
                    "ex4.9-multipliers-reduced); the expected force is derived here by Newton's law for m2 and m3 "
                    "(lower rope tension tau' = m3(g + 2 y1dd - s2dd)), in the spirit of Sec. 1.9(f). Sign: lambda is "
                    "the force on m2 in the +s2 (upward) direction."),
    ),
    Problem(
        id="ex4.9-multipliers-reduced",
        title="Fig. 4-1 with m2 driven: s2 eliminated from the moving-constraint form gives the book's equation",
        chapter=4,
        source="Wells, Example 4.9",
        system=reduced,
        answers=[
            EquationsOfMotion([sp.Eq((m1 + 4 * m3) * y1.diff(t, 2) + 2 * m3 * A * w**2 * sp.sin(w * t),
                                     (m1 - 2 * m3) * g)], per_equation=True),
        ],
        simulation=Simulation(params=PARAMS, initial={y1: 0.0, y1.diff(t): 0.0}, t_end=2.0),
    ),
]
