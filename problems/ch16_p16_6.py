"""Wells, Problem 16.6 — three masses on four transverse springs (Ex. 5.5), exact V: H."""

import sympy as sp

from lagrange import Particle, System, coordinates, hamiltonian, parameters, t
from lagrange.corpus import Problem, Quantity, Simulation

ys = coordinates("y_1 y_2 y_3")
ms = parameters("m_1 m_2 m_3")
ks = parameters("k_1 k_2 k_3 k_4")
ss = parameters("s_1 s_2 s_3 s_4")


def _V(yy):
    full = [0, *yy, 0]
    return sum(ks[j] * (sp.sqrt((full[j + 1] - full[j]) ** 2 + ss[j] ** 2) - ss[j]) ** 2 for j in range(4)) / 2


system = System(list(ys), bodies=[Particle(ms[i], (0, ys[i])) for i in range(3)], V=_V(ys),
                name="three masses on four transverse springs")

yp = [sp.Symbol(f"y_{i}", real=True) for i in (1, 2, 3)]
pp = [sp.Symbol(f"p_y_{i}", real=True) for i in (1, 2, 3)]
# book: H = 1/2 sum p_i^2/m_i + 1/2 sum k_j {[(y_j - y_{j-1})^2 + s_j^2]^(1/2) - s_j}^2, y_0 = y_4 = 0
H_book = sum(pp[i] ** 2 / ms[i] for i in range(3)) / 2 + _V(yp)

PROBLEM = Problem(
    id="p16.6",
    title="Three masses on four transverse springs, V not approximated: H",
    chapter=16,
    source="Wells, Problem 16.6 (system of Ex. 5.5)",
    system=system,
    answers=[Quantity("H", lambda s: hamiltonian(s).H, H_book)],
    simulation=Simulation(params={**dict.fromkeys(ms, 1), **dict.fromkeys(ks, 10), **dict.fromkeys(ss, 1)},
                          initial={ys[0]: 0.2, ys[1]: 0, ys[2]: -0.1, **{y.diff(t): 0 for y in ys}}, t_end=3),
    correction="Each spring j joins mass j-1 and mass j (axial spacing s_j, natural length s_j), y_0 = y_4 = 0. "
    "The book's H is 1/2 sum p^2/m plus this exact V.",
)
