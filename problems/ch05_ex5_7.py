"""Wells, Example 5.7 — two bodies attracting by Newtonian gravitation: c.m. and reduced-mass coordinates."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import ConservedMomenta, JacobiIntegral, KineticEnergy, PotentialEnergy, Problem, Simulation

xb, yb, zb, r, theta, phi = coordinates("xbar ybar zbar r theta phi")
m1, m2, G = parameters("m1 m2 G")
M = m1 + m2
mu = m1 * m2 / M

# Relative position (m1 -> m2) in spherical coordinates; each body placed about the centre of mass.
rel = (r * sp.sin(theta) * sp.cos(phi), r * sp.sin(theta) * sp.sin(phi), r * sp.cos(theta))
cm = (xb, yb, zb)
body1 = Particle(m1, tuple(c - m2 / M * d for c, d in zip(cm, rel, strict=True)))
body2 = Particle(m2, tuple(c + m1 / M * d for c, d in zip(cm, rel, strict=True)))
# The separation |r2 - r1| is the length r of the relative position vector (r > 0).
# T of the two particles, trig-simplified once (keeps the checks fast).
T_bodies = sp.fu(sp.expand(sp.cancel(body1.kinetic_energy() + body2.kinetic_energy())))
system = System([xb, yb, zb, r, theta, phi], T=T_bodies, V=-G * m1 * m2 / r,
                name="two-body problem")

T_book = (M * (xb.diff(t) ** 2 + yb.diff(t) ** 2 + zb.diff(t) ** 2) / 2
          + mu * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2 + r**2 * sp.sin(theta) ** 2 * phi.diff(t) ** 2) / 2)

PROBLEM = Problem(
    id="ex5.7",
    title="Two-body central force: L = M vbar^2/2 + mu(rd^2 + r^2 thd^2 + r^2 sin^2 th phd^2)/2 + G m1 m2 / r",
    chapter=5,
    source="Wells, Example 5.7",
    system=system,
    answers=[
        KineticEnergy(T_book),
        PotentialEnergy(-G * m1 * m2 / r),
        ConservedMomenta({
            xb: M * xb.diff(t), yb: M * yb.diff(t), zb: M * zb.diff(t),
            phi: mu * r**2 * sp.sin(theta) ** 2 * phi.diff(t),
        }),
        JacobiIntegral(T_book - G * m1 * m2 / r),
    ],
    simulation=Simulation(params={m1: 1, m2: 2, G: 1},
                          initial={xb: 0, yb: 0, zb: 0, r: 1, theta: 1.2, phi: 0, xb.diff(t): 0.1, yb.diff(t): 0,
                                   zb.diff(t): 0, r.diff(t): 0, theta.diff(t): 0.5, phi.diff(t): 1.0}, t_end=5),
    correction="OCR prints p_phi = mu r^2 sin(theta) phd; the momentum conjugate to phi is mu r^2 sin^2(theta) phd "
    "(the phi term of T is mu r^2 sin^2(theta) phd^2 / 2).",
)
