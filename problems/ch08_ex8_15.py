"""Wells, Example 8.15 — symmetric top whose tip slides on a smooth horizontal plane (5 DOF).

Tip at (x1, y1, 0); Euler angles θ, ψ, φ; c.m. at z̄ = r on the axis; I_x = I_y, I_z about the TIP; Ī_x = I_x − M r²
about the c.m. V = M g r cθ. Three forms of T: tip origin (8.10), c.m. origin, and c.m. coordinates x, y.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation
from lagrange.model.inertia import euler_zxz

x1, y1, x, y, th, psi, phi = coordinates("x1 y1 x y theta psi phi")
M, g, r, Ix, Iz = parameters("M g r I_x I_z")
thd, psd, phd = th.diff(t), psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos
Ibx = Ix - M * r**2

orient = EulerAngles(psi, th, phi)
top = RigidBody(M, (Ix, Ix, Iz), origin=(x1, y1, 0), orientation=orient, com=(0, 0, r), name="top")
system = System([x1, y1, th, psi, phi], bodies=[top], V=M * g * top.centre_of_mass[2], name="top sliding on a plane")

# Table 8.2 typed (rows: body axes, columns: inertial axes)
a11 = c(phi) * c(psi) - s(phi) * s(psi) * c(th)
a12 = c(phi) * s(psi) + s(phi) * c(psi) * c(th)
a21 = -s(phi) * c(psi) - c(phi) * s(psi) * c(th)
a22 = -s(phi) * s(psi) + c(phi) * c(psi) * c(th)
a31, a32, a33 = s(th) * s(psi), -s(th) * c(psi), c(th)
wx = psd * s(th) * s(phi) + thd * c(phi)
wy = psd * s(th) * c(phi) - thd * s(phi)
wz = phd + psd * c(th)
v0x = x1.diff(t) * a11 + y1.diff(t) * a12
v0y = x1.diff(t) * a21 + y1.diff(t) * a22
T_rot_tip = sp.Rational(1, 2) * (Ix * (thd**2 + psd**2 * s(th) ** 2) + Iz * wz**2)
T_tip = sp.Rational(1, 2) * M * (x1.diff(t) ** 2 + y1.diff(t) ** 2) + T_rot_tip + M * r * (v0x * wy - v0y * wx)
cm = sp.Matrix([x1 + r * a31, y1 + r * a32, r * a33])
T_cm = sp.Rational(1, 2) * M * sum(v**2 for v in cm.diff(t)) + sp.Rational(1, 2) * (Ibx * (wx**2 + wy**2) + Iz * wz**2)

# third form: x, y are the horizontal coordinates of the c.m.; the body origin is then at the c.m.
centre = RigidBody(M, (Ibx, Ibx, Iz), origin=(x, y, r * c(th)), orientation=orient, name="top")
system_cm = System([x, y, th, psi, phi], bodies=[centre], V=M * g * r * c(th), name="top sliding on a plane (c.m.)")
T_third = (sp.Rational(1, 2) * M * (x.diff(t) ** 2 + y.diff(t) ** 2 + r**2 * thd**2 * s(th) ** 2)
           + sp.Rational(1, 2) * (Ibx * (wx**2 + wy**2) + Iz * wz**2))

SIM = dict(params={M: 1.0, g: 9.81, r: 0.1, Ix: 0.03, Iz: 0.01}, t_end=2.0)
RANGES = {"theta": (0.3, 1.3), "I_x": (2.5, 3.5), "r": (0.5, 1.0), "M": (1.1, 2.0)}  # keep Ibar_x = I_x - M r^2 > 0

PROBLEMS = [
    Problem(
        id="ex8.15",
        title="Top whose tip slides on a smooth plane: T about the tip (8.10) and about the c.m.",
        chapter=8,
        source="Wells, Example 8.15",
        system=system,
        answers=[
            Quantity("direction cosines (Table 8.2 rows)", lambda s_: list(euler_zxz(psi, th, phi)[:2, :2]) + [
                euler_zxz(psi, th, phi)[2, 0], euler_zxz(psi, th, phi)[2, 1], euler_zxz(psi, th, phi)[2, 2]],
                [a11, a12, a21, a22, a31, a32, a33]),
            KineticEnergy(T_tip, description="T, tip form"),
            KineticEnergy(T_cm, description="T, c.m. form"),
            PotentialEnergy(M * g * r * c(th)),
        ],
        simulation=Simulation(initial={x1: 0, y1: 0, th: 0.5, psi: 0, phi: 0, x1.diff(t): 0, y1.diff(t): 0,
                                       thd: 0, psd: 2.0, phd: 60.0}, **SIM),
        ranges=RANGES,
        correction="EOM not given. The tip reaction does no work and does not appear.",
    ),
    Problem(
        id="ex8.15-cm",
        title="Top sliding on a plane in c.m. coordinates: v_cm^2 = x'^2 + y'^2 + r^2 theta'^2 s^2(theta)",
        chapter=8,
        source="Wells, Example 8.15 (third form)",
        system=system_cm,
        answers=[KineticEnergy(T_third), PotentialEnergy(M * g * r * c(th))],
        simulation=Simulation(initial={x: 0, y: 0, th: 0.5, psi: 0, phi: 0, x.diff(t): 0, y.diff(t): 0,
                                       thd: 0, psd: 2.0, phd: 60.0}, **SIM),
        ranges=RANGES,
    ),
]
