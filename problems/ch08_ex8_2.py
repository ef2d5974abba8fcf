"""Wells, Example 8.2 — disk D on shaft bc (spin φ), arm ab turning by ψ, fixed inclination θ: ω along the fixed
axes, its magnitude (8.5) and direction cosines; a free particle in the disk frame.

ψ here is the angle between the fixed X1Z1 plane and the plane abc, i.e. 90° from the Euler ψ (which runs from
X1 to the line of nodes, normal to abc): ψ_Euler = ψ + 90°. O lies at the distance s along the shaft from the
fixed intersection point; (x, y, z) are the particle's coordinates along the disk axes.
"""

import sympy as sp

from lagrange import EulerAngles, Particle, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

psi, phi = coordinates("psi phi")
M, A, C, th, m, s_ = parameters("M A C theta m s")
psd, phd = psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

disk = RigidBody(M, (A, A, C), orientation=EulerAngles(psi + sp.pi / 2, th, phi), name="disk D")
system = System([psi, phi], bodies=[disk], name="disk on an inclined shaft")

w = sp.sqrt(phd**2 + psd**2 + 2 * phd * psd * c(th))


def magnitude(sys_):
    return sp.sqrt(sum(v**2 for v in disk.angular_velocity))


# free particle in the disk frame
x, y, z = coordinates("x y z")
frame_pos = disk.R * sp.Matrix([x, y, s_ + z])
particle_system = System([x, y, z, psi, phi], bodies=[Particle(m, tuple(frame_pos))],
                         name="free particle in the disk frame (kinematics)")

PROBLEMS = [
    Problem(
        id="ex8.2",
        title="Disk on an inclined shaft: omega along fixed axes, |omega| (8.5), direction cosines l, l1",
        chapter=8,
        source="Wells, Example 8.2 (Fig. 8-5)",
        system=system,
        answers=[
            Quantity("omega along the fixed axes", lambda s_: disk.space_angular_velocity,
                     [phd * s(th) * c(psi), phd * s(th) * s(psi), psd + phd * c(th)]),
            Quantity("|omega| (8.5)", magnitude, w),
            Quantity("body direction cosine l = omega_x/|omega|", lambda s_: disk.angular_velocity[0] / magnitude(s_),
                     psd * s(th) * s(phi) / w),
            Quantity("fixed-axis direction cosine l1 = omega_1x/|omega|",
                     lambda s_: disk.space_angular_velocity[0] / magnitude(s_), phd * s(th) * c(psi) / w),
        ],
        correction="Kinematics only (no simulation). psi is the book's angle between the planes X1Z1 and abc, "
        "90 deg from the Euler psi.",
        ranges={"theta": (0.2, 1.4)},
    ),
    Problem(
        id="ex8.2-particle",
        title="Free particle in the disk frame of Ex 8.2: v_x along the disk axes",
        chapter=8,
        source="Wells, Example 8.2 (last part)",
        system=particle_system,
        answers=[
            Quantity("v_x along the disk X axis",
                     lambda s_: (disk.R.T * frame_pos.diff(t))[0],
                     x.diff(t) + psd * s_ * s(th) * c(phi) + (psd * z * s(th) * c(phi) - y * (phd + psd * c(th)))),
        ],
        correction="Kinematics only; the book prints v_x only (v_y, v_z by cyclic permutation).",
        ranges={"theta": (0.2, 1.4)},
    ),
]
