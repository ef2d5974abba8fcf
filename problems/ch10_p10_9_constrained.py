"""Wells, Problem 10.9 — pulley (inertia I, radius R) with m1 on one side and a spring k carrying m2 on the
other (Fig. 10-7(d), model reconstructed in the catalog): the rope on the pulley (no slip, inextensible) kept
as a constraint y = R phi on the pulley angle, then eliminated; one zero root and a t^2 drift."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

y, s, ph = coordinates("y s phi")
m1, m2, I, R, k, g = parameters("m1 m2 I R k g")

# y: m1 downward; phi: pulley angle (m1 descends when phi grows); s: spring extension. The spring hangs from
# the other rope end, which rises R phi, so m2 is at depth s - R phi (constants dropped).
system = System(
    [y, s, ph],
    T=sp.Rational(1, 2) * I * ph.diff(t) ** 2,
    bodies=[Particle(m1, (0, -y), name="m1"), Particle(m2, (0, -(s - R * ph)), name="m2")],
    V=sp.Rational(1, 2) * k * s**2 - m1 * g * y - m2 * g * (s - R * ph),
    constraints=[Holonomic(y - R * ph, name="rope")],
    name="pulley with inertia, m1 and a spring-hung m2 (rope as a constraint)",
)
reduced = eliminate(system, {ph: y / R})

PARAMS = {m1: 1.0, m2: 0.6, I: 0.02, R: 0.1, k: 50.0, g: 9.81}
INIT = {y: 0.0, s: 0.1, ph: 0.0, y.diff(t): 0.0, s.diff(t): 0.0, ph.diff(t): 0.0}


def _MK(sy):
    q = list(sy.coordinates)
    return sy.mass_matrix, sp.hessian(sy.V, q)


def _nonzero_root(sy):
    M, K = _MK(sy)
    w2 = sp.Symbol("w2")
    roots = [sp.simplify(r) for r in sp.solve((K - w2 * M).det(), w2)]
    return [r for r in roots if r != 0][0]


def _zero_root(sy):
    M, K = _MK(sy)
    return sp.simplify(K.det())  # a zero root of |c - a w^2| <=> det K = 0


def _drift(sy):
    """Coefficient of t^2 in y: the zero mode u (K u = 0) is accelerated uniformly by the constant forces,
    u^T M u a = u^T F_0; y carries a u_y / 2 t^2 (the oscillating mode is M-orthogonal to it)."""
    M, K = _MK(sy)
    q = list(sy.coordinates)
    u = K.nullspace()[0]
    u = u / u[0]
    F0 = sp.Matrix([-sp.diff(sy.V, qi) for qi in q]).subs({qi: 0 for qi in q})
    a = (u.T * F0)[0] / (u.T * M * u)[0]
    return sp.simplify(a * u[0] / 2)


Mtot = m1 + m2 + I / R**2
PROBLEMS = [
    Problem(
        id="p10.9-multipliers",
        title="Pulley with inertia and a spring-hung mass: rope y = R phi as a multiplier; m1's rope tension",
        chapter=10,
        source="Wells, Problem 10.9 (Fig. 10-7(d))",
        system=system,
        answers=[
            # A = d(y - R phi)/dy = 1: lambda is the rope's force on m1 along +y (down), i.e. minus the tension,
            # which by Newton for m1 is tau_1 = m1 (g - ydd).
            ConstraintForce("rope", -m1 * (g - y.diff(t, 2)), PARAMS, INIT, 2.0,
                            description="lambda = -tau_1, tau_1 = m1 (g - ydd)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=2.0),
        correction=("Model reconstructed in the catalog (the figure is not described): it reproduces both book results "
                    "exactly. The book gives no tension; tau_1 = m1(g - ydd) is Newton's law for m1 (derived), "
                    "lambda = -tau_1 since the rope pulls m1 up while y points down."),
    ),
    Problem(
        id="p10.9-multipliers-reduced",
        title="Pulley with inertia and a spring-hung mass: omega_1 = 0, omega_2, and the (g/2M)(m1 - m2) t^2 drift",
        chapter=10,
        source="Wells, Problem 10.9",
        system=reduced,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * (m1 + I / R**2) * y.diff(t) ** 2
                          + sp.Rational(1, 2) * m2 * (s.diff(t) - y.diff(t)) ** 2),
            PotentialEnergy(sp.Rational(1, 2) * k * s**2 - m1 * g * y - m2 * g * (s - y)),
            Quantity("omega_1 = 0 (det K)", _zero_root, sp.Integer(0)),
            Quantity("omega_2^2", _nonzero_root, k * (m1 + m2 + I / R**2) / (m2 * (m1 + I / R**2))),
            Quantity("t^2 coefficient of y", _drift, g * (m1 - m2) / (2 * Mtot),
                     description="y = A cos(w2 t + phi) + (g/2M)(m1 - m2) t^2 + B t + C, M = m1 + m2 + I/R^2"),
        ],
        simulation=Simulation(params=PARAMS, initial={y: 0.0, s: 0.1, y.diff(t): 0.0, s.diff(t): 0.0}, t_end=2.0),
        correction="Model (T, V in y and s) reconstructed in the catalog; it reproduces both printed results.",
    ),
]
