"""Wells, Problem 10.20 — five geared disks on three flexible shafts (Fig. 10-15): the gear constraints
theta_4 = b_1 theta_3 and theta_5 = b_2 theta_1 kept as multipliers, then eliminated."""

import sympy as sp

from lagrange import Holonomic, System, coordinates, eliminate, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

th1, th2, th3, th4, th5 = coordinates("theta1 theta2 theta3 theta4 theta5")
I1, I2, I3, I4, I5, k1, k2, k3, b1, b2 = parameters("I1 I2 I3 I4 I5 kappa1 kappa2 kappa3 b1 b2")

# Shaft kappa1 joins disks 1-2, kappa2 joins 2-3, kappa3 joins 4-5; disk 4 meshes with 3, disk 5 with 1.
system = System(
    [th1, th2, th3, th4, th5],
    T=sp.Rational(1, 2) * sum(I * q.diff(t) ** 2 for I, q in zip((I1, I2, I3, I4, I5), (th1, th2, th3, th4, th5))),
    V=sp.Rational(1, 2) * (k1 * (th2 - th1) ** 2 + k2 * (th3 - th2) ** 2 + k3 * (th5 - th4) ** 2),
    constraints=[Holonomic(th4 - b1 * th3, name="gear 3-4"), Holonomic(th5 - b2 * th1, name="gear 1-5")],
    name="five geared disks (gear constraints as multipliers)",
)
reduced = eliminate(system, {th4: b1 * th3, th5: b2 * th1})


def _K(s):
    q = list(s.coordinates)
    return sp.hessian(s.V, q)


PARAMS = {I1: 1.0, I2: 2.0, I3: 1.5, I4: 0.5, I5: 0.8, k1: 3.0, k2: 2.0, k3: 4.0, b1: 1.5, b2: 0.7}
INIT = {th1: 0.1, th2: -0.2, th3: 0.3, th4: 0.45, th5: 0.07,
        th1.diff(t): 0.0, th2.diff(t): 0.5, th3.diff(t): 0.0, th4.diff(t): 0.0, th5.diff(t): 0.0}
NOTE = ("The unreduced model (which shafts join which disks) is reconstructed so that it reproduces the book's "
        "reduced T and V exactly; the book gives only the reduced forms and the zero-root statement.")

PROBLEMS = [
    Problem(
        id="p10.20-multipliers",
        title="Five geared disks: gear constraints theta4 = b1 theta3, theta5 = b2 theta1 as multipliers; DOF = 3",
        chapter=10,
        source="Wells, Problem 10.20 (Fig. 10-15)",
        system=system,
        answers=[Quantity("degrees of freedom", lambda s: len(s.coordinates) - len(s.constraints), sp.Integer(3))],
        simulation=Simulation(params=PARAMS, initial=INIT, t_end=5.0),
        correction=NOTE,
    ),
    Problem(
        id="p10.20-multipliers-reduced",
        title="Five geared disks: theta4, theta5 eliminated give the book's T and V; zero root when b1 = b2",
        chapter=10,
        source="Wells, Problem 10.20",
        system=reduced,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * ((I1 + b2**2 * I5) * th1.diff(t) ** 2 + I2 * th2.diff(t) ** 2
                                               + (I3 + b1**2 * I4) * th3.diff(t) ** 2)),
            PotentialEnergy(sp.Rational(1, 2) * ((k1 + b2**2 * k3) * th1**2 + (k1 + k2) * th2**2
                                                 + (k2 + b1**2 * k3) * th3**2 - 2 * k1 * th1 * th2
                                                 - 2 * k2 * th2 * th3 - 2 * k3 * b1 * b2 * th1 * th3)),
            # book: a zero root of D = |a w^2 - c| when b1 = b2, i.e. det K = 0 there
            Quantity("det K at b2 = b1 (zero root)", lambda s: sp.expand(_K(s).det().subs(b2, b1)), sp.Integer(0)),
            Quantity("det K", lambda s: sp.factor(_K(s).det()), k1 * k2 * k3 * (b1 - b2) ** 2,
                     description="det K = kappa1 kappa2 kappa3 (b1 - b2)^2 (computed in the catalog)"),
        ],
        simulation=Simulation(params=PARAMS, initial={th1: 0.1, th2: -0.2, th3: 0.3, th1.diff(t): 0.0,
                                                      th2.diff(t): 0.5, th3.diff(t): 0.0}, t_end=5.0),
        correction=NOTE + " det K = kappa1 kappa2 kappa3 (b1 - b2)^2 is computed in the catalog, not printed.",
    ),
]
