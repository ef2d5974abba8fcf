"""Wells, Problem 8.21 — the Fig. 8-12 mount (frame ψ about its vertical, shaft at constant θ, disk spin φ) with
its base at the distance R from the centre of a table turning with the prescribed angle α(t). The disk c.m. is
at the intersection of the axes: O = R(cα, sα, 0); orientation R_z(α) R_z(ψ) R_x(θ) R_z(φ), i.e. Euler angles
(α + ψ, θ, φ).
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

psi, phi = coordinates("psi phi")
M, Ix, Iz, th, R, Om, A, w = parameters("M Ibar_x Ibar_z theta R Omega A w")
alpha = Om * t + A * sp.sin(w * t)
ad = alpha.diff(t)
psd, phd = psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

disk = RigidBody(M, (Ix, Ix, Iz), origin=(R * c(alpha), R * s(alpha), 0),
                 orientation=EulerAngles(alpha + psi, th, phi), name="disk")
system = System([psi, phi], bodies=[disk], name="Fig. 8-12 mount on a rotating table")
v0 = disk.R.T * disk.origin.diff(t)

PROBLEM = Problem(
    id="p8.21",
    title="Fig. 8-12 mount on a table turning with alpha(t): omega, v_0, v_0^2 = R^2 alpha'^2, T",
    chapter=8,
    source="Wells, Problem 8.21",
    system=system,
    answers=[
        Quantity("omega along the body axes", lambda s_: disk.angular_velocity,
                 [(ad + psd) * s(th) * s(phi), (ad + psd) * s(th) * c(phi), phd + (ad + psd) * c(th)]),
        Quantity("v_0 along the body axes", lambda s_: v0,
                 [R * ad * (c(phi) * s(psi) + s(phi) * c(th) * c(psi)),
                  -R * ad * (s(phi) * s(psi) - c(phi) * c(th) * c(psi)), -R * ad * s(th) * c(psi)]),
        Quantity("v_0^2", lambda s_: sum(v**2 for v in v0), R**2 * ad**2),
        KineticEnergy(sp.Rational(1, 2) * M * R**2 * ad**2 + sp.Rational(1, 2) * Ix * (ad + psd) ** 2 * s(th) ** 2
                      + sp.Rational(1, 2) * Iz * (phd + (ad + psd) * c(th)) ** 2),
    ],
    simulation=Simulation(params={M: 1.0, Ix: 0.05, Iz: 0.1, th: 0.6, R: 0.5, Om: 1.0, A: 0.3, w: 2.0},
                          initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 10.0}, t_end=3.0),
    ranges={"theta": (0.2, 1.4)},
    correction="T is not printed in the book; it follows from (8.10) with O at the c.m. (catalog). alpha(t) is a "
    "concrete prescribed motion standing for the book's general alpha(t).",
)
