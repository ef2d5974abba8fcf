"""Wells, Sec. 14.4, eqs. (14.14), (14.15), (14.25) — a particle in the earth-fixed frame of Fig. 14-2.

X1 east, Y1 north, Z1 up at latitude Phi on the earth of radius R turning at omega_e. The particle's inertial
position comes from EarthFrame (Wells' transformation x2 = R cPhi c(we t) - x1 s(we t) - ..., Feature 8), so T is
(14.14) automatically. Applied forces are left general (F_x1, F_y1, F_z1 constants), giving (14.15).
"""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
m, w, R, Phi, Fx, Fy, Fz = parameters("m omega_e R Phi F_x1 F_y1 F_z1")
s, c = sp.sin(Phi), sp.cos(Phi)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

E = EarthFrame(Phi, w, R)
p = Particle(m, E.point((x, y, z)), name="particle")
system = System([x, y, z], bodies=[p], forces={x: Fx, y: Fy, z: Fz}, name="particle in the earth frame (14.14)")

T_book = (sp.Rational(1, 2) * m * (xd**2 + yd**2 + zd**2)
          + m * w * ((x * yd - y * xd) * s + (R * xd + z * xd - x * zd) * c)
          + sp.Rational(1, 2) * m * w**2 * (x**2 + y**2 * s**2 + (R + z) ** 2 * c**2 - 2 * y * (R + z) * s * c))

# (14.25): velocity of the point (x1, y1, z1) along X1, Y1, Z1
v_book = [R * w * c + xd + w * z * c - w * y * s, yd + w * x * s, zd - w * x * c]


def _velocity_on_earth_axes(_s):
    return list((E.to_inertial()[1].T * p.position.diff(t)).applyfunc(sp.simplify))


PROBLEM = Problem(
    id="eq14.14",
    title="Particle relative to the rotating earth: T (14.14), EOM (14.15), frame velocity (14.25)",
    chapter=14,
    source="Wells, Sec. 14.4, eqs. (14.14), (14.15), (14.25)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        EquationsOfMotion(
            [
                sp.Eq(m * (x.diff(t, 2) + 2 * w * (zd * c - yd * s) - w**2 * x), Fx),
                sp.Eq(m * (y.diff(t, 2) + 2 * w * xd * s + w**2 * s * ((R + z) * c - y * s)), Fy),
                sp.Eq(m * (z.diff(t, 2) - 2 * w * xd * c - w**2 * c * ((R + z) * c - y * s)), Fz),
            ],
            # per_equation=False: the harness's ratio test uses sp.cancel, which does not see
            # y1 cos^2(Phi) - y1 = -y1 sin^2(Phi); the mass matrix is m*I, so the acceleration
            # comparison already checks each printed equation on its own coordinate.
            per_equation=False,
        ),
        Quantity("velocity components (14.25) along X1, Y1, Z1", _velocity_on_earth_axes, v_book),
    ],
    simulation=Simulation(
        params={m: 1.0, w: 7.29211e-5, R: 6.378388e8, Phi: 0.7854, Fx: 0.0, Fy: 0.0, Fz: 0.0},
        initial={x: 0.0, y: 0.0, z: 0.0, xd: 100.0, yd: 0.0, zd: 0.0},
        t_end=10,
    ),
    units="cgs (cm, s) in the simulation",
    correction="(14.25) is checked with the constant R omega_e cPhi term included (Wells' v_1); T (14.14) keeps "
    "the constant 1/2 m omega_e^2 R^2 cos^2 Phi, as printed.",
)
