"""Wells, Problem 10.18 — m1 and m2 on tracks, two wheels (inertia I each, radius r) rolling without slipping
on m1, m3 on springs (Fig. 10-14): the rolling condition kept as a constraint on the wheel angle psi."""

import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, eliminate, parameters, t
from lagrange.corpus import ConstraintForce, KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

x1, q2, x3, psi = coordinates("x1 q2 x3 psi")
m1, m2, m3, I, r, k = parameters("m1 m2 m3 I r k")

# Book's coordinates: x1 (m1), q2 = const - x2 (m2 moves at x1d - q2d), x3 (m3). The two wheels turn at psid;
# rolling without slipping on m1: r psid = q2d (kept as a holonomic constraint r psi - q2 = 0).
system = System(
    [x1, q2, x3, psi],
    T=2 * sp.Rational(1, 2) * I * psi.diff(t) ** 2,
    bodies=[Particle(m1, (x1,), name="m1"), Particle(m2, (x1 - q2,), name="m2"), Particle(m3, (x3,), name="m3")],
    V=sp.Rational(1, 2) * k * (x1**2 + q2**2 + x3**2 - 2 * x1 * x3 + 2 * x3 * q2 - 2 * x1 * q2),
    constraints=[Holonomic(r * psi - q2, name="rolling")],
    name="Fig. 10-14: wheels rolling on m1 (rolling as a constraint)",
)
reduced = eliminate(system, {psi: q2 / r})

PARAMS = {m1: 2.0, m2: 1.0, m3: 0.5, I: 0.05, r: 0.2, k: 30.0}
INIT = {x1: 0.1, q2: 0.0, x3: -0.1, psi: 0.0, x1.diff(t): 0.0, q2.diff(t): 0.2, x3.diff(t): 0.0, psi.diff(t): 1.0}


def _MK(sy):
    return sy.mass_matrix, sp.hessian(sy.V, list(sy.coordinates))


def _zero_multiplicity(sy):
    M, K = _MK(sy)
    return len(K.nullspace())  # M is positive definite: the zero roots of D are the null space of K


def _omega2(sy):
    M, K = _MK(sy)
    w2 = sp.Symbol("w2")
    roots = [sp.factor(rt) for rt in sp.solve(sp.factor((K - w2 * M).det()), w2)]
    return [rt for rt in roots if rt != 0][0]


Ir = 2 * I / r**2
PROBLEMS = [
    Problem(
        id="p10.18-multipliers",
        title="Wheels rolling without slipping on m1, rolling condition as a multiplier: friction at the contacts",
        chapter=10,
        source="Wells, Problem 10.18 (Fig. 10-14)",
        system=system,
        answers=[
            # A = d(r psi - q2)/d psi = r: lambda r is the torque of the contact friction on the two wheels, so by
            # the wheels' rotation 2 I psidd = lambda r, lambda = 2 I psidd / r (the total friction force).
            ConstraintForce("rolling", 2 * I * psi.diff(t, 2) / r, PARAMS, INIT, 2.0,
                            description="total contact friction lambda = 2 I psidd / r (derived)"),
        ],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=3.0),
        correction=("Model from the catalog (q2 = const - x2, m2 moving at x1d - q2d, wheels turning at q2d/r). The book "
                    "gives no contact force; lambda = 2 I psidd / r is derived from the wheels' rotation (sign: lambda "
                    "is the generalized force on r psi, i.e. the friction force in the sense that spins the wheels up)."),
    ),
    Problem(
        id="p10.18-multipliers-reduced",
        title="Fig. 10-14 with psi eliminated: book's T, V; double zero root and the nonzero omega^2",
        chapter=10,
        source="Wells, Problem 10.18",
        system=reduced,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * ((m1 + m2) * x1.diff(t) ** 2 + (m2 + Ir) * q2.diff(t) ** 2
                                               + m3 * x3.diff(t) ** 2 - 2 * m2 * x1.diff(t) * q2.diff(t))),
            PotentialEnergy(sp.Rational(1, 2) * k * (x1**2 + q2**2 + x3**2 - 2 * x1 * x3 + 2 * x3 * q2 - 2 * x1 * q2)),
            Quantity("multiplicity of the zero root", _zero_multiplicity, sp.Integer(2)),
            Quantity("omega^2", _omega2,
                     k * (m1 * m2 + m1 * m3 + (m1 + m2 + m3) * Ir) / (m3 * (m1 * m2 + (m1 + m2) * Ir)),
                     description="m3[m1 m2 + (m1+m2)(2I/r^2)] w^2 = k[m1 m2 + m1 m3 + (m1+m2+m3)(2I/r^2)]"),
        ],
        simulation=Simulation(params=PARAMS, initial={x1: 0.1, q2: 0.0, x3: -0.1, x1.diff(t): 0.0,
                                                      q2.diff(t): 0.2, x3.diff(t): 0.0}, t_end=3.0),
        correction="Unreduced model (wheel angle psi with r psi = q2) built to reproduce the catalog's T.",
    ),
]
