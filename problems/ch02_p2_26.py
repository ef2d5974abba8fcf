"""Wells, Problem 2.26 — particle on a disk spinning (φ) about a horizontal axis that turns about the vertical (ψ)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation

psi, phi = coordinates("psi phi")
m, R, r = parameters("m R r")

# Horizontal axis op along e1 = (cosψ, sinψ, 0); disk centre at R e1; the disk plane is spanned by
# e2 = (−sinψ, cosψ, 0) and Z; the particle is at radius r, angle φ in that plane (inferred).
e1 = sp.Matrix([sp.cos(psi), sp.sin(psi), 0])
e2 = sp.Matrix([-sp.sin(psi), sp.cos(psi), 0])
ez = sp.Matrix([0, 0, 1])
P = R * e1 + r * (sp.cos(phi) * e2 + sp.sin(phi) * ez)
system = System([psi, phi], bodies=[Particle(m, tuple(P))], name="particle on a spinning, turning disk")

psd, phd = psi.diff(t), phi.diff(t)
PROBLEM = Problem(
    id="p2.26",
    title="Particle on a disk spinning about a horizontal axis that turns about the vertical: T",
    chapter=2,
    source="Wells, Problem 2.26",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * m * (R**2 * psd**2 + r**2 * phd**2 - 2 * R * r * psd * phd * sp.sin(phi)
                                               + r**2 * psd**2 * sp.cos(phi) ** 2)),
    ],
    simulation=Simulation(params={m: 1, R: 1, r: 0.5}, initial={psi: 0, phi: 0.0, psd: 1.0, phd: 0.2}, t_end=1.0),
    correction="Geometry inferred to match the printed T. The disk's own T = ½(MR²+I1)ψ̇² + ½I2φ̇² needs "
    "rigid-body inertia (not a particle result) and is not checked. The coordinates are singular at "
    "φ = ±π/2 (det M ∝ cos²φ); the simulation stays away from there.",
)
