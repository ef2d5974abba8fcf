"""Wells, Problem 11.10 — m1 (spring k1 to the axis) and m2 (spring k2 to m1) in a tube turning with a free
shaft (inertia I): oscillations about the steady motion r1 = l1, r2 = l2."""

import functools

import sympy as sp

from lagrange import Particle, System, coordinates, oscillations_about_steady_motion, parameters, routhian, t
from lagrange.corpus import Problem, Quantity, Simulation

r1, r2, phi = coordinates("r1 r2 phi")
m1, m2, k1, k2, a1, a2, I = parameters("m_1 m_2 k_1 k_2 a_1 a_2 I")
l1, l2 = parameters("l_1 l_2")  # steady radii
system = System(
    [r1, r2, phi],
    T=I * phi.diff(t) ** 2 / 2,
    bodies=[Particle(m1, (r1 * sp.cos(phi), r1 * sp.sin(phi))), Particle(m2, (r2 * sp.cos(phi), r2 * sp.sin(phi)))],
    V=k1 * (r1 - a1) ** 2 / 2 + k2 * (r2 - r1 - a2) ** 2 / 2,  # a1, a2: natural lengths
    name="two masses and two springs in a rotating tube",
)
c = sp.Symbol("p_phi", real=True)
J0 = I + m1 * l1**2 + m2 * l2**2


@functools.cache
def _lin(s):
    return oscillations_about_steady_motion(routhian(s), {r1: l1, r2: l2})


cpl = 4 * c**2 * m1 * m2 * l1 * l2 / J0**3 - k2
PROBLEM = Problem(
    id="p11.10",
    title="Two springs and masses in a rotating tube: linear equations about steady motion",
    chapter=11,
    source="Wells, Problem 11.10",
    system=system,
    answers=[
        Quantity("a, b, c about r1 = l1, r2 = l2", lambda s: [*_lin(s).a, *_lin(s).b, *_lin(s).c], [
            m1, 0, 0, m2,
            0, 0, 0, 0,
            m1 * c**2 * (3 * m1 * l1**2 - m2 * l2**2 - I) / J0**3 + k1 + k2, cpl,
            cpl, m2 * c**2 * (3 * m2 * l2**2 - m1 * l1**2 - I) / J0**3 + k2]),
    ],
    simulation=Simulation(params={m1: 1, m2: 1, k1: 100, k2: 100, a1: 1, a2: 1, I: 2},
                          initial={r1: 1.1, r2: 2.2, phi: 0, r1.diff(t): 0, r2.diff(t): 0, phi.diff(t): 3.0},
                          t_end=3),
)
