"""Wells, Problem 13.16 — rod swinging in space about a ball joint with m1 fixed at r1 and m2 sliding at r2 on a
spring (k, r0) (Fig. 4-13): steady motion with constant θ, r2 and φ̇."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, KineticEnergy, Problem, Quantity, Simulation

theta, phi, r2 = coordinates("theta phi r2")
m1, m2, r1, k, r0, g = parameters("m_1 m_2 r_1 k r_0 g")


def _at(rho):
    return (rho * sp.sin(theta) * sp.cos(phi), rho * sp.sin(theta) * sp.sin(phi), -rho * sp.cos(theta))


system = System([theta, phi, r2], bodies=[Particle(m1, _at(r1)), Particle(m2, _at(r2))],
                V=-(m1 * r1 + m2 * r2) * g * sp.cos(theta) + k * (r2 - r0) ** 2 / 2,
                name="rod on a ball joint with a sliding spring mass")
thd, phd, rd = theta.diff(t), phi.diff(t), r2.diff(t)
J = m1 * r1**2 + m2 * r2**2


def _steady(s):
    """Equations with θ̇ = ṙ2 = 0 and all accelerations zero (φ̇ kept): the θ one divided by −sinθ, the r2 one
    by −1, i.e. written as (left − right) of the book's (2) and (1)."""
    rest = {c.diff(t, 2): 0 for c in s.coordinates}
    rest.update({thd: 0, rd: 0})
    e = {c: (eq.lhs - eq.rhs).subs(rest) for c, eq in zip(s.coordinates, s.equations())}
    return [sp.simplify(e[theta] / -sp.sin(theta)), -e[r2], e[phi]]


PROBLEM = Problem(
    id="p13.16",
    title="Rod with a spring-mounted sliding mass on a ball joint: steady motion conditions and p_φ",
    chapter=13,
    source="Wells, Problem 13.16 (Fig. 4-13)",
    system=system,
    answers=[
        KineticEnergy(m1 * (r1**2 * thd**2 + r1**2 * sp.sin(theta) ** 2 * phd**2) / 2
                      + m2 * (r2**2 * thd**2 + r2**2 * sp.sin(theta) ** 2 * phd**2) / 2 + m2 * rd**2 / 2),
        Quantity("steady motion (2), (1), and the φ equation", _steady, [
            J * sp.cos(theta) * phd**2 - (m1 * r1 + m2 * r2) * g,
            m2 * r2 * sp.sin(theta) ** 2 * phd**2 - (k * (r2 - r0) - m2 * g * sp.cos(theta)),
            0]),
        ConservedMomenta({phi: J * sp.sin(theta) ** 2 * phd}),
    ],
    simulation=Simulation(params={m1: 1, m2: 0.5, r1: 0.5, k: 50, r0: 0.8, g: 9.81},
                          initial={theta: 0.6, phi: 0, r2: 0.9, thd: 0, phd: 4.0, rd: 0}, t_end=3),
    correction="The book's T omits the term m2 ṙ2²/2 (it does not affect the steady motion); it is included here "
               "(catalog note).",
)
