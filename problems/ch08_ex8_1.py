"""Wells, Example 8.1 — angular velocity and velocity of a body point: body on a shaft inclined at a constant θ
in a frame turning about the vertical (kinematics).

Frame angle ψ about the vertical Z1, shaft at the constant angle θ to the vertical, body spin φ about the shaft
(from the horizontal line ab): Wells' Euler angles with θ fixed. Body axes X, Y, Z with Z along the shaft.
(x, y, z) are the body coordinates of a body point.
"""

import sympy as sp

from lagrange import EulerAngles, RigidBody, System, coordinates, parameters, t
from lagrange.corpus import Problem, Quantity

psi, phi = coordinates("psi phi")
M, A, B, C, th, x, y, z, l = parameters("M A B C theta x y z l")
psd, phd = psi.diff(t), phi.diff(t)
s, c = sp.sin, sp.cos

body = RigidBody(M, (A, B, C), orientation=EulerAngles(psi, th, phi), name="body")
system = System([psi, phi], bodies=[body], name="body on an inclined shaft in a turning frame")


def body_velocity(point):
    """Velocity of a body point along the instantaneous body axes: Rᵀ d/dt(inertial position)."""
    return body.R.T * body.point(point).position.diff(t)


def fixed_axis_omega(_):
    # (e) ψ' of the book is measured 90° from the Euler ψ (from X1 to the line of nodes): ψ_Euler = ψ' + 90°
    b = RigidBody(M, (A, B, C), orientation=EulerAngles(psi + sp.pi / 2, th, phi))
    return b.space_angular_velocity


wz = phd + psd * c(th)
v_a = [psd * z * s(th) * c(phi) - wz * y, wz * x - psd * z * s(th) * s(phi), psd * y * s(th) * s(phi) - psd * x * s(th) * c(phi)]
v0_b = [psd * l * s(th) * c(phi), -psd * l * s(th) * s(phi), 0]

PROBLEM = Problem(
    id="ex8.1",
    title="Body on an inclined shaft in a frame turning about the vertical: omega and body-point velocities",
    chapter=8,
    source="Wells, Example 8.1 (a), (b), (e) (Fig. 8-5)",
    system=system,
    answers=[
        Quantity("(a) omega along the body axes", lambda s_: body.angular_velocity,
                 [psd * s(th) * s(phi), psd * s(th) * c(phi), wz]),
        Quantity("(a) velocity of body point (x, y, z), O fixed", lambda s_: body_velocity((x, y, z)), v_a),
        Quantity("(b) velocity v_0 of p1 at distance l along Z", lambda s_: body_velocity((0, 0, l)), v0_b),
        Quantity("(b) velocity of body point (x, y, z) relative to origin p1",
                 lambda s_: body_velocity((x, y, l + z)), [a + b for a, b in zip(v0_b, v_a)]),
        Quantity("(e) omega along the fixed axes", fixed_axis_omega,
                 [phd * s(th) * c(psi), phd * s(th) * s(psi), psd + phd * c(th)]),
    ],
    correction="(b): the OCR prints v_0y = -phi_dot l s(theta) s(phi); by v = omega x r it is -psi_dot l s(theta) s(phi). "
    "(e) measures psi from a reference 90 deg from the Euler psi (psi_Euler = psi + 90 deg). Kinematics only: no simulation.",
    ranges={"theta": (0.2, 1.4)},
)
