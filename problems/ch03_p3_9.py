"""Wells, Problem 3.9 — particle between two identical springs (anchors at z = ±S, free length l0 < S)."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x, y, z = coordinates("x y z")
m, k, S, l0 = parameters("m k S l0")

# Geometry inferred in the catalog (figure not available): springs along Z, anchors at (0, 0, ±S).
L1 = sp.sqrt(x**2 + y**2 + (S - z) ** 2)
L2 = sp.sqrt(x**2 + y**2 + (S + z) ** 2)
system = System(
    [x, y, z],
    bodies=[Particle(m, (x, y, z), name="particle")],
    forces=-k * (L1 - l0) * delta(L1) - k * (L2 - l0) * delta(L2),
    name="particle between two springs",
)


def stiffness(s):
    """−∂F_q/∂q at the centre: the small-displacement forces are F = −K q."""
    qs = s.coordinates
    F = s.generalized_forces()
    Fv = sp.Matrix([F[q] for q in qs])
    K = (-Fv.jacobian(qs)).subs({q: 0 for q in qs})
    return [sp.simplify(K[i, j]) for i in range(3) for j in range(3)]


def frequencies(s):
    qs = s.coordinates
    F = s.generalized_forces()
    K = (-sp.Matrix([F[q] for q in qs]).jacobian(qs)).subs({q: 0 for q in qs})
    return [K[i, i] / s.mass_matrix[i, i] for i in range(3)]


c = 2 * k * (1 - l0 / S)
PROBLEM = Problem(
    id="p3.9",
    title="Particle between two springs: small-displacement forces and the three SHM frequencies",
    chapter=3,
    source="Wells, Problem 3.9",
    system=system,
    answers=[
        Quantity("small-displacement stiffness (F_x = -2k(1-l0/S)x, F_y = -2k(1-l0/S)y, F_z = -2kz)", stiffness,
                 [c, 0, 0, 0, c, 0, 0, 0, 2 * k]),
        Quantity("omega^2 for x, y, z (derived)", frequencies, [c / m, c / m, 2 * k / m]),
    ],
    simulation=Simulation(params={m: 1, k: 10, S: 1, l0: 0.5},
                          initial={x: 0.05, y: 0.0, z: 0.1, x.diff(t): 0, y.diff(t): 0.1, z.diff(t): 0}, t_end=5),
    ranges={"l0": (0.2, 0.9), "S": (1.1, 2.3)},
    correction="Geometry inferred (figure not available). F_phi = 0 (axial symmetry) is not checked separately. "
               "The three frequencies are derived in the catalog; the book only says 'integrate'.",
)
