"""Wells, Sec. 14.4, eqs. (14.11)–(14.13) and (14.16) — particle under gravity alone in the earth frame.

Frame of Fig. 14-2 (X1 east, Y1 north, Z1 up, latitude Phi, radius R, rate omega_e). Wells' rule: the generalized
forces come from the TRUE gravity g (tilted north by alpha from -Z1), computed ignoring the earth's rotation;
the plumb-line g' points along -Z1. EarthFrame.gravity_force gives the true gravity from g' by (14.11). With
F_y1 = m omega_e^2 R sPhi cPhi and F_z1 = -m(g' + omega_e^2 R cos^2 Phi) the R omega_e^2 terms of (14.15) cancel,
leaving (14.16).
"""

import sympy as sp

from lagrange import Force, Particle, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, GeneralizedForces, Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame

x, y, z = coordinates("x1 y1 z1")
m, gp, w, R, Phi = parameters("m g_prime omega_e R Phi")
s, c = sp.sin(Phi), sp.cos(Phi)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

E = EarthFrame(Phi, w, R)
p = Particle(m, E.point((x, y, z)), name="particle")
system = System([x, y, z], bodies=[p], forces=[Force(p, E.gravity_force(m, gp))],
                name="particle under gravity in the earth frame (14.16)")


def _g_vector(_s):
    return E.true_gravity(gp)  # (east, north, up) components of the true g per unit mass


def _g_magnitude(_s):
    gv = _g_vector(_s)
    return sp.sqrt(gv.dot(gv))


PROBLEM = Problem(
    id="eq14.16",
    title="Particle under gravity on the rotating earth: true g vs plumb-line g' (14.11)-(14.13), EOM (14.16)",
    chapter=14,
    source="Wells, Sec. 14.3-14.4, eqs. (14.11)-(14.13), (14.15), (14.16)",
    system=system,
    answers=[
        GeneralizedForces({x: 0, y: m * w**2 * R * s * c, z: -m * (gp + w**2 * R * c**2)}),
        EquationsOfMotion(
            [
                sp.Eq(x.diff(t, 2) + 2 * w * (zd * c - yd * s) - w**2 * x, 0),
                sp.Eq(y.diff(t, 2) + 2 * w * xd * s + w**2 * s * (z * c - y * s), 0),
                sp.Eq(z.diff(t, 2) - 2 * w * xd * c - w**2 * c * (z * c - y * s), -gp),
            ],
            per_equation=False,  # mass matrix m*I; sp.cancel in the ratio test misses cos^2 = 1 - sin^2
        ),
        # (14.11): g sin(alpha) = omega_e^2 R sPhi cPhi (north component), g cos(alpha) = g' + omega_e^2 R cos^2 Phi
        Quantity("g sin(alpha) (14.11)", lambda _s: _g_vector(_s)[1], w**2 * R * s * c),
        Quantity("g cos(alpha) (14.11)", lambda _s: -_g_vector(_s)[2], gp + w**2 * R * c**2),
        Quantity("tan(alpha) (14.12)", lambda _s: -_g_vector(_s)[1] / _g_vector(_s)[2],
                 sp.Rational(1, 2) * w**2 * R * sp.sin(2 * Phi) / (gp + w**2 * R * c**2)),
        Quantity("g^2 (14.13)", lambda _s: _g_magnitude(_s) ** 2, gp**2 + w**2 * R * c**2 * (2 * gp + w**2 * R)),
        Quantity("east component of g", lambda _s: _g_vector(_s)[0], sp.S.Zero),
    ],
    simulation=Simulation(
        params={m: 1.0, gp: 980.629, w: 7.29211e-5, R: 6.389135e8, Phi: 0.7853981634},
        initial={x: 0.0, y: 0.0, z: 0.0, xd: 1000.0, yd: 2000.0, zd: 3000.0},
        t_end=5,
    ),
    units="cgs (cm, s, gal) in the simulation",
    correction="The R omega_e^2 terms cancel in the derived forcing (checked through the accelerations).",
)
