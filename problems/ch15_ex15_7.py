"""Wells, Example 15.7 — the inverse problem of Sec. 15.6 on the transducer of Ex. 15.3: the EMF E(t) and the
mechanical force f_x(t) that produce a prescribed Q(t), x(t).

The unknown EMF E and force f_x are generalized forces on Q and x (forces={Q: E, x: f_x}); the resistance is
Wells' power function. Lagrange's equations with the prescribed Q(t), x(t) substituted are solved for E, f_x.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation

Q, x = coordinates("Q x")
M, m, A, s, k, R, E, fx = parameters("M m A s k R E f_x")
Q0, x0, Qd0, w1, w2, ph1, ph2 = parameters("Q_0 x_0 Qdot_0 omega_1 omega_2 phi_1 phi_2")
half = sp.Rational(1, 2)

system = System(
    [Q, x],
    T=half * M * Q.diff(t) ** 2 + half * m * x.diff(t) ** 2,
    V=half * Q**2 * (s - x) / A + half * k * x**2,
    P=-half * R * Q.diff(t) ** 2,
    forces={Q: E, x: fx},
    name="capacitor transducer driven by E and f_x",
)


def driving(Qt, xt):
    """E and f_x from Lagrange's equations of the system along Q = Qt, x = xt."""

    def compute(sys_):
        eqs = [(e.lhs - e.rhs).subs({Q: Qt, x: xt}).doit() for e in sys_.equations()]
        sol = sp.solve(eqs, [E, fx], dict=True)[0]
        return [sol[E], sol[fx]]

    return compute


c1, s1 = sp.cos(w1 * t + ph1), sp.sin(w1 * t + ph1)
s2 = sp.sin(w2 * t + ph2)

PROBLEM = Problem(
    id="ex15.7",
    title="Transducer of Ex. 15.3: E(t) and f_x(t) for prescribed Q(t), x(t)",
    chapter=15,
    source="Wells, Example 15.7",
    system=system,
    answers=[
        GeneralizedForces({Q: E - R * Q.diff(t), x: fx}),
        EquationsOfMotion(
            [
                sp.Eq(M * Q.diff(t, 2) + Q * (s - x) / A + R * Q.diff(t), E),
                sp.Eq(m * x.diff(t, 2) + k * x - Q**2 / (2 * A), fx),
            ],
            per_equation=True,
        ),
        # (a) Q = Q0, x = x0 constant
        Quantity("(a) [E, f_x]", driving(Q0, x0), [Q0 * (s - x0) / A, k * x0 - Q0**2 / (2 * A)],
                 description="(a) constant Q0, x0"),
        # (b) x = x0, Q = Qdot0 t
        Quantity("(b) [E, f_x]", driving(Qd0 * t, x0),
                 [R * Qd0 + Qd0 * t * (s - x0) / A, k * x0 - Qd0**2 * t**2 / (2 * A)],
                 description="(b) constant current Qdot0, x0"),
        # (c) Q' = Qdot0 sin(w1 t + phi1), i.e. Q = -(Qdot0/w1) cos(w1 t + phi1); x = x0 sin(w2 t + phi2)
        Quantity("(c) [E, f_x]", driving(-(Qd0 / w1) * c1, x0 * s2),
                 [M * Qd0 * w1 * c1 - Qd0 / (A * w1) * c1 * (s - x0 * s2) + R * Qd0 * s1,
                  -m * x0 * w2**2 * s2 + k * x0 * s2 - Qd0**2 / (2 * A * w1**2) * c1**2],
                 description="(c) sinusoidal current and plate motion"),
    ],
    simulation=Simulation(
        params={M: 1.0, m: 1.0, A: 1.0, s: 1.0, k: 4.0, R: 0.2, E: 0.5, fx: 0.0},
        initial={Q: 0.0, x: 0.0, Q.diff(t): 0.0, x.diff(t): 0.0},
        t_end=20,
    ),
    correction="(b) is printed E = R Qdot0 + Qdot0^2 t (s - x0)/A; the capacitor voltage Q/C = Qdot0 t (s - x0)/A is "
               "linear in Qdot0 (dimensions: Qdot0^2 t/C is not a voltage), so E = R Qdot0 + Qdot0 t (s - x0)/A. "
               "(c) f_x is printed with a first term -m Qdot0 w2^2 sin(w2 t + phi2); m x'' of x = x0 sin(...) gives "
               "-m x0 w2^2 sin(w2 t + phi2) (a force, where m Qdot0 w2^2 is not). Both re-derived in the catalog.",
)
