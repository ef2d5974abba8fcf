"""Wells, Problem 5.16 — prove (5.13): a particle joined by S stretched springs to fixed anchors in space has, for
small displacements (x, y, z) from equilibrium,

    V ~= 1/2 sum_i [ (k_i l'_i / l_i) (x alpha_i + y beta_i + z gamma_i)^2 + k_i ((l_i - l'_i)/l_i) (x^2 + y^2 + z^2) ],

with l_i the spring's length at equilibrium, l'_i its natural length and (alpha_i, beta_i, gamma_i) its direction
cosines. Here two springs with general anchors (x_i, y_i, z_i) relative to the equilibrium point; the exact V is
expanded to second order by the library (:func:`lagrange.expand_potential`) and its quadratic part compared with
(5.13). The linear part, -sum k_i (l_i - l'_i)(x alpha_i + y beta_i + z gamma_i), is what equilibrium cancels: it is
checked too, so the quadratic part is the whole small-displacement V at equilibrium.
"""

import sympy as sp

from lagrange import Particle, System, coordinates, expand_potential, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

x, y, z = coordinates("x y z")
m = parameters("m")
N = 2  # two springs in general directions already exercise every term of (5.13)
k = parameters(" ".join(f"k_{i}" for i in range(1, N + 1)))
lp = parameters(" ".join(f"lp_{i}" for i in range(1, N + 1)))  # natural lengths l'_i
anchors = [parameters(f"a_{i} b_{i} c_{i}") for i in range(1, N + 1)]  # anchor i at (a_i, b_i, c_i)


def _stretch(i):
    a, b, c = anchors[i]
    return sp.sqrt((a - x) ** 2 + (b - y) ** 2 + (c - z) ** 2)


system = System([x, y, z], bodies=[Particle(m, (x, y, z))],
                V=sum(k[i] * (_stretch(i) - lp[i]) ** 2 / 2 for i in range(N)),
                name="particle on two springs to fixed anchors in space")

_l = [sp.sqrt(a**2 + b**2 + c**2) for a, b, c in anchors]  # lengths at the equilibrium point (origin)
_along = [(a * x + b * y + c * z) / li for (a, b, c), li in zip(anchors, _l)]  # x alpha_i + y beta_i + z gamma_i
V_513 = sum(k[i] * lp[i] / _l[i] * _along[i] ** 2 + k[i] * (_l[i] - lp[i]) / _l[i] * (x**2 + y**2 + z**2)
            for i in range(N)) / 2
V_linear = -sum(k[i] * (_l[i] - lp[i]) * _along[i] for i in range(N))


def _linear_and_quadratic(s):
    """The degree-1 and degree-2 parts of the library's Taylor series of V about the equilibrium point."""
    terms = expand_potential(s.V, {x: 0, y: 0, z: 0}, 2).terms
    return [terms[1], terms[2]]


PROBLEM = Problem(
    id="p5.16",
    title="Prove (5.13): the second-order V of a particle on stretched springs in space",
    chapter=5,
    source="Wells, Problem 5.16, eq. (5.13)",
    system=system,
    answers=[
        # [first-order part (zero at equilibrium), second-order part (5.13)]
        Quantity("first- and second-order parts of V about equilibrium, (5.13)", _linear_and_quadratic,
                 [V_linear, V_513]),
    ],
    # anchors in two directions, springs stretched (l_i > l'_i); the origin is not exactly the
    # equilibrium for these numbers, so the particle oscillates about a nearby point
    simulation=Simulation(
        params={m: 1, k[0]: 2, k[1]: 3, lp[0]: 0.5, lp[1]: 0.5,
                **dict(zip(anchors[0], (1, 0, 0))), **dict(zip(anchors[1], (-0.5, 1, 0.2)))},
        initial={x: 0.05, y: 0, z: 0, x.diff(t): 0, y.diff(t): 0, z.diff(t): 0}, t_end=5),
)
