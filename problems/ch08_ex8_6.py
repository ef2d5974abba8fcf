"""Wells, Example 8.6 — (a) lamina hung on a string of constant length r (a double pendulum); (b) a lamina whose
body point O slides on the smooth parabola y1 = b x1².

(a) The string runs from the fixed origin to the lamina point O = (r cθ, r sθ), X1 vertically down (gravity Mg
along +X1, at the c.m.); φ is the lamina's angle (body X from X1), so ω_z = φ̇; c.m. at (x̄, ȳ) along the body axes,
I_z about O. This geometry reproduces the book's v_0x = r θ̇ s(φ−θ), v_0y = r θ̇ c(φ−θ).
(b) Y1 vertical, O = (x1, b x1²); body X along (sφ, −cφ) (φ measured from the downward vertical), which gives the
book's v_0x = ẋ1 sφ − ẏ1 cφ, v_0y = ẋ1 cφ + ẏ1 sφ; ẏ1 = 2 b x1 ẋ1 eliminated.
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.rotations import rot_z

th, phi, x1 = coordinates("theta phi x1")
M, g, r, Iz, xb, yb, b = parameters("M g r I_z xbar ybar b")
thd, phd, x1d = th.diff(t), phi.diff(t), x1.diff(t)
C, S = sp.cos(phi - th), sp.sin(phi - th)

lam_a = RigidBody(M, (0, 0, Iz), origin=(r * sp.cos(th), r * sp.sin(th), 0), orientation=rot_z(phi),
                  com=(xb, yb, 0), name="lamina")
system_a = System([th, phi], bodies=[lam_a], V=-M * g * lam_a.centre_of_mass[0], name="lamina on a string")

y1 = b * x1**2
lam_b = RigidBody(M, (0, 0, Iz), origin=(x1, y1, 0), orientation=rot_z(phi - sp.pi / 2), com=(xb, yb, 0),
                  name="lamina")
system_b = System([x1, phi], bodies=[lam_b], V=M * g * lam_b.centre_of_mass[1], name="lamina on a parabola")
y1d = 2 * b * x1 * x1d

PROBLEMS = [
    Problem(
        id="ex8.6",
        title="Lamina on a string of constant length (double pendulum): omega_z = phi', v_0, T",
        chapter=8,
        source="Wells, Example 8.6 (a)",
        system=system_a,
        answers=[
            Quantity("omega_z", lambda s_: lam_a.angular_velocity[2], phd),
            Quantity("v_0 along the body axes", lambda s_: list(lam_a.R.T * lam_a.origin.diff(t))[:2],
                     [r * thd * S, r * thd * C]),
            KineticEnergy(sp.Rational(1, 2) * M * r**2 * thd**2 + sp.Rational(1, 2) * Iz * phd**2
                          + M * r * thd * phd * (xb * C - yb * S)),
        ],
        simulation=Simulation(params={M: 1.0, g: 9.81, r: 1.0, Iz: 0.2, xb: 0.3, yb: 0.1},
                              initial={th: 0.4, phi: 0.2, thd: 0.0, phd: 0.0}, t_end=5.0),
        correction="OCR prints the bars of xbar, ybar as dots. The book gives T only (gravity Mg at the c.m.).",
    ),
    Problem(
        id="ex8.6-b",
        title="Lamina whose point O slides on the smooth parabola y1 = b x1^2: v_0 and T (8.10)",
        chapter=8,
        source="Wells, Example 8.6 (b)",
        system=system_b,
        answers=[
            Quantity("v_0 along the body axes", lambda s_: list(lam_b.R.T * lam_b.origin.diff(t))[:2],
                     [x1d * sp.sin(phi) - y1d * sp.cos(phi), x1d * sp.cos(phi) + y1d * sp.sin(phi)]),
            KineticEnergy(sp.Rational(1, 2) * M * (x1d**2 + y1d**2) + sp.Rational(1, 2) * Iz * phd**2
                          + M * phd * (xb * (x1d * sp.cos(phi) + y1d * sp.sin(phi))
                                       - yb * (x1d * sp.sin(phi) - y1d * sp.cos(phi)))),
        ],
        simulation=Simulation(params={M: 1.0, g: 9.81, b: 0.5, Iz: 0.2, xb: 0.3, yb: 0.1},
                              initial={x1: 0.5, phi: 0.2, x1d: 0.0, phd: 0.0}, t_end=5.0),
        correction="The OCR garbles the cross term as M phi[x.(...) - y.(...)]; the catalog's reading "
        "M phi'[xbar(x1' c(phi) + y1' s(phi)) - ybar(x1' s(phi) - y1' c(phi))] is used, with y1' = 2 b x1 x1'. "
        "The book gives no EOM; gravity (Y1 up) is added for the simulation only.",
    ),
]
