"""Wells, Problem 7.25 — principal moments referred to fixed axes through Euler angles."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import Inertia, euler_zxz

Ixp, Iyp, Izp, psi, theta, phi = parameters("I_xp I_yp I_zp psi theta phi")
cps, sps, cth, sth, cph, sph = sp.cos(psi), sp.sin(psi), sp.cos(theta), sp.sin(theta), sp.cos(phi), sp.sin(phi)

PROBLEM = Problem(
    id="p7.25",
    title="Principal moments to fixed axes via Wells' Euler angles (z-x-z, ψ precession, φ spin)",
    chapter=7,
    source="Wells, Problem 7.25",
    system=None,
    answers=[Quantity("I_x1", lambda _: Inertia(Ixp, Iyp, Izp).rotated(euler_zxz(psi, theta, phi).T).I_x,
                      Ixp * (cph * cps - sph * sps * cth) ** 2 + Iyp * (sph * cps + cph * sps * cth) ** 2
                      + Izp * sth**2 * sps**2)],
)
