"""Wells, Problem 8.13 — the lamina of Ex 8.6(a) hung on an elastic string (r variable, stiffness k, natural
length r0). Same geometry as Ex 8.6(a): O = (r cθ, r sθ) with X1 vertically down, gravity Mg along +X1.
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.rotations import rot_z

r, th, phi = coordinates("r theta phi")
M, g, k, r0, Iz, xb, yb = parameters("M g k r0 I_z xbar ybar")
rd, thd, phd = r.diff(t), th.diff(t), phi.diff(t)
C, S = sp.cos(phi - th), sp.sin(phi - th)

lamina = RigidBody(M, (0, 0, Iz), origin=(r * sp.cos(th), r * sp.sin(th), 0), orientation=rot_z(phi),
                   com=(xb, yb, 0), name="lamina")
system = System([r, th, phi], bodies=[lamina],
                V=-M * g * lamina.centre_of_mass[0] + sp.Rational(1, 2) * k * (r - r0) ** 2,
                name="lamina on an elastic string")


def r_residual(s):
    e = s.equations()[0]
    return e.lhs - e.rhs


PROBLEM = Problem(
    id="p8.13",
    title="Lamina on an elastic string: T and the r equation",
    chapter=8,
    source="Wells, Problem 8.13",
    system=system,
    answers=[
        KineticEnergy(sp.Rational(1, 2) * M * (rd**2 + r**2 * thd**2) + sp.Rational(1, 2) * Iz * phd**2
                      - M * rd * phd * (xb * S + yb * C) + M * r * phd * thd * (xb * C - yb * S)),
        Quantity("r equation (lhs - rhs)", r_residual,
                 M * (r.diff(t, 2) - r * thd**2) - M * phi.diff(t, 2) * (xb * S + yb * C)
                 - M * phd**2 * (xb * C - yb * S) - (M * g * sp.cos(th) - k * (r - r0))),
    ],
    simulation=Simulation(params={M: 1.0, g: 9.81, k: 40.0, r0: 1.0, Iz: 0.2, xb: 0.3, yb: 0.1},
                          initial={r: 1.2, th: 0.4, phi: 0.2, rd: 0.0, thd: 0.0, phd: 0.0}, t_end=5.0),
    correction="The book prints the last term of T as -M r phi' theta'[xbar c(phi-theta) - ybar s(phi-theta)]; the sign must be + "
    "(consistent with Ex 8.6(a), and the printed r equation follows only with +; with - an extra "
    "+2 M phi' theta'[...] would appear). The OCR prints m for the first M and dots for the bars.",
)
