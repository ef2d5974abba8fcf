"""Wells, Problem 8.11 — disk on shaft bc at the distance s from the fixed intersection point b, shaft at the
constant angle θ, frame A (moment I1 about the vertical) turning by ψ, disk spin φ.

(a) Origin at the disk's c.m.: T = ½(M s² + Ī_x) ψ̇² s²θ + ½ Ī_z(ψ̇ cθ + φ̇)² + ½ I1 ψ̇².
(b) Origin at b (fixed): I_x = Ī_x + M s² about b, c.m. at z̄ = s; the same T.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Simulation
from lagrange.model.inertia import Inertia
from lagrange.model.rotations import rot_z

psi, phi = coordinates("psi phi")
M, Ix, Iz, I1, th, s_ = parameters("M Ibar_x Ibar_z I_1 theta s")
psd, phd = psi.diff(t), phi.diff(t)

orient = EulerAngles(psi, th, phi)
frame = RigidBody(0, (0, 0, I1), orientation=rot_z(psi), name="frame A")
centre = RigidBody(M, (Ix, Ix, Iz), origin=orient.matrix * sp.Matrix([0, 0, s_]), orientation=orient, name="disk")
about_b = RigidBody(M, Inertia(Ix, Ix, Iz).from_centre(M, (0, 0, s_)), orientation=orient, com=(0, 0, s_), name="disk")
T_book = (sp.Rational(1, 2) * (M * s_**2 + Ix) * psd**2 * sp.sin(th) ** 2
          + sp.Rational(1, 2) * Iz * (psd * sp.cos(th) + phd) ** 2 + sp.Rational(1, 2) * I1 * psd**2)
SIM = Simulation(params={M: 1.0, Ix: 0.05, Iz: 0.1, I1: 0.2, th: 0.6, s_: 0.3},
                 initial={psi: 0.0, phi: 0.0, psd: 0.5, phd: 20.0}, t_end=5.0)

PROBLEMS = [
    Problem(id="p8.11", title="Disk at distance s on an inclined shaft in a turning frame: T with origin at the c.m.",
            chapter=8, source="Wells, Problem 8.11 (a)",
            system=System([psi, phi], bodies=[centre, frame], name="disk on shaft bc (origin at c.m.)"),
            answers=[KineticEnergy(T_book)], simulation=SIM, ranges={"theta": (0.2, 1.4)}),
    Problem(id="p8.11-b", title="Same disk with the origin at the fixed point b: the same T",
            chapter=8, source="Wells, Problem 8.11 (b)",
            system=System([psi, phi], bodies=[about_b, frame], name="disk on shaft bc (origin at b)"),
            answers=[KineticEnergy(T_book)], simulation=SIM, ranges={"theta": (0.2, 1.4)},
            correction="(b) is tagged [PARTIAL] in the catalog (the book only says the T is the same); the T of (a) is used."),
]
