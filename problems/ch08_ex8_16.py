"""Wells, Example 8.16 — gyroscope in two massless gimbals, c.m. at the gimbal centre (the top with g = 0).

T = ½ Ī_x(ψ̇² s²θ + θ̇²) + ½ Ī_z(ψ̇ cθ + φ̇)²; all generalized forces vanish, ψ and φ are cyclic.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation

psi, th, phi = coordinates("psi theta phi")
M, Ix, Iz = parameters("M I_x I_z")
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)

rotor = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, th, phi), name="rotor")
system = System([th, psi, phi], bodies=[rotor], name="gyroscope in massless gimbals")

P_phi = Iz * (phd + psd * sp.cos(th))
P_psi = Ix * psd * sp.sin(th) ** 2 + P_phi * sp.cos(th)

PROBLEM = Problem(
    id="ex8.16",
    title="Gyroscope in two massless gimbals: T, zero generalized forces, cyclic psi and phi",
    chapter=8,
    source="Wells, Example 8.16",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * Ix * (psd**2 * sp.sin(th) ** 2 + thd**2)
                      + sp.Rational(1, 2) * Iz * (psd * sp.cos(th) + phd) ** 2),
        GeneralizedForces({th: 0, psi: 0, phi: 0}),
        ConservedMomenta({phi: P_phi, psi: P_psi}),
        EquationsOfMotion(
            [
                sp.Eq(Ix * th.diff(t, 2) - Ix * psd**2 * sp.sin(th) * sp.cos(th)
                      + Iz * (phd + psd * sp.cos(th)) * psd * sp.sin(th), 0),
                sp.Eq(P_psi.diff(t), 0),
                sp.Eq(P_phi.diff(t), 0),
            ],
        ),
    ],
    simulation=Simulation(
        params={Ix: 0.02, Iz: 0.03},
        initial={th: 0.8, psi: 0.0, phi: 0.0, thd: 0.5, psd: 1.0, phd: 40.0},
        t_end=3.0,
    ),
    ranges={"theta": (0.3, 1.3)},
    correction="EOM not printed as such in the book: the theta equation is the top's (8.13) with g = 0 and the psi, phi "
    "equations are d/dt of the book's constants (catalog-derived). Compared through the accelerations.",
)
