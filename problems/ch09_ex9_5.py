"""Wells, Example 9.5 — disk of Fig. 8-12 on a shaft at the fixed angle theta to Z1, turned about Z1 by a motor
(psi), spinning freely on the shaft (phi); c.m. fixed at O; bearings a, b on the shaft at distances l1, l2.

Wells' Euler angles with theta constant; I_bar_x = I_bar_y, I_bar_z about the c.m.; gravity along -Z1; the motor's
generalized force on psi is tau_psi (the bearing moments' projection, book (5)).
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, Problem, Quantity, Simulation
from lagrange.derive.euler import euler_equations, support_loads

psi, phi = coordinates("psi phi")
M, g, Ix, Iz, th, tau_psi = parameters("M g Ibar_x Ibar_z theta tau_psi")
st, ct, sph, cph = sp.sin(th), sp.cos(th), sp.sin(phi), sp.cos(phi)
psd, phd = psi.diff(t), phi.diff(t)

disk = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, th, phi), name="disk")
gravity = (0, 0, -M * g)
system = System([psi, phi], bodies=[disk], forces={psi: tau_psi}, name="disk on an inclined driven shaft")


def _bearing_force_sum(_s):
    F, _tau = support_loads(disk, gravity, frame="inertial")
    return list(disk.R.T * F)


PROBLEM = Problem(
    id="ex9.5",
    title="Disk on a driven inclined shaft: bearing force sums, Euler's equations (2)-(4), Ibar_x psidd s^2 theta = tau_psi",
    chapter=9,
    source="Wells, Example 9.5 (Fig. 8-12)",
    system=system,
    answers=[
        # (1): f_x1 + f_x2 = M g sth sphi, f_y1 + f_y2 = M g sth cphi, f_z = M g cth
        Quantity("bearing force sums along body axes (1)", _bearing_force_sum, [M * g * st * sph, M * g * st * cph, M * g * ct]),
        # (2), (3), (4): the bearing moments f_y1 l1 - f_y2 l2, f_x2 l2 - f_x1 l1, 0
        Quantity("Euler's equations (2), (3), (4), left sides", lambda _s: list(euler_equations(disk)), [
            Ix * (psi.diff(t, 2) * st * sph + psd * phd * st * cph) + (Iz - Ix) * (psd * st * cph) * (phd + psd * ct),
            Ix * (psi.diff(t, 2) * st * cph - psd * phd * st * sph) - (Iz - Ix) * (psd * st * sph) * (phd + psd * ct),
            Iz * (phi.diff(t, 2) + psi.diff(t, 2) * ct),
        ]),
        EquationsOfMotion([sp.Eq(Ix * psi.diff(t, 2) * st**2, tau_psi),
                           sp.Eq(Iz * sp.diff(phd + psd * ct, t), 0)]),
        ConservedMomenta({phi: Iz * (phd + psd * ct)}),
    ],
    simulation=Simulation(params={Ix: 0.5, Iz: 1.0, th: 0.6, tau_psi: 0.2},
                          initial={psi: 0.0, phi: 0.0, psd: 1.0, phd: 10.0}, t_end=5),
    ranges={"theta": (0.3, 1.2)},
    correction="Book (5) is the psi Lagrange equation with (4) used to remove the spin term, so the equations are "
    "compared through the accelerations (not one-to-one per coordinate).",
)
