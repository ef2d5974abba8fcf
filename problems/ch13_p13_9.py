"""Wells, Problem 13.9 — bead on the smooth parabolic wire z = a r² turning about the vertical at constant θ̇:
the force parallel to Z, or along r, that holds m at any point of the wire."""

import sympy as sp

from lagrange import Particle, System, coordinates, delta, parameters, static_equilibrium, t
from lagrange.corpus import EnergySplit, Problem, Quantity, Simulation

r = coordinates("r")
m, g, a, w = parameters("m g a omega")
f_z, f_r = sp.symbols("f_z f_r", real=True)
pos = (r * sp.cos(w * t), r * sp.sin(w * t), a * r**2)
V = m * g * a * r**2
held_z = System([r], bodies=[Particle(m, pos)], V=V, forces=f_z * delta(a * r**2), name="bead held by a vertical force")
held_r = System([r], bodies=[Particle(m, pos)], V=V, forces=f_r * delta(r), name="bead held by a radial force")
free = System([r], bodies=[Particle(m, pos)], V=V, name="bead on a turning parabolic wire")

PROBLEMS = [
    Problem(
        id="p13.9",
        title="Bead on a turning parabolic wire z = ar²: holding forces f_z = mg − mθ̇²/2a, f_r = 2mgar − mrθ̇²",
        chapter=13,
        source="Wells, Problem 13.9 (Fig. 2-29, Prob. 2.20)",
        system=held_z,
        answers=[
            EnergySplit(A=sp.Matrix([[m * (1 + 4 * a**2 * r**2) / 2]]), C=m * r**2 * w**2 / 2),
            Quantity("f_z (parallel to Z)", lambda s: static_equilibrium(s, [f_z])[0][f_z], m * g - m * w**2 / (2 * a)),
            Quantity("f_z vanishes at θ̇ = sqrt(2ga)",
                     lambda s: static_equilibrium(s, [f_z])[0][f_z].subs(w, sp.sqrt(2 * g * a)), 0),
        ],
        simulation=Simulation(params={m: 1, g: 9.81, a: 1, w: 3, f_z: 0}, initial={r: 0.5, r.diff(t): 0}, t_end=3),
        correction="The book's T = m(ṙ² + r²θ̇² + 4a²r²ṙ²)/2 is split as A = m(1 + 4a²r²)/2, C = m r²θ̇²/2.",
    ),
    Problem(
        id="p13.9-radial",
        title="Bead on a turning parabolic wire: horizontal radial holding force f_r = 2mgar − mrθ̇²",
        chapter=13,
        source="Wells, Problem 13.9",
        system=held_r,
        answers=[Quantity("f_r (along r)", lambda s: static_equilibrium(s, [f_r])[0][f_r],
                          2 * m * g * a * r - m * r * w**2)],
        simulation=Simulation(params={m: 1, g: 9.81, a: 1, w: 3, f_r: 0}, initial={r: 0.5, r.diff(t): 0}, t_end=3),
    ),
]
