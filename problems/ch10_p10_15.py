"""Wells, Problem 10.15 — triple torsion pendulum (Fig. 10-13): three equal dumbbells on a wire with fixed ends,
(a) viscous torques −b_i θ_i', (b) V = κ[θ1² + θ2² + θ3² − (θ1θ2 + θ2θ3)]."""

import sympy as sp

from lagrange import System, characteristic_roots, coordinates, linearize, parameters, t
from lagrange.corpus import GeneralizedForces, PotentialEnergy, Problem, Quantity, Simulation

th = coordinates("theta1 theta2 theta3")
I, kappa, b1, b2, b3 = parameters("I kappa b1 b2 b3")
bs = (b1, b2, b3)
angles = [0, *th, 0]  # wire clamped at both ends
system = System(
    list(th),
    T=sp.Rational(1, 2) * I * sum(q.diff(t) ** 2 for q in th),
    V=sum(sp.Rational(1, 2) * kappa * (angles[i + 1] - angles[i]) ** 2 for i in range(4)),
    rayleigh=sp.Rational(1, 2) * sum(b * q.diff(t) ** 2 for b, q in zip(bs, th)),  # viscous torques −b θ'
    name="triple torsion pendulum with viscous torques",
)
BOOK_P = -sp.Rational(1, 2) * sum(b * q.diff(t) ** 2 for b, q in zip(bs, th))
NUM = {I: 1.0, kappa: 4.0, b1: 0.1, b2: 0.2, b3: 0.3}


def _stable(s):
    return sp.Integer(int(all(characteristic_roots(linearize(s), NUM).real < 0)))


PROBLEM = Problem(
    id="p10.15",
    title="Triple torsion pendulum: P = −½Σ b_i θ_i'², V = κ[Σθ² − (θ1θ2 + θ2θ3)]",
    chapter=10,
    source="Wells, Problem 10.15 (Fig. 10-13)",
    system=system,
    answers=[
        PotentialEnergy(kappa * (th[0] ** 2 + th[1] ** 2 + th[2] ** 2 - (th[0] * th[1] + th[1] * th[2]))),
        # (a) Wells' P: the generalized forces it gives, ∂P/∂θ_i', against the viscous torques of the model
        GeneralizedForces({q: sp.diff(BOOK_P, q.diff(t)) for q in th}),
        Quantity("b matrix", lambda s: linearize(s).b, sp.diag(b1, b2, b3), description="b_rl = −∂²P/∂θ'∂θ'"),
        Quantity("damped roots stable", _stable, sp.Integer(1),
                 description="Sec. 10.16: with P < 0 all characteristic roots have negative real parts"),
    ],
    simulation=Simulation(params=NUM, initial={th[0]: 0.3, th[1]: 0.0, th[2]: 0.0, **{q.diff(t): 0.0 for q in th}},
                          t_end=10.0),
    correction="Catalog marks P10.15 PARTIAL (no numbers); part (b) (V for n dumbbells) is checked with n = 3 and "
               "part (a) as the forces of Wells' P. The stability statement is Sec. 10.16's general result.",
)
