"""Wells, Problem 9.2 — with T' = 1/2[(v_0x + xdot + Omega_y z - Omega_z y)^2 + ...] (v_0 and Omega along the
moving axes, known functions of t), d/dt(dT'/dxdot) - dT'/dx equals a_x of (9.6a).

Omega and v_0 are taken as general quadratics in t (parameters p_ij); a_0x = vdot_0x + Omega_y v_0z - Omega_z v_0y
is the acceleration of O along the moving axes.
"""

import sympy as sp

from lagrange import System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

x, y, z = coordinates("x y z")
c = parameters(" ".join(f"c{i}{j}" for i in range(6) for j in range(3)))
quad = [c[3 * i] + c[3 * i + 1] * t + c[3 * i + 2] * t**2 for i in range(6)]
Wx, Wy, Wz, v0x, v0y, v0z = quad
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
half = sp.Rational(1, 2)
Tp = half * ((v0x + xd + Wy * z - Wz * y) ** 2 + (v0y + yd + Wz * x - Wx * z) ** 2
             + (v0z + zd + Wx * y - Wy * x) ** 2)
system = System([x, y, z], T=Tp, name="T' of a particle in a moving frame (unit mass)")

a0 = [v0x.diff(t) + Wy * v0z - Wz * v0y, v0y.diff(t) + Wz * v0x - Wx * v0z, v0z.diff(t) + Wx * v0y - Wy * v0x]
ax = (a0[0] + x.diff(t, 2) - x * (Wy**2 + Wz**2) + y * (Wx * Wy - Wz.diff(t)) + z * (Wx * Wz + Wy.diff(t))
      + 2 * (zd * Wy - yd * Wz))
ay = (a0[1] + y.diff(t, 2) - y * (Wz**2 + Wx**2) + z * (Wy * Wz - Wx.diff(t)) + x * (Wy * Wx + Wz.diff(t))
      + 2 * (xd * Wz - zd * Wx))
az = (a0[2] + z.diff(t, 2) - z * (Wx**2 + Wy**2) + x * (Wz * Wx - Wy.diff(t)) + y * (Wz * Wy + Wx.diff(t))
      + 2 * (yd * Wx - xd * Wy))

PROBLEM = Problem(
    id="p9.2",
    title="Lagrangian method for accelerations: d/dt(dT'/dxdot) - dT'/dx = a_x of (9.6a)",
    chapter=9,
    source="Wells, Problem 9.2, eq. (9.6)",
    system=system,
    answers=[Quantity("(a_x, a_y, a_z) = Lagrange expressions of T'",
                      lambda s: [e.lhs - e.rhs for e in s.equations()], [ax, ay, az])],
    ranges={ci: (-1.0, 1.0) for ci in c},
    correction="(9.6a) for a_y, a_z by cyclic permutation of x, y, z.",
)
