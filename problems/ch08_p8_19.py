"""Wells, Problem 8.19 — T = ½ M v_cm² + ½ I ω², with I the moment of inertia about the instantaneous axis
through the c.m. (direction cosines l, m, n = ω_x/ω, ω_y/ω, ω_z/ω along the body axes):
I = I_x l² + I_y m² + I_z n² − 2 I_xy l m − 2 I_xz l n − 2 I_yz m n (Wells' positive products, about the c.m.).
Free body: c.m. at (x, y, z), Euler angles ψ, θ, φ.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.inertia import Inertia

x, y, z, psi, th, phi = coordinates("x y z psi theta phi")
M, Ix, Iy, Iz, Ixy, Ixz, Iyz = parameters("M I_x I_y I_z I_xy I_xz I_yz")
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

body = RigidBody(M, Inertia(Ix, Iy, Iz, I_xy=Ixy, I_xz=Ixz, I_yz=Iyz), origin=(x, y, z),
                 orientation=EulerAngles(psi, th, phi), name="free body")
system = System([x, y, z, psi, th, phi], bodies=[body], name="free rigid body, origin at the c.m.")

wx = psd * s(th) * s(phi) + thd * c(phi)
wy = psd * s(th) * c(phi) - thd * s(phi)
wz = phd + psd * c(th)
w = sp.sqrt(wx**2 + wy**2 + wz**2)
l_, m_, n_ = wx / w, wy / w, wz / w
I_axis = Ix * l_**2 + Iy * m_**2 + Iz * n_**2 - 2 * Ixy * l_ * m_ - 2 * Ixz * l_ * n_ - 2 * Iyz * m_ * n_

PROBLEM = Problem(
    id="p8.19",
    title="T = 1/2 M v_cm^2 + 1/2 I omega^2 about the instantaneous axis through the c.m.",
    chapter=8,
    source="Wells, Problem 8.19",
    system=system,
    answers=[KineticEnergy(sp.Rational(1, 2) * M * (x.diff(t) ** 2 + y.diff(t) ** 2 + z.diff(t) ** 2)
                           + sp.Rational(1, 2) * I_axis * w**2)],
    simulation=Simulation(params={M: 1.0, Ix: 0.3, Iy: 0.4, Iz: 0.5, Ixy: 0.02, Ixz: 0.03, Iyz: 0.01},
                          initial={x: 0, y: 0, z: 0, psi: 0, th: 0.8, phi: 0, x.diff(t): 1.0, y.diff(t): 0.0,
                                   z.diff(t): 0.5, psd: 0.3, thd: 0.2, phd: 2.0}, t_end=3.0),
    ranges={"theta": (0.3, 1.3), "I_xy": (0.01, 0.2), "I_xz": (0.01, 0.2), "I_yz": (0.01, 0.2)},
)
