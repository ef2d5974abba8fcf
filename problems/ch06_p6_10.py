"""Wells, Problem 6.10 — particle on a disk turning at omega(t): (a) dry friction, (b) viscous drag, relative velocity."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import GeneralizedForces, Problem, Simulation

r, theta = coordinates("r theta")
m, g, mu, a, a0, beta = parameters("m g mu a alpha0 beta")
omega = a0 * beta * sp.cos(beta * t)  # disk angular velocity (explicit t)

pos = (r * sp.cos(theta), r * sp.sin(theta))
vel = [c.diff(t) for c in pos]
disk_vel = (-omega * pos[1], omega * pos[0])  # velocity of the disk point under the particle
rel2 = sp.expand(sum((v - w) ** 2 for v, w in zip(vel, disk_vel, strict=True)))
rel2 = sp.trigsimp(rel2)
dry = System([r, theta], bodies=[Particle(m, pos)], P=-mu * m * g * sp.sqrt(rel2), name="particle on a disk, dry")
viscous = System([r, theta], bodies=[Particle(m, pos)], P=-a * rel2 / 2, name="particle on a disk, viscous")

rd, thd = r.diff(t), theta.diff(t)
vr = sp.sqrt(rd**2 + r**2 * (thd - omega) ** 2)
start = {r: 1, theta: 0, r.diff(t): 0.2, theta.diff(t): 0.5}
PROBLEMS = [
    Problem(
        id="p6.10-dry",
        title="Particle on a turning disk, dry friction against the relative velocity",
        chapter=6,
        source="Wells, Problem 6.10(a)",
        system=dry,
        answers=[GeneralizedForces({r: -mu * m * g * rd / vr, theta: -mu * m * g * r**2 * (thd - omega) / vr})],
        simulation=Simulation(params={m: 1, g: 9.81, mu: 0.1, a0: 0.5, beta: 2}, initial=start, t_end=0.5),
        correction="OCR prints mu m g r rd and [r^2 + ...] in F_r; corrected (catalog, re-derived) to "
        "F_r = -mu m g rd / [rd^2 + r^2 (thd - omega)^2]^(1/2).",
    ),
    Problem(
        id="p6.10-viscous",
        title="Particle on a turning disk, viscous drag: F_r = -a rd, F_theta = -a r^2 (thd - omega)",
        chapter=6,
        source="Wells, Problem 6.10(b)",
        system=viscous,
        answers=[GeneralizedForces({r: -a * rd, theta: -a * r**2 * (thd - omega)})],
        simulation=Simulation(params={m: 1, a: 0.3, a0: 0.5, beta: 2}, initial=start, t_end=5),
    ),
]
