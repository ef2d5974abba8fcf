"""Wells, Example 8.8 — uniform disk spinning (φ) on a shaft at the constant angle θ in a frame turning (ψ) about
the vertical (Fig. 8-12); the disk's c.m. is at rest at the intersection of the axes; Ī_x = Ī_y.

T = ½ Ī_x ψ̇² s²θ + ½ Ī_z(φ̇ + ψ̇ cθ)² + ½ I_f ψ̇² (frame). A motor torque τ_ψ about the vertical drives the frame.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, Torque, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, KineticEnergy, Problem, Simulation
from lagrange.model.rotations import rot_z

psi, phi = coordinates("psi phi")
M, Ix, Iz, If, th, tau = parameters("M Ibar_x Ibar_z I_f theta tau_psi")
psd, phd = psi.diff(t), phi.diff(t)

disk = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, th, phi), name="disk")
frame = RigidBody(0, (0, 0, If), orientation=rot_z(psi), name="frame")
system = System([psi, phi], bodies=[disk, frame], forces=[Torque(frame, (0, 0, tau))],
                name="disk on an inclined shaft in a driven frame")

PROBLEM = Problem(
    id="ex8.8",
    title="Disk on an inclined shaft in a turning frame: T, Ibar_z d/dt(phi' + psi' c(theta)) = 0, psi equation",
    chapter=8,
    source="Wells, Example 8.8 (EOM as in Ex 9.5 (4), (5))",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * Ix * psd**2 * sp.sin(th) ** 2
                      + sp.Rational(1, 2) * Iz * (phd + psd * sp.cos(th)) ** 2 + sp.Rational(1, 2) * If * psd**2),
        GeneralizedForces({psi: tau, phi: 0}),
        EquationsOfMotion(
            [
                sp.Eq((Ix * sp.sin(th) ** 2 + If) * psi.diff(t, 2), tau),
                sp.Eq(Iz * (phi.diff(t, 2) + psi.diff(t, 2) * sp.cos(th)), 0),
            ],
        ),
    ],
    simulation=Simulation(params={Ix: 0.05, Iz: 0.1, If: 0.2, th: 0.6, tau: 0.3},
                          initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 20.0}, t_end=5.0),
    ranges={"theta": (0.2, 1.4)},
    correction="EOM derived in the catalog from this T and matching Ex 9.5 (4), (5): Ibar_z d/dt(phi' + psi' c(theta)) = 0 and "
    "Ibar_x psi'' s^2(theta) = tau_psi for the disk alone; with the frame's 1/2 I_f psi'^2 included the psi equation "
    "(after using the phi equation) gains I_f psi''. Compared through the accelerations.",
)
