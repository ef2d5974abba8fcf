"""Wells, Problem 7.24 — cone with its apex fixed: I_x1 about the fixed X1 axis in Euler angles."""

import sympy as sp

from lagrange import parameters
from lagrange.corpus import Problem, Quantity
from lagrange.model.inertia import euler_zxz
from lagrange.model.standard_bodies import cone

M, r, h, psi, theta, phi = parameters("M r h psi theta phi")
at_apex = cone(M, r, h).from_centre(M, (0, 0, 3 * h / 4))  # apex 3h/4 above the c.m. on the axis
fixed = at_apex.rotated(euler_zxz(psi, theta, phi).T)  # body -> fixed axes X1, Y1, Z1

PROBLEM = Problem(
    id="p7.24",
    title="Cone with the apex fixed: moment about the fixed X1 axis in Wells' Euler angles",
    chapter=7,
    source="Wells, Problem 7.24",
    system=None,
    answers=[Quantity("I_x1", lambda _: fixed.I_x,
                      sp.Rational(3, 20) * M * (r**2 + 4 * h**2 - (4 * h**2 - r**2) * sp.sin(theta) ** 2 * sp.sin(psi) ** 2))],
    correction="The OCR prints (3/20)M[r² + h² - ...]; the apex moment is (3/20)M(r² + 4h²), so r² + 4h². "
               "Check: θ = ψ = 90° must give the axial (3/10)Mr², which only the corrected form does.",
)
