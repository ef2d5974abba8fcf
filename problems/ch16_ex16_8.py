"""Wells, Example 16.8 — particle in oblique coordinates (q1, q2) of a frame translating with velocity v + a t (eq. 2.50)."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

q1, q2 = coordinates("q_1 q_2")
m, al, be, vx, vy, ax, ay = parameters("m alpha beta v_x v_y a_x a_y")
q1d, q2d = q1.diff(t), q2.diff(t)

# q1 along a line at angle alpha, q2 at angle beta to X; the frame origin moves with velocity (vx + ax t, vy + ay t)
X = vx * t + ax * t**2 / 2 + q1 * sp.cos(al) + q2 * sp.cos(be)
Y = vy * t + ay * t**2 / 2 + q1 * sp.sin(al) + q2 * sp.sin(be)
system = System([q1, q2], bodies=[Particle(m, (X, Y))], name="particle in a translating oblique frame")

ux, uy = vx + ax * t, vy + ay * t
T_book = (m * (q1d**2 + q2d**2 + 2 * q1d * q2d * sp.cos(be - al)) / 2
          + m * ((ux * sp.cos(al) + uy * sp.sin(al)) * q1d + (ux * sp.cos(be) + uy * sp.sin(be)) * q2d)
          + m * (2 * (vx * ax + vy * ay) * t + (ax**2 + ay**2) * t**2 + vx**2 + vy**2) / 2)



def _p_q1(sys):
    """p = 2A qdot + B from Wells' split (2.55) of T (hamiltonian() also works but takes ~4 s here)."""
    A, B, _ = sys.energy_split()
    return (2 * A * sp.Matrix([q1d, q2d]) + B)[0]


PROBLEM = Problem(
    id="ex16.8",
    title="Oblique coordinates in a translating frame: T with T2 != 0 and the momentum p_q1",
    chapter=16,
    source="Wells, Example 16.8 (system of eq. 2.50)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        Quantity("p_q1 = (2A qdot + B)_1", _p_q1,
                 m * (q1d + q2d * sp.cos(be - al)) + m * (ux * sp.cos(al) + uy * sp.sin(al))),
    ],
    simulation=Simulation(params={m: 1, al: 0.2, be: 1.3, vx: 1, vy: 0.5, ax: 0.3, ay: -0.2},
                          initial={q1: 0, q2: 0, q1d: 1, q2d: 0}, t_end=3),
    ranges={"alpha": (0.1, 0.5), "beta": (1.0, 1.5)},
    correction="Catalog tag [PARTIAL]: the book prints T and p_q1 only (H is left as an exercise, (16.4) vs (16.8)); "
    "those two printed results are checked. No applied forces are assumed.",
)
