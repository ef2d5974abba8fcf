"""Wells, Example 8.23 — particle m' on a rotating table (angle θ) whose base rides an elevator with constant
upward acceleration a and initial speed v0; the table axes' origin is at radius r from the rotation axis, turned
by the constant β. Transformation equations:
x1 = r cθ + x c(θ+β) − y s(θ+β), y1 = r sθ + x s(θ+β) + y c(θ+β), z1 = z + v0 t + ½ a t².
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity

x, y, z, th = coordinates("x y z theta")
m, r, beta, v0, a = parameters("m r beta v0 a")
xd, yd, zd, thd = x.diff(t), y.diff(t), z.diff(t), th.diff(t)
cb, sb = sp.cos(beta), sp.sin(beta)

X1 = r * sp.cos(th) + x * sp.cos(th + beta) - y * sp.sin(th + beta)
Y1 = r * sp.sin(th) + x * sp.sin(th + beta) + y * sp.cos(th + beta)
Z1 = z + v0 * t + sp.Rational(1, 2) * a * t**2
system = System([x, y, z, th], bodies=[Particle(m, (X1, Y1, Z1))], name="particle on a rotating table in an elevator")


def frame_velocity(s):
    """Velocity along the table axes x, y (directions θ+β) and z."""
    v = sp.Matrix([X1, Y1, Z1]).diff(t)
    ex = sp.Matrix([sp.cos(th + beta), sp.sin(th + beta), 0])
    ey = sp.Matrix([-sp.sin(th + beta), sp.cos(th + beta), 0])
    return [v.dot(ex), v.dot(ey), v[2]]


PROBLEM = Problem(
    id="ex8.23",
    title="Particle on a rotating table riding an elevator: velocity components (8.4) and T(q, q', t)",
    chapter=8,
    source="Wells, Example 8.23",
    system=system,
    answers=[
        Quantity("velocity along the table axes", frame_velocity,
                 [r * thd * sb + xd - thd * y, r * thd * cb + yd + thd * x, v0 + a * t + zd]),
        KineticEnergy(sp.Rational(1, 2) * m * (xd**2 + yd**2 + r**2 * thd**2 + (x**2 + y**2) * thd**2
                                               + 2 * r * thd**2 * (x * cb - y * sb) + 2 * r * thd * (yd * cb + xd * sb)
                                               + 2 * thd * (x * yd - y * xd) + (v0 + a * t + zd) ** 2)),
    ],
    correction="The text says 'applying (8.2)'; it means (8.4). The accelerations are requested but not printed. "
    "The table's own inertia is not given, so the mass matrix (particle only, 4 coordinates) is singular: no simulation.",
)
