"""Wells, Example 8.14 — heavy symmetric top with its tip fixed (Euler angles, (8.13)).

Body origin O at the fixed tip, Z along the symmetry axis, c.m. at z̄ = r; I_x = I_y, I_z about the tip.
L = ½[I_x(θ̇² + ψ̇² s²θ) + I_z(φ̇ + ψ̇ cθ)²] − M g r cθ; ψ and φ are ignorable (8.13).
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Simulation

psi, th, phi = coordinates("psi theta phi")
M, g, r, Ix, Iz = parameters("M g r I_x I_z")
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)

top = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, th, phi), com=(0, 0, r), name="top")
system = System([th, psi, phi], bodies=[top], V=M * g * top.centre_of_mass[2], name="heavy symmetric top")

P_phi = Iz * (psd * sp.cos(th) + phd)
P_psi = Ix * psd * sp.sin(th) ** 2 + P_phi * sp.cos(th)

PROBLEM = Problem(
    id="ex8.14",
    title="Heavy symmetric top, tip fixed: theta equation and the first integrals P_phi, P_psi (8.13)",
    chapter=8,
    source="Wells, Example 8.14 (eq. 8.13)",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * (Ix * (thd**2 + psd**2 * sp.sin(th) ** 2) + Iz * (phd + psd * sp.cos(th)) ** 2)),
        PotentialEnergy(M * g * r * sp.cos(th)),
        ConservedMomenta({phi: P_phi, psi: P_psi}),
        # θ equation as printed; the ψ and φ equations are d/dt of the book's constant momenta
        EquationsOfMotion(
            [
                sp.Eq(Ix * th.diff(t, 2) + ((Iz - Ix) * psd * sp.cos(th) + Iz * phd) * psd * sp.sin(th),
                      M * g * r * sp.sin(th)),
                sp.Eq(P_psi.diff(t), 0),
                sp.Eq(P_phi.diff(t), 0),
            ],
        ),
    ],
    simulation=Simulation(
        params={M: 1.0, g: 9.81, r: 0.1, Ix: 0.02, Iz: 0.01},
        initial={th: 0.5, psi: 0.0, phi: 0.0, thd: 0.0, psd: 2.0, phd: 60.0},
        t_end=3.0,
    ),
    ranges={"theta": (0.3, 1.3)},
    correction="Equations compared through the accelerations (per_equation off: the engine writes s²θ as 1 − c²θ, "
    "which the constant-ratio test cannot cancel).",
)
