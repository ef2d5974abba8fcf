"""Wells, Problem 8.22 — gyrocompass on the rotating earth at latitude Φ; gimbal angles θ1 (about the local
vertical) and θ2 (spin, about the horizontal rotor axis Z); c.m. at the gimbal centre O on the earth's surface.

Local axes X1 east, Y1 north, Z1 up (EarthFrame). At θ1 = θ2 = 0 the body axes are X = north, Y = up, Z = east;
orientation = earth · R_z(θ1) · [N U E] · R_z(θ2), which gives the book's
ω_x = (θ̇1 + ω_e sΦ) sθ2 + ω_e cΦ cθ1 cθ2, ω_y = (θ̇1 + ω_e sΦ) cθ2 − ω_e cΦ cθ1 sθ2, ω_z = θ̇2 + ω_e cΦ sθ1.
Ī_x = Ī_y (symmetric rotor, massless gimbals).
"""

import sympy as sp

from lagrange import RigidBody, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, EquationsOfMotion, KineticEnergy, Problem, Quantity, Simulation
from lagrange.model.frames import EarthFrame
from lagrange.model.rotations import rot_z

th1, th2 = coordinates("theta1 theta2")
M, Ix, Iz, Phi, we, Re, cc = parameters("M Ibar_x Ibar_z Phi omega_e R c")
t1d, t2d = th1.diff(t), th2.diff(t)
s, c = sp.sin, sp.cos

earth = EarthFrame(Phi, we, Re)
_, R_earth = earth.to_inertial()
NUE = sp.Matrix([[0, 0, 1], [1, 0, 0], [0, 1, 0]])  # columns: north, up, east in (east, north, up)
gyro = RigidBody(M, (Ix, Ix, Iz), origin=earth.point((0, 0, 0)), orientation=R_earth * rot_z(th1) * NUE * rot_z(th2),
                 name="gyrocompass rotor")
system = System([th1, th2], bodies=[gyro], name="gyrocompass on the rotating earth")
W_BODY = gyro.angular_velocity

wx = (t1d + we * s(Phi)) * s(th2) + we * c(Phi) * c(th1) * c(th2)
wy = (t1d + we * s(Phi)) * c(th2) - we * c(Phi) * c(th1) * s(th2)
wz = t2d + we * c(Phi) * s(th1)
p2 = Iz * (t2d + we * c(Phi) * s(th1))  # c = dT/d theta2_dot


def small_oscillation_omega2(sys_):
    """θ1 equation with θ̇2 = c/Ī_z − ω_e cΦ sθ1, the ω_e² term dropped, linearized at θ1 = 90° (α = 90° − θ1)."""
    e = sys_.equations()[0]
    e = (e.lhs - e.rhs).subs(t2d, cc / Iz - we * c(Phi) * s(th1))
    eps = sp.Symbol("eps")
    e = sp.expand(e.subs(we, eps * we)).series(eps, 0, 2).removeO().subs(eps, 1)
    m_ = sp.diff(e, th1.diff(t, 2))
    k_ = sp.diff(e, th1).subs(th1, sp.pi / 2)
    return sp.simplify(k_ / m_)


PROBLEM = Problem(
    id="p8.22",
    title="Gyrocompass on the rotating earth: omega, T, c = dT/d theta2' and the north-seeking oscillation",
    chapter=8,
    source="Wells, Problem 8.22",
    system=system,
    answers=[
        Quantity("omega along the body axes", lambda s_: W_BODY, [wx, wy, wz]),
        KineticEnergy(sp.Rational(1, 2) * Ix * ((t1d + we * s(Phi)) ** 2 + we**2 * c(Phi) ** 2 * c(th1) ** 2)
                      + sp.Rational(1, 2) * Iz * (t2d + we * c(Phi) * s(th1)) ** 2
                      + sp.Rational(1, 2) * M * (we * Re * c(Phi)) ** 2),
        ConservedMomenta({th2: p2}),
        EquationsOfMotion([
            sp.Eq(Ix * th1.diff(t, 2) + Ix * we**2 * c(Phi) ** 2 * s(th1) * c(th1) - p2 * we * c(Phi) * c(th1), 0),
            sp.Eq(p2.diff(t), 0),
        ]),
        Quantity("omega^2 of the small alpha oscillation (alpha = 90 deg - theta1)", small_oscillation_omega2,
                 cc * we * c(Phi) / Ix),
    ],
    simulation=Simulation(params={M: 1.0, Ix: 0.01, Iz: 0.02, Phi: 0.7, we: 7.29e-5, Re: 6.37e6},
                          initial={th1: 1.2, th2: 0.0, t1d: 0.0, t2d: 2000.0}, t_end=20.0),
    ranges={"Phi": (0.2, 1.3)},
    correction="The book's T ends in '+ const'; here the constant is written out: 1/2 M (omega_e R c(Phi))^2, the kinetic "
    "energy of the carried centre. The exact theta1 equation (with c = dT/d theta2' constant) is the catalog's; the book's "
    "answer Ibar_x alpha'' + c omega_e c(Phi) s(alpha) = 0 (omega_e^2 dropped, theta1 = 90 deg - alpha; OCR 'Ibar_x^p**') "
    "gives the period 2 pi (Ibar_x/(c omega_e c(Phi)))^(1/2), checked here through omega^2.",
)
