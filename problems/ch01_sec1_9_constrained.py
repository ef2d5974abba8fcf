"""Wells, Sec. 1.9 — two masses and two springs driven by block B: the block's motion s = A sin ωt kept as a
moving constraint on a free (massless) coordinate s; the multiplier is the driving force on B."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, EquationsOfMotion, Problem, Quantity, Simulation

x1, x2, s = coordinates("x1 x2 s")
m1, m2, k1, k2, A, omega = parameters("m1 m2 k1 k2 A omega")

# B is massless: s carries no inertia (singular mass matrix), its motion is imposed by the constraint.
system = System(
    [x1, x2, s],
    bodies=[Particle(m1, (x1,), name="m1"), Particle(m2, (x2,), name="m2")],
    V=sp.Rational(1, 2) * k1 * (x1 - s) ** 2 + sp.Rational(1, 2) * k2 * (x2 - x1) ** 2,
    constraints=[Holonomic(s - A * sp.sin(omega * t), name="drive")],
    name="Sec. 1.9 system with the block's motion as a moving constraint",
)
reduced = eliminate(system, {s: A * sp.sin(omega * t)})

NUM = {m1: 400, m2: 300, A: 5, k1: 60000, k2: 50000, omega: 12}  # CGS
INIT = {x1: 3.0, x2: 4.0, s: 0.0, x1.diff(t): 0.0, x2.diff(t): 0.0, s.diff(t): 5 * 12.0}

PROBLEMS = [
    Problem(
        id="sec1.9-multipliers",
        title="Sec. 1.9 with the block motion s = A sin(wt) as a moving constraint: driving force F_B = k1(s - x1)",
        chapter=1,
        source="Wells, Sec. 1.9 (Fig. 1-4), part (f)",
        system=system,
        answers=[
            Quantity("degrees of freedom", lambda sy: len(sy.coordinates) - len(sy.constraints), sp.Integer(2)),
            # A = d(s - A sin wt)/ds = 1, so lambda is the generalized force of the constraint on s, i.e. the force
            # that drives B in the +s direction. B is massless: 0 = k1 (x1 - s) + lambda.
            ConstraintForce("drive", k1 * (s - x1), NUM, INIT, 1.0, description="F_B = k1 (s - x1) (lambda = F_B)"),
        ],
        units="CGS: grams, dyn/cm, cm, rad/s",
        simulation=Simulation(params=NUM, initial=INIT, t_end=2.0),
        correction=("Part (f) (the force on B) is left to the reader in the book; F_B = k1(s - x1) for a massless B "
                    "is the catalog's derived answer. Sign: lambda is the force on B in the +s (+X) direction."),
    ),
    Problem(
        id="sec1.9-multipliers-reduced",
        title="Sec. 1.9: s eliminated from the moving-constraint form gives the book's driven equations",
        chapter=1,
        source="Wells, Sec. 1.9, equations (1)-(2)",
        system=reduced,
        answers=[
            EquationsOfMotion(
                [
                    sp.Eq(m1 * x1.diff(t, 2) + (k1 + k2) * x1 - k2 * x2, k1 * A * sp.sin(omega * t)),
                    sp.Eq(m2 * x2.diff(t, 2) + k2 * x2 - k2 * x1, 0),
                ],
                per_equation=True,
            ),
        ],
        units="CGS: grams, dyn/cm, cm, rad/s",
        simulation=Simulation(params=NUM, initial={x1: 3.0, x2: 4.0, x1.diff(t): 0.0, x2.diff(t): 0.0}, t_end=2.0),
    ),
]
