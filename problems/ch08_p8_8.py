"""Wells, Problem 8.8 — verify (8.11) and Table 8.2 for the Euler angles (Fig. 8-16, z-x-z).

Table 8.2 is checked against the chain R = R_z(ψ) R_x(θ) R_z(φ) (α = Rᵀ) and against euler_zxz; (8.11) against the
engine's EulerAngles and against vee(Rᵀ Ṙ) of the chain (the definition, Wells Sec. 8.7); the space components
(Ex 8.19) against R ω.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.inertia import euler_zxz
from lagrange.model.rotations import rot_x, rot_z

psi, th, phi = coordinates("psi theta phi")
A, B, C = parameters("A B C")
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

body = RigidBody(1, (A, B, C), orientation=EulerAngles(psi, th, phi), name="body")
system = System([psi, th, phi], bodies=[body], name="free rotation in Euler angles")
CHAIN = rot_z(psi) * rot_x(th) * rot_z(phi)


def chain_omega(_):
    W = CHAIN.T * CHAIN.diff(t)  # [omega]x along the body axes
    return [W[2, 1], W[0, 2], W[1, 0]]


table = [
    c(phi) * c(psi) - s(phi) * s(psi) * c(th), c(phi) * s(psi) + s(phi) * c(psi) * c(th), s(th) * s(phi),
    -s(phi) * c(psi) - c(phi) * s(psi) * c(th), -s(phi) * s(psi) + c(phi) * c(psi) * c(th), s(th) * c(phi),
    s(th) * s(psi), -s(th) * c(psi), c(th),
]
wx = psd * s(th) * s(phi) + thd * c(phi)
wy = psd * s(th) * c(phi) - thd * s(phi)
wz = phd + psd * c(th)

PROBLEM = Problem(
    id="p8.8",
    title="Euler angles: body components (8.11), space components and Table 8.2",
    chapter=8,
    source="Wells, Problem 8.8 (Table 8.2, eq. 8.11; space components as in Ex 8.19)",
    system=system,
    answers=[
        Quantity("Table 8.2: alpha = R^T from the rotation chain", lambda s_: list(CHAIN.T), table),
        Quantity("Table 8.2: lagrange.model.inertia.euler_zxz", lambda s_: list(euler_zxz(psi, th, phi)), table),
        Quantity("(8.11) omega along the body axes (EulerAngles)", lambda s_: body.angular_velocity, [wx, wy, wz]),
        Quantity("(8.11) omega along the body axes (vee of R^T R' of the chain)", chain_omega, [wx, wy, wz]),
        Quantity("omega along the space axes", lambda s_: body.space_angular_velocity,
                 [thd * c(psi) + phd * s(th) * s(psi), thd * s(psi) - phd * s(th) * c(psi), psd + phd * c(th)]),
        KineticEnergy(sp.Rational(1, 2) * (A * wx**2 + B * wy**2 + C * wz**2)),
    ],
    simulation=Simulation(params={A: 1.0, B: 2.0, C: 3.0},
                          initial={psi: 0.0, th: 0.8, phi: 0.0, psd: 0.3, thd: 0.2, phd: 1.0}, t_end=3.0),
    ranges={"theta": (0.3, 1.3)},
)
