"""Wells, Example 8.10 — arbitrary rigid body in the Fig. 8-12 mount (frame ψ about the vertical, shaft at the
constant θ, spin φ); body axes not principal, c.m. off the origin, O fixed (v_0 = 0).

(a) T with Wells' positive products of inertia about O. (b) principal axes: the principal directions have
constant direction cosines α_ij relative to the body axes (here the rows of A = R_x(a)ᵀ R_z(b)ᵀ, a and b constant),
so J = Aᵀ diag(I1, I2, I3) A and ω_i = ω_x α_i1 + ω_y α_i2 + ω_z α_i3.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.inertia import Inertia
from lagrange.model.rotations import rot_x, rot_z

psi, phi = coordinates("psi phi")
M, Ix, Iy, Iz, Ixy, Ixz, Iyz, th, xb, yb, zb = parameters("M I_x I_y I_z I_xy I_xz I_yz theta xbar ybar zbar")
I1, I2, I3, a, b = parameters("I_1 I_2 I_3 a b")
psd, phd = psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

body = RigidBody(M, Inertia(Ix, Iy, Iz, I_xy=Ixy, I_xz=Ixz, I_yz=Iyz), orientation=EulerAngles(psi, th, phi),
                 com=(xb, yb, zb), name="body")
system = System([psi, phi], bodies=[body], name="arbitrary body in the Fig. 8-12 mount")

A = (rot_z(b) * rot_x(a)).T  # rows: principal directions in body components (alpha_ij)
J = A.T * sp.diag(I1, I2, I3) * A
principal = RigidBody(M, J, orientation=EulerAngles(psi, th, phi), com=(xb, yb, zb), name="body")
system_b = System([psi, phi], bodies=[principal], name="body in the Fig. 8-12 mount (principal moments)")

wx, wy, wz = psd * s(th) * s(phi), psd * s(th) * c(phi), phd + psd * c(th)
wp = [A[i, 0] * wx + A[i, 1] * wy + A[i, 2] * wz for i in range(3)]

PROBLEMS = [
    Problem(
        id="ex8.10",
        title="Arbitrary body (products of inertia, c.m. off O) in the Fig. 8-12 mount, O fixed: T",
        chapter=8,
        source="Wells, Example 8.10 (a)",
        system=system,
        answers=[
            KineticEnergy(sp.Rational(1, 2) * (Ix * psd**2 * s(th) ** 2 * s(phi) ** 2 + Iy * psd**2 * s(th) ** 2 * c(phi) ** 2
                                               + Iz * (phd + psd * c(th)) ** 2)
                          - (Ixy * psd**2 * s(th) ** 2 * s(phi) * c(phi) + Ixz * (psd * s(th) * s(phi)) * (phd + psd * c(th))
                             + Iyz * (psd * s(th) * c(phi)) * (phd + psd * c(th)))),
        ],
        simulation=Simulation(params={Ix: 0.3, Iy: 0.4, Iz: 0.5, Ixy: 0.02, Ixz: 0.03, Iyz: 0.01, th: 0.6},
                              initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 5.0}, t_end=3.0),
        ranges={"theta": (0.2, 1.4), "I_xy": (0.01, 0.2), "I_xz": (0.01, 0.2), "I_yz": (0.01, 0.2)},
        correction="The c.m. position does not enter T because O is fixed. M, xbar, ybar, zbar drop out of the system.",
    ),
    Problem(
        id="ex8.10-b",
        title="The same body through its principal axes: T = 1/2(I1 w1^2 + I2 w2^2 + I3 w3^2)",
        chapter=8,
        source="Wells, Example 8.10 (b)",
        system=system_b,
        answers=[KineticEnergy(sp.Rational(1, 2) * (I1 * wp[0] ** 2 + I2 * wp[1] ** 2 + I3 * wp[2] ** 2))],
        simulation=Simulation(params={I1: 0.3, I2: 0.4, I3: 0.5, a: 0.3, b: 0.2, th: 0.6},
                              initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 5.0}, t_end=3.0),
        ranges={"theta": (0.2, 1.4)},
        correction="The principal directions are an arbitrary constant rotation (a, b) of the body axes, standing for "
        "the book's eigen-decomposition (Sec. 7.3).",
    ),
]
