"""Wells, eqs. (2.12), (2.27) — the Fig. 2-9 pulley masses in the coordinates (s4, q1)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

s4, q1 = coordinates("s4 q1")
m1, m2, m3, m4, h, l1, l2, C = parameters("m1 m2 m3 m4 h l1 l2 C")

# (2.12), support at the fixed height h.
y1 = h + s4 + q1 - l1 - l2 - 2 * C
y3 = h - s4 - q1 + l1
y2 = h - s4 - 2 * q1 + l1
y4 = h - s4
system = System(
    [s4, q1],
    bodies=[Particle(m1, (y1,), name="m1"), Particle(m2, (y2,), name="m2"),
            Particle(m3, (y3,), name="m3"), Particle(m4, (y4,), name="m4")],
    name="Fig. 2-9 pulleys in (s4, q1)",
)


def _velocities(s):
    return [b.velocity[0] for b in s.bodies]


sd, qd = s4.diff(t), q1.diff(t)
PROBLEM = Problem(
    id="eq2.27",
    title="Fig. 2-9 pulleys: velocities of the four masses in (s4, q1)",
    chapter=2,
    source="Wells, Sec. 2.5/2.8, eqs. (2.12), (2.27)",
    system=system,
    answers=[
        Quantity("(ẏ1, ẏ2, ẏ3, ẏ4)", _velocities, [sd + qd, -sd - 2 * qd, -sd - qd, -sd]),
        KineticEnergy(sp.Rational(1, 2) * (m1 * (sd + qd) ** 2 + m2 * (sd + 2 * qd) ** 2
                                           + m3 * (sd + qd) ** 2 + m4 * sd**2)),
    ],
    simulation=Simulation(
        params={m1: 1, m2: 2, m3: 1.5, m4: 0.5},
        initial={s4: 0, q1: 0, sd: 0.5, qd: -0.2},
        t_end=1.0,
    ),
    correction="The book prints the velocities (2.27); the KineticEnergy entry is T = ½Σ m_i ẏ_i² (2.37) with "
    "those printed velocities (not a separately printed T). Support fixed; the moving-support variants "
    "(h = v1 t + ½at², h = h0 + C sin ωt) have no printed answer.",
)
