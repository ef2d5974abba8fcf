"""Wells, Example 9.8 — top with a fixed tip by Euler's method (x_bar = y_bar = 0, z_bar = r, I_x = I_y about the tip).

Wells' Euler angles (psi precession, theta nutation, phi spin; z-x-z). Gravity along -Z1.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, Problem, Quantity, Simulation
from lagrange.derive.euler import euler_equations, support_loads

psi, th, phi = coordinates("psi theta phi")
M, g, r, Ix, Iz = parameters("M g r I_x I_z")
st, ct, sph, cph = sp.sin(th), sp.cos(th), sp.sin(phi), sp.cos(phi)
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)
psdd, thdd, phdd = psi.diff(t, 2), th.diff(t, 2), phi.diff(t, 2)

top = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, th, phi), com=(0, 0, r), name="top")
gravity = (0, 0, -M * g)
system = System([th, psi, phi], bodies=[top], V=M * g * top.centre_of_mass[2], name="top with a fixed tip")

B_book = [
    Ix * (psdd * st * sph + 2 * psd * thd * ct * sph + thdd * cph - psd**2 * st * ct * cph)
    + Iz * (psd * st * cph - thd * sph) * (phd + psd * ct),
    Ix * (psdd * st * cph + 2 * psd * thd * ct * cph - thdd * sph + psd**2 * st * ct * sph)
    - Iz * (psd * st * sph + thd * cph) * (phd + psd * ct),
    Iz * (phdd + psdd * ct - psd * thd * st),
]
A_book = [
    r * (psd**2 * st * ct * sph + 2 * thd * psd * ct * cph + psdd * st * cph - thdd * sph),
    r * (psd**2 * st * ct * cph - 2 * thd * psd * ct * sph - psdd * st * sph - thdd * cph),
    -r * (thd**2 + psd**2 * st**2),
]
# M A = F with F_x = -M g sth sphi + f_x, etc.: the tip reaction along the body axes
f_book = [M * A_book[0] + M * g * st * sph, M * A_book[1] + M * g * st * cph, M * A_book[2] + M * g * ct]


def _tip_reaction_body(_s):
    F, _tau = support_loads(top, gravity, frame="inertial")
    return list(top.R.T * F)


P_phi = Iz * (phd + psd * ct)
PROBLEM = Problem(
    id="ex9.8",
    title="Top with a fixed tip by Euler's method: B components, tip reaction, equations (5)-(7), first integrals",
    chapter=9,
    source="Wells, Example 9.8",
    system=system,
    answers=[
        Quantity("B = J omegadot + omega x J omega (body axes)", lambda _s: list(euler_equations(top)), B_book),
        Quantity("tip reaction along body axes (f_x, f_y, f_z)", _tip_reaction_body, f_book),
        EquationsOfMotion(
            [
                sp.Eq(Ix * (thdd - psd**2 * st * ct) + Iz * (psd**2 * st * ct + phd * psd * st), M * g * r * st),
                sp.Eq(Ix * (psdd * st**2 + 2 * psd * thd * st * ct)
                      + Iz * (psdd * ct**2 + phdd * ct - 2 * thd * psd * st * ct - thd * phd * st), 0),
                sp.Eq(Iz * (phdd + psdd * ct - psd * thd * st), 0),
            ],
            per_equation=True,
        ),
        ConservedMomenta({phi: P_phi, psi: Ix * psd * st**2 + P_phi * ct}),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, r: 0.1, Ix: 0.02, Iz: 0.01},
                          initial={th: 0.5, psi: 0.0, phi: 0.0, thd: 0.0, psd: 1.0, phd: 50.0}, t_end=3),
    ranges={"theta": (0.3, 1.2)},
)
