"""Wells, Problem 8.23 — symmetric top whose base (the tip) oscillates horizontally as x = A sin ωt.

Tip origin, Z along the axis, c.m. at z̄ = r; I_x = I_y, I_z about the tip; V = M g r cθ.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

th, psi, phi = coordinates("theta psi phi")
M, g, r, Ix, Iz, A, w = parameters("M g r I_x I_z A omega")
thd, psd, phd = th.diff(t), psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

top = RigidBody(M, (Ix, Ix, Iz), origin=(A * s(w * t), 0, 0), orientation=EulerAngles(psi, th, phi), com=(0, 0, r),
                name="top")
system = System([th, psi, phi], bodies=[top], V=M * g * top.centre_of_mass[2], name="top on an oscillating base")


def theta_residual(sys_):
    e = sys_.equations()[0]
    return e.lhs - e.rhs


PROBLEM = Problem(
    id="p8.23",
    title="Top on a base oscillating as A sin(wt): T and the theta equation",
    chapter=8,
    source="Wells, Problem 8.23",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * M * A**2 * w**2 * c(w * t) ** 2
                      + sp.Rational(1, 2) * Ix * (thd**2 + psd**2 * s(th) ** 2) + sp.Rational(1, 2) * Iz * (phd + psd * c(th)) ** 2
                      + M * A * w * r * c(w * t) * (psd * s(th) * c(psi) + thd * c(th) * s(psi))),
        Quantity("theta equation (lhs - rhs)", theta_residual,
                 Ix * th.diff(t, 2) + (Iz - Ix) * psd**2 * s(th) * c(th) + Iz * phd * psd * s(th)
                 - M * A * w**2 * r * s(w * t) * c(th) * s(psi) - M * g * r * s(th)),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, r: 0.1, Ix: 0.02, Iz: 0.01, A: 0.02, w: 10.0},
                          initial={th: 0.5, psi: 0.0, phi: 0.0, thd: 0.0, psd: 2.0, phd: 60.0}, t_end=3.0),
    ranges={"theta": (0.3, 1.3)},
    correction="The OCR prints psi' s^2(theta) in T; it is psi'^2 s^2(theta). Time-dependent T: no energy check.",
)
