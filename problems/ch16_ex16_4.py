"""Wells, Example 16.4 — double pendulum on springs (Fig. 2-10), planar: the generalized momenta."""

import sympy as sp

from lagrange import Particle, System, coordinates, parameters, t
from lagrange.corpus import KineticEnergy, Problem, Quantity, Simulation

r1, r2, th, ph = coordinates("r_1 r_2 theta phi")
m1, m2, g, k1, k2, l1, l2 = parameters("m_1 m_2 g k_1 k_2 l_1 l_2")
r1d, r2d, thd, phd = (c.diff(t) for c in (r1, r2, th, ph))

# angles from the downward vertical; m1 at the end of spring k1 from the pivot, m2 at the end of spring k2 from m1
P1 = (r1 * sp.sin(th), -r1 * sp.cos(th))
P2 = (P1[0] + r2 * sp.sin(ph), P1[1] - r2 * sp.cos(ph))
system = System(
    [r1, r2, th, ph],
    bodies=[Particle(m1, P1), Particle(m2, P2)],
    V=m1 * g * P1[1] + m2 * g * P2[1] + k1 * (r1 - l1) ** 2 / 2 + k2 * (r2 - l2) ** 2 / 2,
    name="double spring pendulum",
)

c, s = sp.cos(ph - th), sp.sin(ph - th)
T_book = ((m1 + m2) * (r1d**2 + r1**2 * thd**2) / 2
          + m2 * (r2d**2 + r2**2 * phd**2 + 2 * (r1d * r2d + r1 * r2 * thd * phd) * c
                  + 2 * (r1 * r2d * thd - r2 * r1d * phd) * s) / 2)
p_book = [
    (m1 + m2) * r1d + m2 * r2d * c - m2 * r2 * phd * s,
    m2 * r2d + m2 * r1d * c + m2 * r1 * thd * s,
    (m1 + m2) * r1**2 * thd + m2 * r1 * r2 * phd * c + m2 * r1 * r2d * s,
    m2 * r2**2 * phd + m2 * r1 * r2 * thd * c - m2 * r2 * r1d * s,
]


def _momenta(sys):
    """p = 2A qdot + B from Wells' split (2.55) of T (the book's p = dL/dqdot, L linear-quadratic)."""
    A, B, _ = sys.energy_split()
    qd = sp.Matrix([r1d, r2d, thd, phd])
    return list(2 * A * qd + B)


PROBLEM = Problem(
    id="ex16.4",
    title="Double pendulum on springs: the four momenta p_r1, p_r2, p_theta, p_phi",
    chapter=16,
    source="Wells, Example 16.4 (system of Fig. 2-10)",
    system=system,
    answers=[
        KineticEnergy(T_book),
        Quantity("momenta p = 2A qdot + B", _momenta, p_book),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, g: 9.81, k1: 60, k2: 60, l1: 1, l2: 1},
                          initial={r1: 1.1, r2: 1.1, th: 0.3, ph: 0.5, r1d: 0, r2d: 0, thd: 0, phd: 0}, t_end=3),
    correction="The book writes H only as the 4x4 Legendre transform (not printed); the momenta are checked. "
    "The momenta come from the A, B split of T because hamiltonian() inverts the 4x4 configuration-dependent "
    "mass matrix symbolically, which is too slow for the corpus check.",
)
