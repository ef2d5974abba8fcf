"""Wells, Problem 8.6 — verify the angular velocity of Ex 8.8 (disk on a shaft at constant θ in a frame turning
about the vertical): ω_x = ψ̇ sθ sφ, ω_y = ψ̇ sθ cφ, ω_z = φ̇ + ψ̇ cθ, computed here from the rotation chain
R = R_z(ψ) R_x(θ) R_z(φ) (Rᵀ Ṙ), not from the closed form (8.11)."""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.rotations import rot_x, rot_z

psi, phi = coordinates("psi phi")
M, Ix, Iz, th = parameters("M Ibar_x Ibar_z theta")
psd, phd = psi.diff(t), phi.diff(t)

disk = RigidBody(M, (Ix, Ix, Iz), orientation=rot_z(psi) * rot_x(th) * rot_z(phi), name="disk")
system = System([psi, phi], bodies=[disk], name="disk of Ex 8.8 (rotation chain)")

PROBLEM = Problem(
    id="p8.6",
    title="Angular velocity of the disk of Ex 8.8 from the rotation chain",
    chapter=8,
    source="Wells, Problem 8.6",
    system=system,
    answers=[
        Quantity("omega along the body axes", lambda s: disk.angular_velocity,
                 [psd * sp.sin(th) * sp.sin(phi), psd * sp.sin(th) * sp.cos(phi), phd + psd * sp.cos(th)]),
        KineticEnergy(sp.Rational(1, 2) * Ix * psd**2 * sp.sin(th) ** 2 + sp.Rational(1, 2) * Iz * (phd + psd * sp.cos(th)) ** 2),
    ],
    simulation=Simulation(params={Ix: 0.05, Iz: 0.1, th: 0.6}, initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 20.0}, t_end=5.0),
    ranges={"theta": (0.2, 1.4)},
)
