"""Wells, Example 8.11 — heavy disk rolling without slipping on an incline, ball joint at O on the plane.

Shaft OZ at the constant nutation θ with sθ = r1/r3, cθ = r2/r3 (r2 disk radius, r1 distance from O to the disk
centre along the shaft, r3 = (r1² + r2²)^½). Rolling, r3 ψ̇ = −r2 φ̇, eliminates φ = −(r3/r2) ψ. I_x = I_y about O,
I_z about the shaft; c.m. at distance l along the shaft. Incline angle ε: with the plane's X1Y1 tilted so that
−Y1 points down the slope, the height of a point is Z1 cε + Y1 sε, and ψ (Euler) is measured from the
down-slope line to the projection of OZ (V = −M g l (r1/r3) sε cψ + const, the catalog's reading).
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import EquationsOfMotion, KineticEnergy, PotentialEnergy, Problem, Quantity, Simulation

psi = coordinates("psi")
M, g, l, r1, r2, Ix, Iz, eps = parameters("M g l r1 r2 I_x I_z epsilon")
r3 = sp.sqrt(r1**2 + r2**2)
theta0 = sp.atan(r1 / r2)  # sθ = r1/r3, cθ = r2/r3
psd = psi.diff(t)

disk = RigidBody(M, (Ix, Ix, Iz), orientation=EulerAngles(psi, theta0, -r3 / r2 * psi), com=(0, 0, l), name="disk")
cm = disk.centre_of_mass
system = System([psi], bodies=[disk], V=M * g * (cm[2] * sp.cos(eps) + cm[1] * sp.sin(eps)),
                name="disk rolling on an incline with a ball joint")

phi_ = -r3 / r2 * psi
wx = psd * r1 / r3 * sp.sin(phi_)
wy = psd * r1 / r3 * sp.cos(phi_)
wz = -psd * r1**2 / (r2 * r3)


def _small_oscillation_period(s):
    Mq = s.mass_matrix[0, 0]
    K = sp.diff(s.V, psi, 2).subs(psi, 0)
    return 2 * sp.pi * sp.sqrt(Mq / K)


PROBLEM = Problem(
    id="ex8.11",
    title="Disk rolling on an incline about a ball joint: (r1/r3)(I_x + I_z r1^2/r2^2) psi'' = -M g l s(eps) s(psi)",
    chapter=8,
    source="Wells, Example 8.11 (and Sec. 8.11)",
    system=system,
    answers=[
        Quantity("body angular velocity (omega_x, omega_y, omega_z)", lambda s: disk.angular_velocity, [wx, wy, wz]),
        KineticEnergy(sp.Rational(1, 2) * (Ix * (wx**2 + wy**2) + Iz * wz**2)),
        PotentialEnergy(-M * g * l * r1 / r3 * sp.sin(eps) * sp.cos(psi)),
        EquationsOfMotion(
            [sp.Eq(r1 / r3 * (Ix + Iz * r1**2 / r2**2) * psi.diff(t, 2), -M * g * l * sp.sin(eps) * sp.sin(psi))],
        ),
        Quantity("small-oscillation period about psi = 0", _small_oscillation_period,
                 2 * sp.pi * sp.sqrt(r1 / r3 * (Ix + Iz * r1**2 / r2**2) / (M * g * l * sp.sin(eps)))),
    ],
    simulation=Simulation(
        params={M: 1.0, g: 9.81, l: 0.3, r1: 0.3, r2: 0.2, Ix: 0.1, Iz: 0.02, eps: 0.3},
        initial={psi: 0.5, psd: 0.0},
        t_end=5.0,
    ),
    ranges={"epsilon": (0.1, 1.2)},
    correction="The small-oscillation period is derived in the catalog (the book suggests the experiment of Sec. 8.11); "
    "the book's EOM is the Lagrange equation divided by r1/r3.",
)
