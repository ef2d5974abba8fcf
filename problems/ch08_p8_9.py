"""Wells, Problem 8.9 — from x1 = x0 + x α11 + y α21 + z α31 (etc.), the velocity components along the moving
axes v_x = ẋ1 α11 + ẏ1 α12 + ż1 α13 reduce to (8.4): v_x = v_0x + ẋ + Ω_y z − Ω_z y (and cyclic).

The frame's origin (x0, y0, z0) and Euler angles (ψ, θ, φ) and the particle's frame coordinates (x, y, z) are
all free; Ω from (8.11) and v_0x = ẋ0 α11 + ẏ0 α12 + ż0 α13 are typed from the book. A pure identity, checked
without a System (nine coordinates for one particle would only give a singular mass matrix): both sides are
compared after replacing q(t), q̇ by plain symbols.
"""

import sympy as sp

from lagrange import EulerAngles, coordinates, t
from lagrange.corpus import Problem, Quantity
from lagrange.model.coordinates import to_symbols
from lagrange.model.frames import Frame

x0, y0, z0, psi, th, phi, x, y, z = coordinates("x0 y0 z0 psi theta phi x y z")
psd, thd, phd = psi.diff(t), th.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

frame = Frame(origin=(x0, y0, z0), rotation=EulerAngles(psi, th, phi).matrix, name="moving frame")
pos = frame.point((x, y, z))
Q = (x0, y0, z0, psi, th, phi, x, y, z)
SYMS = {**{q.diff(t): to_symbols(q.diff(t), Q) for q in Q}, **{q: to_symbols(q, Q) for q in Q}}


def plain(e):
    """q(t), q̇ → plain symbols (xreplace: derivatives are matched before the functions inside them)."""
    return e.xreplace(SYMS)


al = [
    [c(phi) * c(psi) - s(phi) * s(psi) * c(th), c(phi) * s(psi) + s(phi) * c(psi) * c(th), s(th) * s(phi)],
    [-s(phi) * c(psi) - c(phi) * s(psi) * c(th), -s(phi) * s(psi) + c(phi) * c(psi) * c(th), s(th) * c(phi)],
    [s(th) * s(psi), -s(th) * c(psi), c(th)],
]
Ox = psd * s(th) * s(phi) + thd * c(phi)
Oy = psd * s(th) * c(phi) - thd * s(phi)
Oz = phd + psd * c(th)
v0 = [x0.diff(t) * al[i][0] + y0.diff(t) * al[i][1] + z0.diff(t) * al[i][2] for i in range(3)]


def frame_components(sys_):
    v = pos.diff(t)
    return [plain(sum(v[j] * al[i][j] for j in range(3))) for i in range(3)]


PROBLEM = Problem(
    id="p8.9",
    title="Velocity of a particle along translating and rotating axes reduces to (8.4)",
    chapter=8,
    source="Wells, Problem 8.9 (also Problem 9.1)",
    system=None,
    answers=[
        Quantity("v along the moving axes", frame_components,
                 [plain(e) for e in (v0[0] + x.diff(t) + Oy * z - Oz * y, v0[1] + y.diff(t) + Oz * x - Ox * z,
                                             v0[2] + z.diff(t) + Ox * y - Oy * x)]),
    ],
    correction="Kinematic identity (no system, no simulation).",
)
